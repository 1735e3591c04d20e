#pragma once
// The Solve and Placement panels' state, and the stroke → fine-tune → display
// latency they report.
#include "hilight/named_room.hpp"

#include <chrono>
#include <optional>
#include <vector>

namespace hilight::painter {

struct SolvePanelState {
  int cut_k = 0;
  char place_text[256] = {};  ///< the placement rules being edited
  /// The scene's named rooms (region:NAME), read on the first rule that names one.
  std::optional<std::vector<NamedRoom>> named_rooms;
  std::optional<std::chrono::steady_clock::time_point> stroke_released;
  bool fine_tune_after_stroke = false;
  bool fine_tune_queued = false;  ///< a stroke ended while a job ran
  bool stroke_shown = false;      ///< its lights are on screen (a quick stage so far)
};

} // namespace hilight::painter
