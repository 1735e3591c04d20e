#include "core/shadow_candidates.hpp"

#include "core/region.hpp"
#include "hilight/error.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace hilight::painter {

namespace {

/// Candidate positions: the centres of a grid over the light bounds, each
/// where a light for it stands (LightSpace::place: on the ceiling mount under
/// a ceiling rule) if `space` admits it there (free, and the designer's rules
/// kept); each position once (computed once per estimate).
std::vector<Vec3> candidate_grid(const LightSpace& space, int cells_along_longest) {
  const Bounds b = space.light_bounds();
  const Vec3 extent = b.extent();
  const float longest = std::max({extent.x, extent.y, extent.z});
  const float cell = longest / float(std::max(cells_along_longest, 1));
  int counts[3];
  for (int a = 0; a < 3; ++a) counts[a] = std::max(1, int(std::round(extent[a] / cell)));
  std::vector<Vec3> grid;
  for (int i = 0; i < counts[0]; ++i)
    for (int j = 0; j < counts[1]; ++j)
      for (int k = 0; k < counts[2]; ++k) {
        Vec3 p = b.lo + extent * Vec3((float(i) + 0.5f) / float(counts[0]), (float(j) + 0.5f) / float(counts[1]),
                                      (float(k) + 0.5f) / float(counts[2]));
        const std::optional<Vec3> at = space.place(p);
        // A column's cells share one ceiling place: the first stands for them.
        if (at && space.admissible(*at) && (*at == p || std::find(grid.begin(), grid.end(), *at) == grid.end())) grid.push_back(*at);
      }
  return grid;
}

/// Stroke points snapped to the surface and lifted off it, at most `limit` (evenly thinned).
std::vector<SurfacePick> shadow_samples(const RayScene& rays, const std::vector<Vec3>& points, size_t limit) {
  std::vector<SurfacePick> picks;
  const size_t step = std::max<size_t>(1, (points.size() + limit - 1) / std::max<size_t>(limit, 1));
  for (size_t i = 0; i < points.size(); i += step)
    if (auto pick = pick_near(rays, points[i])) picks.push_back(*pick);
  return picks;
}

/// True when the occluder shadows at least `fraction` of the picks from `light`.
bool casts_shadow(const SceneObjects& objects, const RayScene& rays, uint32_t occluder,
                  const std::vector<SurfacePick>& picks, const Vec3& light, double fraction) {
  size_t shadowed = 0, needed = size_t(std::ceil(fraction * double(picks.size())));
  for (size_t i = 0; i < picks.size(); ++i) {
    const SurfacePick& p = picks[i];
    Vec3 to_light = light - p.position;
    const float distance = glm::length(to_light);
    to_light /= distance;
    if (glm::dot(to_light, p.normal) <= 0.f) continue;  // the light is behind this surface: no shadow to draw
    Vec3 origin = p.position + rays.epsilon() * p.normal;
    Hit hit = rays.intersect(origin, to_light, distance);
    if (hit.valid() && objects.object_of_triangle(hit.triangle) == occluder) ++shadowed;
    if (shadowed >= needed) return true;
    if (shadowed + (picks.size() - i - 1) < needed) return false;
  }
  return shadowed >= needed && needed > 0;
}

double angle_deg(const Vec3& a, const Vec3& b) {
  double c = glm::dot(glm::normalize(DVec3(a)), glm::normalize(DVec3(b)));
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / kPi;
}

} // namespace

ShadowEstimate estimate_shadow_lights(const SceneObjects& objects, const LightSpace& space,
                                      const std::vector<ShadowRequest>& requests, const ShadowCandidateSettings& settings) {
  const std::string what = "shadow lights";
  for (size_t r = 0; r < requests.size(); ++r) {
    if (requests[r].occluder >= objects.count())
      throw InputError(what, "request " + std::to_string(r) + ": no object " + std::to_string(requests[r].occluder));
    if (requests[r].shadow_points.empty())
      throw InputError(what, "request " + std::to_string(r) + ": no shadow points");
  }
  const RayScene& rays = space.rays();
  const std::vector<Vec3> grid = candidate_grid(space, settings.grid_cells);
  ShadowEstimate estimate;
  std::vector<std::vector<uint32_t>> sets;  // grid indices per request, sorted
  std::vector<Vec3> set_shadow_centres;
  for (const ShadowRequest& request : requests) {
    RequestCandidates found;
    found.occluder_centre = objects.centre(request.occluder);
    found.shadow_centre = centroid(request.shadow_points);
    const std::vector<SurfacePick> picks = shadow_samples(rays, request.shadow_points, settings.max_shadow_points);
    std::vector<uint32_t> casting_ids;
    for (uint32_t g = 0; g < grid.size(); ++g)
      if (casts_shadow(objects, rays, request.occluder, picks, grid[g], settings.shadow_fraction)) {
        casting_ids.push_back(g);
        found.casting.push_back(grid[g]);
      }
    // The cone: apex at the occluder centre, axis away from the shadow.
    const Vec3 axis = found.occluder_centre - found.shadow_centre;
    std::vector<double> angles;
    for (const Vec3& c : found.casting) angles.push_back(angle_deg(c - found.occluder_centre, axis));
    double cone = settings.initial_angle_deg;
    auto count_inside = [&](double a) { return size_t(std::count_if(angles.begin(), angles.end(), [&](double x) { return x <= a; })); };
    while (count_inside(cone) < settings.enough && cone + settings.widen_step_deg <= settings.max_angle_deg)
      cone += settings.widen_step_deg;
    found.cone_angle_deg = cone;
    std::vector<uint32_t> in_set;
    for (uint32_t i = 0; i < angles.size(); ++i)
      if (angles[i] <= cone) {
        found.in_cone.push_back(i);
        in_set.push_back(casting_ids[i]);
      }
    if (!in_set.empty()) {
      // Greedy reduction (Fig. 5c): join the first kept set this one overlaps.
      bool merged = false;
      for (size_t s = 0; s < sets.size() && !merged; ++s) {
        std::vector<uint32_t> common;
        std::set_intersection(sets[s].begin(), sets[s].end(), in_set.begin(), in_set.end(), std::back_inserter(common));
        if (!common.empty()) {
          sets[s] = std::move(common);
          merged = true;
        }
      }
      if (!merged) {
        sets.push_back(std::move(in_set));
        set_shadow_centres.push_back(found.shadow_centre);
      }
    }
    estimate.requests.push_back(std::move(found));
  }
  for (size_t s = 0; s < sets.size(); ++s) {
    std::vector<Vec3> positions;
    for (uint32_t g : sets[s]) positions.push_back(grid[g]);
    const Vec3 mean = centroid(positions);
    const float d = glm::length(mean - set_shadow_centres[s]);
    estimate.lights.push_back(Light::point(mean, Rgb(settings.irradiance * d * d)));
    estimate.kept_sets.push_back(std::move(positions));
  }
  return estimate;
}

} // namespace hilight::painter
