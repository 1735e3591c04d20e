#pragma once
// What the view shows and how (the View panel, keys 1/2/3): the view mode,
// exposure, the illumination shown and whether it is current.
#include "hilight/lighting.hpp"
#include "ui/vertex_colours.hpp"

#include <optional>
#include <string>
#include <vector>

namespace hilight::painter {

struct DisplayState {
  ui::ViewMode view = ui::ViewMode::Result;
  float exposure = 0.f;               ///< 0 until first set automatically
  bool exposure_from_result = false;  ///< set from a lit result (else from the target, or not yet)
  float exposure_stops = 0.f;         ///< the user's adjustment
  bool show_lights = true;
  std::vector<Rgb> radiance;          ///< I(p) of radiance_lights, per vertex
  bool radiance_final = false;        ///< from the exact display stage
  Lighting radiance_lights;
  bool illumination_pending = false;
  uint64_t colours_revision = 0;
  std::optional<Lighting> requested_lights;  ///< what the illumination worker was last asked for
  bool colours_dirty = true;
  /// A poor fit's painted vertices that no allowed place sees: hatched in
  /// every view until the next job's answer.
  std::vector<uint32_t> unreachable;
  std::string last_activity = "idle";  ///< what the last frame did (for --timings)
};

} // namespace hilight::painter
