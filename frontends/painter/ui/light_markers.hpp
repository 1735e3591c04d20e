#pragma once
/// Overlay geometry for the painter's objects: lights (spotlights with their
/// cone), spot hints, the shadow tool's candidates (paper Fig. 5) and a
/// selected object's box.
#include "core/shadow_candidates.hpp"
#include "hilight/lighting.hpp"
#include "ui/line_batch.hpp"

namespace hilight::painter::ui {

/// A dot per light in its colour (brightest channel = 1) with a dark rim;
/// spotlights add their axis and cone, drawn `diagonal`/8 long.
void add_light_markers(LineBatch& lines, const Lighting& lights, float diagonal);
/// The spotlights the designer asked for, as orange cone outlines.
void add_spot_hint_markers(LineBatch& lines, const Lighting& hints, float diagonal);
/// Candidates that cast each requested shadow (yellow), those inside the cone
/// (blue), the cone's axis, and the lights estimated from them (white).
void add_shadow_estimate_markers(LineBatch& lines, const ShadowEstimate& estimate);
/// The 12 edges of a box.
void add_box_marker(LineBatch& lines, const Bounds& box, const glm::vec4& colour);

} // namespace hilight::painter::ui
