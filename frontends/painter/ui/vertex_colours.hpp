#pragma once
/// What each vertex shows in the three views: the result I(p), the painted
/// target Ψ, and |Ψ − I| as a heat map. Radiance is scaled by one exposure
/// and clamped, the convention of hilight's PNG output, so a screenshot of
/// the result view and `hilight render`'s PNG read alike.
#include "hilight/math.hpp"
#include "ui/scene_mesh.hpp"

#include <vector>

namespace hilight::painter::ui {

enum class ViewMode { Result, Target, Difference };

/// Exposure that maps the 99th percentile of the luminance of `values`
/// (those with weight > 0, when weights are given) to 0.9; 0 if they are all dark.
float auto_exposure(const std::vector<Rgb>& values, const std::vector<float>& weights = {});

/// The result view: I(p) · exposure.
std::vector<VertexColour> result_colours(const std::vector<Rgb>& radiance, float exposure);

/// The target view: painted vertices show Ψ · exposure; "don't care" ones
/// show `backdrop` (display-ready shading that keeps the geometry readable), hatched.
std::vector<VertexColour> target_colours(const std::vector<Rgb>& psi, const std::vector<float>& weight,
                                         const std::vector<Rgb>& backdrop, float exposure);

/// The difference view: |lum(Ψ) − lum(I)| · exposure on a black → blue → red →
/// yellow ramp (yellow = a difference of the display's full white); "don't
/// care" vertices show `backdrop`, hatched.
std::vector<VertexColour> difference_colours(const std::vector<Rgb>& psi, const std::vector<float>& weight,
                                             const std::vector<Rgb>& radiance, const std::vector<Rgb>& backdrop,
                                             float exposure);

/// The heat ramp at t in [0, 1] (clamped).
Rgb heat_colour(float t);

float luminance(const Rgb& c);

} // namespace hilight::painter::ui
