// The illuminance design's parts (design_parts.hpp).
#include "design_parts.hpp"

#include "hilight/point_grid.hpp"

namespace hilight::design {

std::vector<Vec3> cylinder_places(const RayScene& rays, const IlluminanceCriteria& criteria, float floor_y, float height) {
  std::vector<Vec3> out;
  for (const auto& g : criteria.grids)
    if (g.kind == CriterionGrid::Kind::WorkPlane)
      for (const Vec3& p : g.points) {
        const Vec3 at(p.x, floor_y + height, p.z);
        if (!rays.inside_solid(at)) out.push_back(at);
      }
  return out;
}

namespace {

/// A wall or ceiling grid's points are one per cell where the surfaces lie
/// (make_surface_grid), not a lattice: between each pair of neighbours on
/// the same plane, the midpoint, where the surface runs on between them
/// (not across a window or past a corner) and nothing stands in between.
void add_between_on_surfaces(const RayScene& rays, const CriterionGrid& g, SurfacePoints& out) {
  const float reach = 1.5f * float(g.spacing), eps = rays.epsilon();
  if (!(reach > 0.f)) return;
  PointGrid grid(reach);
  for (size_t i = 0; i < g.points.size(); ++i) grid.add(g.points[i], uint32_t(i));
  std::unordered_set<uint64_t> taken;  // midpoints already added, on a fine lattice
  const float fine = 1e-3f * reach;
  // The midpoint of i and a later neighbour j on the same surface, once.
  const auto between = [&](size_t i, size_t j) {
    const Vec3 &p = g.points[i], &n = g.normals[i];
    if (j <= i || glm::dot(n, g.normals[j]) < 0.999f) return;
    const Vec3 d = g.points[j] - p;
    const float len = glm::length(d);
    if (len > reach || len < fine || std::abs(glm::dot(n, d)) > 2.f * eps) return;
    const Vec3 q = p + 0.5f * d;
    const uint64_t k = PointGrid::key(glm::ivec3(glm::round(q / fine)));
    if (taken.count(k)) return;
    const Vec3 lift = 4.f * eps * n;
    if (rays.occluded(p + lift, d / len, len)) return;
    const Hit under = rays.intersect(q + lift, -n, 8.f * eps);
    if (!under.valid() || glm::dot(rays.face_normals()[under.triangle], n) < 0.999f) return;
    taken.insert(k);
    out.positions.push_back(q);
    out.normals.push_back(n);
  };
  for (size_t i = 0; i < g.points.size(); ++i) grid.for_each_near(g.points[i], [&](uint32_t j) { between(i, j); });
}

} // namespace

void add_between(const RayScene& rays, const CriterionGrid& g, SurfacePoints& out) {
  if (g.points.size() < 2) return;
  if (g.kind != CriterionGrid::Kind::WorkPlane) return add_between_on_surfaces(rays, g, out);
  // The cells: the smallest steps between points of a row and of a column.
  const auto step = [&](int along, int across) {
    std::vector<std::pair<float, float>> v;
    for (const Vec3& p : g.points) v.push_back({p[across], p[along]});
    std::sort(v.begin(), v.end());
    float best = std::numeric_limits<float>::max();
    for (size_t i = 1; i < v.size(); ++i)
      if (std::abs(v[i].first - v[i - 1].first) < 1e-4f && v[i].second - v[i - 1].second > 1e-4f)
        best = std::min(best, v[i].second - v[i - 1].second);
    return best < std::numeric_limits<float>::max() ? best : float(g.spacing);
  };
  const float cx = step(0, 2), cz = step(2, 0);
  if (!(cx > 0.f) || !(cz > 0.f)) return;
  const Vec3 o = g.points.front();
  const auto key = [&](const Vec3& p) {
    const int64_t i = std::llround(2.0 * double(p.x - o.x) / double(cx)), k = std::llround(2.0 * double(p.z - o.z) / double(cz));
    return uint64_t(i + (1 << 30)) << 32 | uint64_t(k + (1 << 30));
  };
  std::unordered_set<uint64_t> taken;
  for (const Vec3& p : g.points) taken.insert(key(p));
  const Vec3 lift(0.f, 4.f * rays.epsilon(), 0.f);
  for (const Vec3& p : g.points)
    for (int a = -1; a <= 1; ++a)
      for (int b = -1; b <= 1; ++b) {
        if (!a && !b) continue;
        const Vec3 q = p + Vec3(0.5f * float(a) * cx, 0.f, 0.5f * float(b) * cz);
        const uint64_t k = key(q);
        if (taken.count(k)) continue;
        const Vec3 d = q - p;
        const float len = glm::length(d);
        if (rays.occluded(p + lift, d / len, len) || rays.inside_solid(q + lift)) continue;
        taken.insert(k);
        out.positions.push_back(q);
        out.normals.push_back(Vec3(0.f, 1.f, 0.f));
      }
}

std::vector<double> program_column(const IlluminanceCriteria& criteria, const Points& pts, double margin, const Field& f) {
  const std::vector<double>& e = f.lux;
  std::vector<double> col;
  if (pts.cylinders) col.push_back(f.cylindrical);  // Ēz ≥ (1+m)·wanted
  size_t first = 0;
  for (size_t g = 0; g < criteria.grids.size(); ++g) {
    const auto& grid = criteria.grids[g];
    const size_t n = grid.points.size();
    const double mean = std::accumulate(e.begin() + long(first), e.begin() + long(first + n), 0.0) / double(n);
    col.push_back(mean);
    if (grid.u0 > 0) {
      const double u0 = grid.u0 * (1 + margin);
      for (size_t i = 0; i < n; ++i) col.push_back(e[first + i] - u0 * mean);
      const auto [from, count] = pts.between[g];
      for (size_t i = 0; i < count; ++i) col.push_back(e[from + i] - u0 * mean);
    }
    first += n;
  }
  return col;
}

std::vector<double> program_bounds(const IlluminanceCriteria& criteria, const Points& pts, double margin, double cylindrical_min) {
  std::vector<double> b;
  if (pts.cylinders) b.push_back(cylindrical_min * (1 + margin) * (1.0 + 1e-4));
  for (size_t g = 0; g < criteria.grids.size(); ++g) {
    const auto& grid = criteria.grids[g];
    b.push_back(grid.lux * (1 + margin) * (1.0 + 1e-4));
    if (grid.u0 > 0) b.insert(b.end(), grid.points.size() + pts.between[g].second, 0.0);
  }
  return b;
}

double layout_ugr(const std::vector<const Field*>& fields, const std::vector<double>& x, size_t observers) {
  double worst = kNaN;
  for (size_t o = 0; o < observers; ++o) {
    double glare = 0, indirect = 0;
    for (size_t j = 0; j < fields.size(); ++j) {
      glare += x[j] * x[j] * fields[j]->glare[o];
      indirect += x[j] * fields[j]->indirect[o];
    }
    const double u = unified_glare_rating(glare, indirect);
    if (std::isfinite(u) && !(u <= worst)) worst = u;
  }
  return worst;
}

std::vector<float> candidate_layers(const LightSpace& space, float plane, float step) {
  if (space.rules().ceiling_offset) return {plane + 1e-3f};
  const float bottom = std::max(space.bounds().lo.y, plane + step), top = space.bounds().hi.y - 1e-3f;
  std::vector<float> layers;
  for (int k = 0; k < 3; ++k) layers.push_back(bottom + (top - bottom) * float(k + 1) / 3.f);
  return layers;
}

} // namespace hilight::design
