#pragma once
/// Paper §4.1, brightness/colour adjustment: the designer marks a region and
/// asks it brighter, darker or tinted; only the lights able to light that
/// region change, so the rest of the scene keeps its lighting (lights that
/// cast shadows on the region do not reach it and keep their intensity).
///
/// A light "lights the region" when its share of the region's current
/// illumination (from the renderer's per-light responses, shadows and bounce
/// included) is at least `min_share`. Those lights' intensities are
/// multiplied per channel; the region's target becomes its current target
/// (or, where nothing was painted, the current illumination) plus the change
/// those lights make there, and is marked as cared for (weight ≥ 1). Lights
/// and target change in one undo step.
#include "core/document.hpp"
#include "hilight/renderer.hpp"

#include <cstdint>
#include <vector>

namespace hilight::painter {

struct RegionAdjustSettings {
  Rgb multiplier{1.f};     ///< per channel: 1.2 = 20% brighter, (1, 0.9, 0.8) = warmer
  double min_share = 0.1;  ///< a light's least share of the region's light to be changed
};

struct RegionAdjustResult {
  std::vector<size_t> changed_lights;  ///< indices into the lights
  std::vector<double> shares;          ///< every light's share of the region's light
};

/// Applies the adjustment to `document` (one step labelled "adjust region").
/// `renderer` must be bound to the document's scene and not in use elsewhere
/// (SolveJob::renderer() while no job runs). InputError for an empty region
/// or a region no light reaches.
RegionAdjustResult adjust_region(Document& document, Renderer& renderer, const std::vector<uint32_t>& region,
                                 const RegionAdjustSettings& settings);

} // namespace hilight::painter
