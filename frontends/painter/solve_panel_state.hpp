#pragma once
// The Solve and Placement panels' state, and the stroke → fine-tune → display
// latency they report.
#include "hilight/named_room.hpp"
#include "hilight/solve/fit_notes.hpp"

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace hilight::painter {

struct SolvePanelState {
  int cut_k = 0;
  char place_text[256] = {};  ///< the placement rules being edited
  /// The scene's named rooms (region:NAME), read on the first rule that names one.
  std::optional<std::vector<NamedRoom>> named_rooms;
  /// The building default's note (cli::apply_building_default) for the
  /// rules `noted_rules` describes: shown while the job's rules are those.
  std::string building_note, noted_rules;
  /// Why the last Apply was refused (a bad rule, a region that is not a
  /// room); "" after one that took.
  std::string place_error;
  std::optional<std::chrono::steady_clock::time_point> stroke_released;
  bool fine_tune_after_stroke = false;
  bool fine_tune_queued = false;  ///< a stroke ended while a job ran
  bool stroke_shown = false;      ///< its lights are on screen (a quick stage so far)
  /// The last job's answer as the panel says it ("solve: 1 light, D̄ 75.0%"),
  /// and what `hilight solve` would warn of it (fit_notes.hpp); "" before one.
  std::string fit_line;
  std::vector<FitNote> fit_notes;
};

} // namespace hilight::painter
