#pragma once
/// Paper §4.1, Fig. 4f and Fig. 9b: a spotlight for a marked region.
///
/// The spotlight stands at the camera's eye and points along the camera's
/// view direction (the paper's choice: "the position and direction of the
/// current camera"; the designer aims by looking at the region). Its cutoff
/// is the least that covers the region: the largest angle α between that
/// direction and the direction to any region point, plus the soft edge's
/// width (`falloff_deg`) so every region point gets the full intensity
/// (α ≤ cutoff − falloff), plus 1e-3° so rounding keeps the farthest point in.
#include "hilight/lighting.hpp"
#include "hilight/light_space.hpp"
#include "hilight/ray_scene.hpp"

#include <vector>

namespace hilight::painter {

struct SpotRegionSettings {
  float falloff_deg = 0.f;  ///< soft edge width inside the cutoff
  Rgb intensity{1.f};       ///< starting intensity (a solve fits it)
};

/// InputError for an empty region, a zero direction, or a region point at
/// or behind the eye's plane (α ≥ 90°: no spotlight covers it; the cone is
/// limited to below 90°).
Light spot_for_region(const Vec3& eye, const Vec3& direction, const std::vector<Vec3>& region,
                      const SpotRegionSettings& settings = {});

/// The same, for a camera that may stand where no light may (outside the
/// room, inside a wall, outside the light bounds, where the designer's
/// placement rules forbid): the apex slides along the view direction, past
/// each surface in the way, to the first point where `space` lets a light
/// stand (LightSpace::place and admissible: free, and every rule kept) and
/// from which the region's centroid is unblocked; the cutoff is then the
/// least for that apex. Under a ceiling rule the apex is on the ceiling mount
/// above that point, aimed at the region's centroid. InputError when no such
/// point lies before the region.
Light spot_for_region_in_scene(const LightSpace& space, const Vec3& eye, const Vec3& direction,
                               const std::vector<Vec3>& region, const SpotRegionSettings& settings = {});

/// Largest angle (degrees) between `direction` and eye→point over the region.
double max_angle_deg(const Vec3& eye, const Vec3& direction, const std::vector<Vec3>& region);

/// Margin added so the farthest point stays inside after float rounding.
constexpr float kSpotCoverMarginDeg = 1e-3f;

} // namespace hilight::painter
