#include "hilight/room_split.hpp"
#include "hilight/voxel_labels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <tuple>

namespace hilight {

namespace {

constexpr uint16_t kUnreached = 0xFFFF;
constexpr int kOutside = -1;  ///< a label: free space joined to the grid's sides
constexpr size_t kMinCoreVoxels = 8;  ///< a core smaller than this is a gap between furniture, no room

} // namespace

RoomSplit::RoomSplit(const RayScene& rays, float voxel) {
  const Scene& scene = rays.scene();
  m_box = scene.light_bounds();
  const Vec3 extent = m_box.extent();
  m_voxel = std::max(voxel, std::max({extent.x, extent.y, extent.z}) / 160.f);  // at most 160 along the longest axis: ~45 MB for a cube
  if (!(m_voxel > 0.f)) return;
  for (int k = 0; k < 3; ++k) m_dims[k] = std::max(1, int(std::ceil(extent[k] / m_voxel)));
  const size_t n = size_t(m_dims.x) * m_dims.y * m_dims.z;
  const auto coords = [&](size_t i) {
    return glm::ivec3(int(i % size_t(m_dims.x)), int(i / size_t(m_dims.x) % size_t(m_dims.y)), int(i / (size_t(m_dims.x) * m_dims.y)));
  };
  const auto inside = [&](const glm::ivec3& v) { return v.x >= 0 && v.y >= 0 && v.z >= 0 && v.x < m_dims.x && v.y < m_dims.y && v.z < m_dims.z; };
  static const glm::ivec3 kFaces[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};

  // Walls: every voxel a surface passes through.
  std::vector<char> wall(n, 0);
  scene.for_each_surface_point(0.5f * m_voxel, [&](const Vec3& p) {
    glm::ivec3 v;
    for (int k = 0; k < 3; ++k) v[k] = std::clamp(int((p[k] - m_box.lo[k]) / m_voxel), 0, m_dims[k] - 1);
    wall[index(v.x, v.y, v.z)] = 1;
  });

  // The outside: free space reached from the grid's sides.
  m_label.assign(n, 0);
  std::vector<size_t> stack;
  for (size_t i = 0; i < n; ++i) {
    const glm::ivec3 v = coords(i);
    const bool side = v.x == 0 || v.y == 0 || v.z == 0 || v.x == m_dims.x - 1 || v.y == m_dims.y - 1 || v.z == m_dims.z - 1;
    if (side && !wall[i] && m_label[i] == 0) m_label[i] = kOutside, stack.push_back(i);
  }
  while (!stack.empty()) {
    const glm::ivec3 v = coords(stack.back());
    stack.pop_back();
    for (const auto& f : kFaces)
      if (const glm::ivec3 q = v + f; inside(q))
        if (const size_t j = index(q.x, q.y, q.z); !wall[j] && m_label[j] == 0) m_label[j] = kOutside, stack.push_back(j);
  }

  // Clearance: steps (any of the 26 neighbours) to the nearest wall voxel.
  std::vector<uint16_t> steps(n, kUnreached);
  std::deque<size_t> queue;
  for (size_t i = 0; i < n; ++i)
    if (wall[i]) steps[i] = 0, queue.push_back(i);
  while (!queue.empty()) {
    const size_t i = queue.front();
    queue.pop_front();
    const glm::ivec3 v = coords(i);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if (const glm::ivec3 q = v + glm::ivec3(dx, dy, dz); inside(q))
            if (const size_t j = index(q.x, q.y, q.z); steps[j] == kUnreached) steps[j] = uint16_t(steps[i] + 1), queue.push_back(j);
  }

  // Cores: the air farther than kCoreClearance from every surface, split at doors; numbered provisionally from 1.
  const auto core = [&](size_t i) { return m_label[i] == 0 && steps[i] != kUnreached && float(steps[i]) * m_voxel > kCoreClearance; };
  std::vector<int> provisional(n, 0);
  std::vector<VoxelPart> cores = label_parts(m_dims, core, provisional, 0, 1);
  cores.insert(cores.begin(), VoxelPart{});  // cores[c] is core c's: numbers start at 1
  const auto centre = [&](size_t i) { return m_box.lo + (Vec3(coords(i)) + 0.5f) * m_voxel; };
  std::vector<char> kept(cores.size(), 0);
  for (size_t c = 1; c < cores.size(); ++c) kept[c] = cores[c].voxels >= kMinCoreVoxels && !rays.inside_solid(centre(cores[c].first));

  // Each core grows over the free space around it, level by level: a doorway goes half to each side.
  for (size_t i = 0; i < n; ++i)
    if (provisional[i] && kept[size_t(provisional[i])]) queue.push_back(i);
    else provisional[i] = 0;
  while (!queue.empty()) {
    const size_t i = queue.front();
    queue.pop_front();
    const glm::ivec3 v = coords(i);
    for (const auto& f : kFaces)
      if (const glm::ivec3 q = v + f; inside(q))
        if (const size_t j = index(q.x, q.y, q.z); !wall[j] && m_label[j] == 0 && !provisional[j])
          provisional[j] = provisional[i], queue.push_back(j);
  }

  // Boxes and volumes, then the numbers: by floor, then x, then z.
  std::vector<Room> rooms(cores.size());
  const double cell = double(m_voxel) * m_voxel * m_voxel;
  for (size_t i = 0; i < n; ++i)
    if (const int c = provisional[i]) {
      rooms[size_t(c)].box.extend(centre(i) - 0.5f * m_voxel);
      rooms[size_t(c)].box.extend(centre(i) + 0.5f * m_voxel);
      rooms[size_t(c)].volume += cell;
    }
  std::vector<int> order;
  for (size_t c = 1; c < rooms.size(); ++c)
    if (kept[c]) order.push_back(int(c));
  const auto key = [&](int c) {
    const Bounds& b = rooms[size_t(c)].box;
    return std::tuple(std::lround(b.lo.y / 0.5f), b.center().x, b.center().z);
  };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b); });
  std::vector<int> number(rooms.size(), 0);
  for (size_t k = 0; k < order.size(); ++k) {
    number[size_t(order[k])] = int(k) + 1;
    m_rooms.push_back(rooms[size_t(order[k])]);
    m_rooms.back().number = int(k) + 1;
  }
  for (size_t i = 0; i < n; ++i) m_label[i] = number[size_t(provisional[i])];
}

int RoomSplit::at(const Vec3& p) const {
  return label_near(m_label, m_dims, m_box, m_voxel, p, 0);
}

} // namespace hilight
