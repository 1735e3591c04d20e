#pragma once
/// The plan view's lux readout (issue 20): the illuminance on the surface
/// straight below a light, from the result view's per-vertex radiance.
#include "hilight/ray_scene.hpp"

#include <optional>
#include <vector>

namespace hilight::painter {

/// Lux on the first surface below `p`, at that triangle's corner nearest the
/// hit: E = 683 · π · luminance(radiance / albedo) (a diffuse surface's
/// radiance is albedo/π · irradiance). nullopt with nothing below, no
/// radiance yet (`radiance` not one per vertex) or a black surface.
std::optional<double> lux_below(const RayScene& rays, const std::vector<Rgb>& radiance, const std::vector<Rgb>& albedo,
                                const Vec3& p);

} // namespace hilight::painter
