// Illuminance criteria: work-plane and surface grids (illuminance_criteria.hpp).
#include "hilight/illuminance_criteria.hpp"

#include "hilight/error.hpp"
#include "hilight/units.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <unordered_set>

namespace hilight {

namespace {

constexpr float kUp = 0.7f;         // |n.y| above this: a floor or a ceiling
constexpr float kVertical = 0.5f;   // |n.y| below this (30° of vertical): a wall

/// The area's box and, for a region, its id.
Bounds area_box(const RayScene& rays, const Regions& regions, const GridArea& area) {
  if (area.box) return *area.box;
  if (area.region) {
    const auto& list = regions.list();
    const auto it = std::find_if(list.begin(), list.end(), [&](const Region& r) { return r.id == *area.region; });
    if (it == list.end())
      throw InputError("region " + std::to_string(*area.region) + " does not exist (hilight info lists " +
                       std::to_string(list.size()) + ")");
    Bounds b = it->box;
    const float v = regions.voxel_size();  // the region's floor and walls stand in the voxels around it
    b.lo -= Vec3(2.f * v);
    b.hi += Vec3(2.f * v);
    return b;
  }
  if (!area.rooms.empty()) {  // the rooms' outlines, with the floor under them and the walls around
    Bounds b;
    for (const auto& r : area.rooms) b.extend(r.box.lo), b.extend(r.box.hi);
    b.lo -= Vec3(0.3f);
    b.hi += Vec3(0.3f);
    return b;
  }
  return rays.scene().bounds;
}

bool in_area(const Regions& regions, const GridArea& area, const Bounds& box, const Vec3& p) {
  if (!box.contains(p)) return false;
  if (!area.rooms.empty() && std::none_of(area.rooms.begin(), area.rooms.end(), [&](const NamedRoom& r) { return r.contains(p); })) return false;
  return !area.region || regions.at(p) == *area.region;
}

/// The lowest upward-facing surface on the vertical line through (x, z)
/// within the box's height, or nothing. An object standing on the floor
/// (a closed box) hides the floor under it (its base and the floor are one
/// plane): when the last hit is such a base, under a top, it is the floor.
std::optional<float> floor_under(const RayScene& rays, const Bounds& box, float x, float z) {
  std::optional<float> floor;
  const float eps = rays.epsilon();
  // A floor on the box's face (the scene's own bounds) must still be hit.
  const float margin = std::max(0.01f * box.extent().y, 16.f * eps);
  Vec3 origin(x, box.hi.y + margin, z);
  std::optional<float> base;
  bool top = false;
  for (int step = 0; step < 64; ++step) {
    const float span = origin.y - (box.lo.y - margin);
    if (!(span > 0.f)) break;
    const Hit hit = rays.intersect(origin, Vec3(0.f, -1.f, 0.f), span);
    if (!hit.valid()) break;
    const Vec3 p = rays.hit_position(hit);
    const float ny = rays.face_normals()[hit.triangle].y;
    base.reset();
    if (ny < -kUp && top) base = p.y;  // the underside of what we entered through its top
    top = ny > kUp;
    if (top) floor = p.y;
    origin = Vec3(x, p.y - eps, z);
  }
  if (base) floor = base;
  return floor;
}

bool near_wall(const RayScene& rays, const Vec3& p, float border) {
  if (!(border > 0.f)) return false;
  for (const Vec3& d : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)})
    if (rays.intersect(p, d, border).valid()) return true;
  return false;
}

double spacing_for(const Bounds& box, double spacing) {
  if (spacing > 0) return spacing;
  const Vec3 e = box.extent();
  return en12464_spacing(std::max(e.x, e.z));
}

} // namespace

size_t IlluminanceCriteria::size() const {
  size_t n = 0;
  for (const auto& g : grids) n += g.points.size();
  return n;
}

SurfacePoints IlluminanceCriteria::points() const {
  SurfacePoints out;
  for (const auto& g : grids) {
    out.positions.insert(out.positions.end(), g.points.begin(), g.points.end());
    out.normals.insert(out.normals.end(), g.normals.begin(), g.normals.end());
  }
  out.albedo.assign(out.positions.size(), Rgb(1.f));
  return out;
}

double en12464_spacing(double d) {
  if (!(d > 0)) return 0.2;
  return std::min(10.0, 0.2 * std::pow(5.0, std::log10(d)));
}

GridFigures grid_figures(const CriterionGrid& grid, std::span<const double> lux, double tolerance) {
  GridFigures f;
  if (lux.empty()) return f;
  double sum = 0;
  f.min = lux[0];
  f.max = lux[0];
  for (double e : lux) {
    sum += e;
    f.min = std::min(f.min, e);
    f.max = std::max(f.max, e);
  }
  f.mean = sum / double(lux.size());
  f.u0 = f.mean > 0 ? f.min / f.mean : 0;
  f.met = f.mean >= grid.lux * (1 - tolerance) && f.u0 >= grid.u0 * (1 - tolerance);
  return f;
}

std::vector<double> lux_from_radiance(std::span<const Rgb> radiance) {
  std::vector<double> out(radiance.size());
  for (size_t i = 0; i < radiance.size(); ++i) out[i] = kLumensPerWatt * kPi * luminance(radiance[i]);
  return out;
}

CriterionGrid make_work_plane(const RayScene& rays, const Regions& regions, const GridArea& area, float height, double lux,
                              double u0, double spacing, float border) {
  const Bounds box = area_box(rays, regions, area);
  CriterionGrid grid;
  grid.name = "workplane";
  grid.kind = CriterionGrid::Kind::WorkPlane;
  grid.lux = lux;
  grid.u0 = u0;
  grid.spacing = spacing_for(box, spacing);
  const Vec3 e = box.extent();
  // EN 12464-1: cells no larger than p, a point at each cell's centre.
  const int nx = std::max(1, int(std::ceil(e.x / grid.spacing))), nz = std::max(1, int(std::ceil(e.z / grid.spacing)));
  for (int iz = 0; iz < nz; ++iz)
    for (int ix = 0; ix < nx; ++ix) {
      const float x = box.lo.x + (float(ix) + 0.5f) * e.x / float(nx), z = box.lo.z + (float(iz) + 0.5f) * e.z / float(nz);
      const auto floor = floor_under(rays, box, x, z);
      if (!floor) continue;
      const Vec3 p(x, *floor + height, z);
      // A point on a desk top at the plane's height is on the plane: look a hair above it.
      const Vec3 above = p + Vec3(0.f, 4.f * rays.epsilon(), 0.f);
      if (!in_area(regions, area, box, p) || rays.inside_solid(above) || near_wall(rays, above, border)) continue;
      grid.points.push_back(p);
      grid.normals.push_back(Vec3(0.f, 1.f, 0.f));
    }
  if (grid.points.empty())
    throw InputError("the work plane has no point: no floor under the area, or every point is within the " +
                     std::to_string(border) + " border of a wall");
  return grid;
}

CriterionGrid make_surface_grid(const RayScene& rays, const Regions& regions, const GridArea& area, CriterionGrid::Kind kind,
                                double lux, double u0, const CriterionGrid& plane, double spacing) {
  const Scene& scene = rays.scene();
  const Bounds box = area_box(rays, regions, area);
  CriterionGrid grid;
  grid.kind = kind;
  grid.name = to_string(kind);
  grid.lux = lux;
  grid.u0 = u0;
  grid.spacing = spacing_for(box, spacing);
  const float cell = float(grid.spacing);
  const float probe = std::max(regions.voxel_size(), 4.f * rays.epsilon());  // a step into the room
  float above = -std::numeric_limits<float>::max();
  for (const Vec3& p : plane.points) above = std::max(above, p.y);
  const auto seen = [&](const Vec3& p, const Vec3& n) {
    const Vec3 from = p + 4.f * rays.epsilon() * n;
    for (const Vec3& q : plane.points) {
      const Vec3 d = q - from;
      const float len = glm::length(d);
      if (glm::dot(d, n) > 0.f && len > 0.f && !rays.occluded(from, d / len, len)) return true;
    }
    return false;
  };
  // One point per cell and facing (the two sides of a thin wall are two points).
  std::unordered_set<uint64_t> taken;
  auto key = [&](const Vec3& p, const Vec3& n) {
    const auto q = [&](float v, float lo) { return uint64_t(std::clamp(int64_t(std::floor((v - lo) / cell)), int64_t(0), int64_t(0xFFFF))); };
    const uint64_t facing = uint64_t(n.x > 0.5f) | uint64_t(n.x < -0.5f) << 1 | uint64_t(n.z > 0.5f) << 2 | uint64_t(n.z < -0.5f) << 3;
    return q(p.x, box.lo.x) | q(p.y, box.lo.y) << 16 | q(p.z, box.lo.z) << 32 | facing << 48;
  };
  for (size_t t = 0; t < scene.triangles.size(); ++t) {
    const Vec3 n = scene.face_normal(t);
    const bool wanted = kind == CriterionGrid::Kind::Walls ? std::abs(n.y) < kVertical : n.y < -kUp;
    if (!wanted) continue;
    const auto& tri = scene.triangles[t];
    const Vec3 a = scene.positions[tri[0]], b = scene.positions[tri[1]], c = scene.positions[tri[2]];
    const float longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    const int steps = std::clamp(int(std::ceil(longest / cell)), 1, 256);
    for (int i = 0; i < steps; ++i)
      for (int j = 0; i + j < steps; ++j) {
        const float u = (float(i) + 1.f / 3.f) / float(steps), v = (float(j) + 1.f / 3.f) / float(steps);
        const Vec3 p = a + u * (b - a) + v * (c - a);
        if (p.y <= above || !in_area(regions, area, box, p + probe * n)) continue;
        if (regions.at(p + probe * n) < 0) continue;  // facing into a solid or nowhere
        const uint64_t k = key(p, n);
        if (taken.count(k) || !seen(p, n)) continue;
        taken.insert(k);
        grid.points.push_back(p);
        grid.normals.push_back(n);
      }
  }
  if (grid.points.empty())
    throw InputError(std::string("no ") + to_string(kind) + " face into the area above the work plane");
  return grid;
}

double surround_lux(double task_lux) {
  if (task_lux >= 750) return 500;
  if (task_lux >= 500) return 300;
  if (task_lux >= 300) return 200;
  return task_lux;
}

std::vector<CriterionGrid> make_zones(const RayScene& rays, const Regions& regions, const Bounds& task, const CriterionGrid& task_plane,
                                      float height, float border, float surround_width, float background_width) {
  std::set<int> rooms;
  for (const Vec3& p : task_plane.points)
    if (const int r = regions.at(p); r >= 0) rooms.insert(r);
  // Distance over the floor from the task area (0 inside it).
  const auto from_task = [&](const Vec3& p) {
    const float dx = std::max({task.lo.x - p.x, 0.f, p.x - task.hi.x}), dz = std::max({task.lo.z - p.z, 0.f, p.z - task.hi.z});
    return std::hypot(dx, dz);
  };
  std::vector<CriterionGrid> out;
  const double surround = surround_lux(task_plane.lux);
  struct Band {
    const char* name;
    float inner, outer;
    double lux, u0;
  };
  for (const Band& band : {Band{"surround", 0.f, surround_width, surround, 0.4},
                           Band{"background", surround_width, surround_width + background_width, surround / 3.0, 0.1}}) {
    Bounds outer = task;
    outer.lo -= Vec3(band.outer, 0.f, band.outer);
    outer.hi += Vec3(band.outer, 0.f, band.outer);
    const Vec3 e = outer.extent();
    const double spacing = std::min(en12464_spacing(std::max(e.x, e.z)), 0.5 * double(band.outer - band.inner));
    GridArea area;
    area.box = outer;
    CriterionGrid g;
    try {
      g = make_work_plane(rays, regions, area, height, band.lux, band.u0, spacing, border);
    } catch (const InputError&) {
      continue;  // no floor there
    }
    CriterionGrid kept = g;
    kept.name = band.name;
    kept.points.clear();
    kept.normals.clear();
    for (size_t i = 0; i < g.points.size(); ++i) {
      const float d = from_task(g.points[i]);
      if (d > band.inner + 1e-4f && d <= band.outer + 1e-4f && (rooms.empty() || rooms.count(regions.at(g.points[i])))) {
        kept.points.push_back(g.points[i]);
        kept.normals.push_back(g.normals[i]);
      }
    }
    if (!kept.points.empty()) out.push_back(std::move(kept));
  }
  return out;
}

const char* to_string(CriterionGrid::Kind kind) {
  switch (kind) {
    case CriterionGrid::Kind::WorkPlane: return "workplane";
    case CriterionGrid::Kind::Walls: return "walls";
    case CriterionGrid::Kind::Ceiling: return "ceiling";
  }
  return "?";
}

} // namespace hilight
