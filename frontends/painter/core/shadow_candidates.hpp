#pragma once
/// Paper §4.1, Fig. 4a–b and Fig. 5: lights from shadows the designer draws.
///
/// Each request is an occluder (an object of SceneObjects) and a stroked
/// shadow region on a receiver (world points). Candidate light positions are
/// the cells of a grid over the light space's light bounds where a light may
/// stand (LightSpace::place and admissible: out of solids, and the designer's
/// placement rules kept; under a ceiling rule, on its mount) and from which the occluder really shadows the stroke: shadow rays from at
/// least `shadow_fraction` of the stroke's points toward the candidate first
/// hit the occluder. Per request, the candidates inside a cone — apex at the
/// occluder centre, axis from the shadow centre through the occluder centre,
/// half-angle 15°, widened by 5° until it holds 8 candidates — are kept.
/// Requests whose sets overlap are reduced to the intersection (greedily, in
/// order); disjoint sets are kept as they are; each remaining set becomes one
/// point light at the mean of its candidates.
///
/// Intensity of an estimated light: d² · `irradiance` (white), d = distance to
/// its shadow centre, so the lit surroundings of the shadow receive about
/// that irradiance before a solve fits intensities properly.
#include "core/scene_objects.hpp"
#include "hilight/lighting.hpp"
#include "hilight/light_space.hpp"
#include "hilight/ray_scene.hpp"

#include <cstdint>
#include <vector>

namespace hilight::painter {

struct ShadowRequest {
  uint32_t occluder = 0;           ///< object id (SceneObjects)
  std::vector<Vec3> shadow_points; ///< where its shadow should fall
};

struct ShadowCandidateSettings {
  int grid_cells = 16;               ///< candidate grid cells along the longest axis of light_bounds()
  double initial_angle_deg = 15.0;   ///< cone half-angle to start with
  double widen_step_deg = 5.0;       ///< widened by this until it holds `enough` candidates
  double max_angle_deg = 90.0;       ///< never wider
  size_t enough = 8;                 ///< candidates a cone should hold
  double shadow_fraction = 0.5;      ///< share of stroke points the occluder must shadow
  size_t max_shadow_points = 64;     ///< stroke points tested (evenly thinned beyond)
  float irradiance = 1.f;            ///< sets the estimated lights' intensity (see above)
};

/// What one request found (for drawing Fig. 5 in the UI).
struct RequestCandidates {
  Vec3 occluder_centre{0.f}, shadow_centre{0.f};
  double cone_angle_deg = 0;         ///< half-angle the cone reached
  std::vector<Vec3> casting;         ///< every candidate that casts the shadow (blue and yellow dots)
  std::vector<uint32_t> in_cone;     ///< indices into `casting` inside the cone (blue dots)
};

struct ShadowEstimate {
  std::vector<RequestCandidates> requests;
  std::vector<std::vector<Vec3>> kept_sets;  ///< after intersecting (Fig. 5c)
  Lighting lights;                           ///< one per kept set (Fig. 5d)
};

/// InputError when an occluder id is out of range or a request has no points.
/// Requests whose shadow no candidate can cast contribute no set.
ShadowEstimate estimate_shadow_lights(const SceneObjects& objects, const LightSpace& space,
                                      const std::vector<ShadowRequest>& requests,
                                      const ShadowCandidateSettings& settings = {});

} // namespace hilight::painter
