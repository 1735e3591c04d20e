#pragma once
/// What a solve's result needs said to the user, and why (issue 36): a light
/// count it could not reach, a poor fit and its cause, a building default
/// that may be the cause. One wording for `hilight solve` (stderr) and
/// `hilight paint` (its Solve panel).
#include "hilight/solve/solver.hpp"

#include <string>
#include <vector>

namespace hilight {

struct FitNote {
  bool warning = true;  ///< a warning ("hilight: warning: ..."), else advice
  std::string text;     ///< one sentence, no prefix
};

/// What the fit was asked for, beyond the report.
struct FitAsked {
  size_t lights = 0;              ///< --lights N (0: the solve decides)
  bool building_default = false;  ///< the lights were held on the ceiling by a building's default
};

/// The notes for `report` (empty for a good fit at the count asked).
std::vector<FitNote> fit_notes(const SolveReport& report, const FitAsked& asked);

} // namespace hilight
