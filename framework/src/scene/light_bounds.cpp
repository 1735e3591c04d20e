#include "hilight/light_bounds.hpp"

#include "hilight/own_frame.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace hilight {

namespace {

constexpr int kGrid = 32;
/// A flat axis shorter than this share of its grown extent has no depth to
/// look into: its sides count as open (a floor alone, a two-sided sheet).
constexpr float kDepthless = 1e-3f;

/// Nearest surface depth seen from both faces across axis k, per grid cell.
struct DepthMaps {
  int k, a, b;
  std::vector<float> from_lo, from_hi;
};

} // namespace

namespace {

/// side_openness() of the scene's surfaces as `to_frame` maps them (the
/// world's axes, or the scene's own), over `box` (their box in that frame).
std::array<float, 6> openness_in(const Scene& scene, const std::function<Vec3(const Vec3&)>& to_frame, const Bounds& box) {
  const Vec3 extent = box.extent();
  std::array<DepthMaps, 3> maps;
  for (int k = 0; k < 3; ++k) {
    const float inf = std::numeric_limits<float>::infinity();
    maps[k] = {k, (k + 1) % 3, (k + 2) % 3, std::vector<float>(kGrid * kGrid, inf), std::vector<float>(kGrid * kGrid, inf)};
  }
  auto cell_of = [&](float v, int axis) {
    return extent[axis] > 0.f ? std::clamp(int((v - box.lo[axis]) / extent[axis] * kGrid), 0, kGrid - 1) : 0;
  };
  const float cell = std::max(extent.x, std::max(extent.y, extent.z)) / kGrid;
  // Points on the surfaces, closer than half a cell, mark the maps.
  scene.for_each_surface_point(0.5f * cell, [&](const Vec3& world) {
    const Vec3 p = to_frame(world);
    for (auto& m : maps) {
      const int c = cell_of(p[m.a], m.a) * kGrid + cell_of(p[m.b], m.b);
      m.from_lo[c] = std::min(m.from_lo[c], p[m.k] - box.lo[m.k]);
      m.from_hi[c] = std::min(m.from_hi[c], box.hi[m.k] - p[m.k]);
    }
  });
  std::array<float, 6> open{};
  for (const auto& m : maps) {
    // A flat face (no extent along a or b) is one row of cells.
    const int rows = extent[m.a] > 0.f ? kGrid : 1, cols = extent[m.b] > 0.f ? kGrid : 1;
    const float deep = 0.25f * extent[m.k];
    int lo_open = 0, hi_open = 0;
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c) {
        lo_open += !(m.from_lo[r * kGrid + c] <= deep);
        hi_open += !(m.from_hi[r * kGrid + c] <= deep);
      }
    open[2 * m.k] = float(lo_open) / float(rows * cols);
    open[2 * m.k + 1] = float(hi_open) / float(rows * cols);
  }
  return open;
}

} // namespace

std::array<float, 6> side_openness(const Scene& scene) {
  return openness_in(scene, [](const Vec3& p) { return p; }, scene.bounds);
}

namespace {

/// A scene counts as turned when its box in its own frame (grown) has less
/// than this share of the world box's volume: an upright room or building
/// has about the same box either way (its own axes within a few degrees of
/// the world's), a turned one a much larger world box.
constexpr double kTurnedVolume = 0.7;

/// Grows a flat extent [lo, hi] (below `flat`) to `grown`, on the side the
/// surfaces face when most of their area faces one way (`lean`: +1 all face
/// up the axis), else on both; never beyond a closed side (`open_lo`,
/// `open_hi` false): a floor with low objects gets height above it, a
/// closed flat (a floor, walls and a ceiling: 3 m high and 16 m across)
/// keeps its floor and ceiling (issue 33: it reached 2.4 m under its floor
/// and over its roof, and those two outside regions were each larger than
/// the flat).
void grow_flat(float& lo, float& hi, float lean, float grown, bool open_lo, bool open_hi) {
  const float more = grown - (hi - lo);
  const bool down = lean <= 0.5f && open_lo, up = lean >= -0.5f && open_hi;
  if (up && down) {
    lo -= 0.5f * more;
    hi += 0.5f * more;
  } else if (up) {
    hi += more;
  } else if (down) {
    lo -= more;
  }
}

/// The surface's area vectors in a frame (`to_frame` takes a world
/// direction there): summed (`facing`), summed by magnitude per axis
/// (`area`), and the area facing squarely along one of its axes.
struct Facing {
  Vec3 facing{0.f}, area{0.f};
  double total = 0.0, square = 0.0;
};

/// Triangles covered back to back by another (the same corners, wound the
/// other way): a two-sided sheet, which faces neither way. Counted in the
/// lean, a flipped copy of half a floor's quad made it face "both ways", and
/// the light bounds reached only half as high (issue 35, item 11).
std::vector<bool> back_to_back(const Scene& scene) {
  using Corners = std::array<float, 9>;
  std::vector<std::pair<Corners, uint32_t>> keyed(scene.triangles.size());
  for (size_t t = 0; t < scene.triangles.size(); ++t) {
    std::array<Vec3, 3> c;
    for (int k = 0; k < 3; ++k) c[k] = scene.positions[scene.triangles[t][k]];
    std::sort(c.begin(), c.end(), [](const Vec3& a, const Vec3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); });
    keyed[t] = {{c[0].x, c[0].y, c[0].z, c[1].x, c[1].y, c[1].z, c[2].x, c[2].y, c[2].z}, uint32_t(t)};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<bool> paired(scene.triangles.size(), false);
  auto normal = [&](uint32_t t) {
    const auto& tri = scene.triangles[t];
    return glm::cross(scene.positions[tri[1]] - scene.positions[tri[0]], scene.positions[tri[2]] - scene.positions[tri[0]]);
  };
  for (size_t i = 0, j = 0; i < keyed.size(); i = j) {
    for (j = i + 1; j < keyed.size() && keyed[j].first == keyed[i].first;) ++j;
    bool both_ways = false;  // one pass: a group is a handful, but a crafted file may pile up thousands
    for (size_t b = i + 1; b < j && !both_ways; ++b) both_ways = glm::dot(normal(keyed[i].second), normal(keyed[b].second)) < 0.f;
    for (size_t b = i; b < j && both_ways; ++b) paired[keyed[b].second] = true;
  }
  return paired;
}

Facing facing_in(const Scene& scene, const glm::mat3& to_frame) {
  Facing f;
  const std::vector<bool> two_sided = back_to_back(scene);
  for (size_t t = 0; t < scene.triangles.size(); ++t) {
    const auto& tri = scene.triangles[t];
    const Vec3& a = scene.positions[tri[0]];
    const Vec3 n = to_frame * glm::cross(scene.positions[tri[1]] - a, scene.positions[tri[2]] - a);  // length: twice the area
    if (!two_sided[t]) {  // the lean: which way the surface faces
      f.facing += n;
      f.area += glm::abs(n);
    }
    const float length = glm::length(n);
    f.total += double(length);
    if (std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)}) >= 0.999f * length) f.square += double(length);
  }
  return f;
}

/// [lo, hi] (in the frame of `f`) with each flat axis grown (grow_flat);
/// `openness()` gives side_openness() in that frame, asked only when an axis
/// is flat. A side is closed when under kOpenSide of it is open, unless the
/// axis has no depth to look into (a floor alone: its face is the floor).
void grow_flat_axes(Vec3& lo, Vec3& hi, const Facing& f, float flat, float grown,
                    const std::function<std::array<float, 6>()>& openness) {
  std::optional<std::array<float, 6>> open;
  for (int k = 0; k < 3; ++k) {
    const float extent = hi[k] - lo[k];
    if (!(extent < flat)) continue;
    if (!open) open = openness();
    const bool depthless = !(extent > kDepthless * grown);
    grow_flat(lo[k], hi[k], f.area[k] > 0.f ? f.facing[k] / f.area[k] : 0.f, grown, depthless || (*open)[2 * k] >= kOpenSide,
              depthless || (*open)[2 * k + 1] >= kOpenSide);
  }
}

/// Where lights may stand when the scene is turned off the world's axes
/// (a floor with models, tilted): its box in its own frame (own_frame.hpp),
/// grown along its own flat axes, as an upright one is along the world's;
/// returned as the world box around it. Nothing when that box is not much
/// tighter than `world` (the scene is about as upright as it is turned).
std::optional<Bounds> turned_bounds(const Scene& scene, const Bounds& world, float flat, float grown) {
  const OwnFrame frame = own_frame(scene);
  Vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (const Vec3& p : scene.positions) {
    const Vec3 q = frame.to_own(p - frame.centre);
    lo = glm::min(lo, q), hi = glm::max(hi, q);
  }
  const glm::mat3 to_own = glm::transpose(frame.axes);
  Bounds own_box;
  own_box.lo = lo, own_box.hi = hi;
  grow_flat_axes(lo, hi, facing_in(scene, to_own), flat, grown, [&] {
    return openness_in(scene, [&](const Vec3& p) { return frame.to_own(p - frame.centre); }, own_box);
  });
  auto volume = [](const Vec3& extent) { return double(extent.x) * double(extent.y) * double(extent.z); };
  if (!(volume(hi - lo) < kTurnedVolume * volume(world.extent()))) return std::nullopt;
  Bounds box = scene.bounds;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 own((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
    const Vec3 at = frame.centre + frame.to_world(own);
    box.lo = glm::min(box.lo, at), box.hi = glm::max(box.hi, at);
  }
  return box;
}

} // namespace

Bounds Scene::light_bounds() const {
  // A room or a house keeps its walls (a light outside would only light
  // their outer sides; open_light_bounds() is for targets lit from outside).
  // A flat axis grows to half the diagonal: a floor with low objects gets
  // height, on the side its surfaces face when most of their area faces one
  // way (a light under an open floor would only light its underside), and
  // never beyond a closed side (a flat's floor and ceiling are its walls).
  Bounds b = bounds;
  const float flat = 0.25f * diagonal(), grown = 0.5f * diagonal();
  const Facing world = facing_in(*this, glm::mat3(1.f));
  grow_flat_axes(b.lo, b.hi, world, flat, grown, [this] { return side_openness(*this); });
  // Most of the surface squarely along the world's axes (walls, floors):
  // upright, whatever its own frame says.
  if (world.square >= 0.5 * world.total) return b;
  // A scene turned off the world's axes: the same space, turned (measured:
  // the curved models on their floor, tilted at random, had their lamps
  // outside the world box and the solve ended on its top face at D̄ 15%).
  if (auto turned = turned_bounds(*this, b, flat, grown)) return *turned;
  return b;
}

Bounds open_light_bounds(const Scene& scene) {
  Bounds b = scene.light_bounds();
  const auto open = side_openness(scene);
  const float margin = kOpenMargin * scene.diagonal();
  for (int k = 0; k < 3; ++k) {
    if (open[2 * k] >= kOpenSide) b.lo[k] = std::min(b.lo[k], scene.bounds.lo[k] - margin);
    if (open[2 * k + 1] >= kOpenSide) b.hi[k] = std::max(b.hi[k], scene.bounds.hi[k] + margin);
  }
  return b;
}

} // namespace hilight
