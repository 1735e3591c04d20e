#include "hilight/regions.hpp"
#include "hilight/voxel_labels.hpp"

#include <algorithm>
#include <cmath>

namespace hilight {

Regions::Regions(const RayScene& rays, int cells) {
  const Scene& scene = rays.scene();
  m_box = scene.light_bounds();
  const Vec3 extent = m_box.extent();
  m_voxel = std::max({extent.x, extent.y, extent.z}) / float(std::max(cells, 1));
  if (!(m_voxel > 0.f)) return;
  for (int k = 0; k < 3; ++k) m_dims[k] = std::max(1, int(std::ceil(extent[k] / m_voxel)));
  const size_t n = size_t(m_dims.x) * m_dims.y * m_dims.z;
  auto voxel_of = [&](const Vec3& p) {
    glm::ivec3 v;
    for (int k = 0; k < 3; ++k) v[k] = std::clamp(int((p[k] - m_box.lo[k]) / m_voxel), 0, m_dims[k] - 1);
    return v;
  };
  // Walls: every voxel a surface passes through (points on each triangle
  // closer than half a voxel apart).
  std::vector<char> wall(n, 0);
  scene.for_each_surface_point(0.5f * m_voxel, [&](const Vec3& p) {
    const glm::ivec3 v = voxel_of(p);
    wall[index(v.x, v.y, v.z)] = 1;
  });
  // The free voxels' 6-connected parts, labelled provisionally in scan order.
  m_label.assign(n, -1);
  const std::vector<VoxelPart> parts = label_parts(m_dims, [&](size_t i) { return !wall[i]; }, m_label, -1, 0);
  // Keep the parts that are not inside solids and hold a light with room to
  // spare (pockets between furniture parts, under a stair: not regions),
  // numbered by size.
  constexpr size_t kMinVoxels = 32;
  auto centre = [&](size_t i) {
    const glm::ivec3 v(int(i % size_t(m_dims.x)), int(i / size_t(m_dims.x) % size_t(m_dims.y)), int(i / (size_t(m_dims.x) * m_dims.y)));
    return m_box.lo + (Vec3(v) + 0.5f) * m_voxel;
  };
  std::vector<int> order(parts.size());
  for (size_t p = 0; p < parts.size(); ++p) order[p] = int(p);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return parts[size_t(a)].voxels > parts[size_t(b)].voxels; });
  std::vector<int> renamed(parts.size(), -1);
  for (int p : order)
    if (parts[size_t(p)].voxels >= kMinVoxels && !rays.inside_solid(centre(parts[size_t(p)].first))) {
      renamed[size_t(p)] = int(m_regions.size());
      m_regions.push_back({int(m_regions.size()), {}, 0.0, false});
    }
  const double cell_volume = double(m_voxel) * m_voxel * m_voxel;
  for (size_t i = 0; i < n; ++i) {
    if (m_label[i] < 0) continue;
    m_label[i] = renamed[size_t(m_label[i])];
    if (m_label[i] < 0) continue;
    Region& r = m_regions[size_t(m_label[i])];
    r.box.extend(centre(i) - 0.5f * m_voxel);
    r.box.extend(centre(i) + 0.5f * m_voxel);
    r.volume += cell_volume;
    const int x = int(i % size_t(m_dims.x)), y = int(i / size_t(m_dims.x) % size_t(m_dims.y)), z = int(i / (size_t(m_dims.x) * m_dims.y));
    if (x == 0 || y == 0 || z == 0 || x == m_dims.x - 1 || y == m_dims.y - 1 || z == m_dims.z - 1) r.at_border = true;
  }
}

int Regions::at(const Vec3& p) const {
  return label_near(m_label, m_dims, m_box, m_voxel, p, -1);
}

} // namespace hilight
