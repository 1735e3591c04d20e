#include "hilight/solve/fit_notes.hpp"

#include "hilight/solve/judge.hpp"

#include <cstdio>

namespace hilight {

namespace {

template <typename... Args>
std::string format(const char* pattern, Args... args) {
  char text[512];
  std::snprintf(text, sizeof text, pattern, args...);
  return text;
}

} // namespace

std::vector<FitNote> fit_notes(const SolveReport& report, const FitAsked& asked) {
  std::vector<FitNote> notes;
  const char* plural = report.chosen == 1 ? "" : "s";
  // A count the solve could not reach is said, and why (issue 35): no free
  // place was left where one more light changes the fit.
  if (asked.lights > 0 && report.chosen < asked.lights)
    notes.push_back({true, format("--lights %zu: the solve placed %zu: no place was left in the scene where one more light "
                                  "changes the fit (D̄ %.2f%%)",
                                  asked.lights, report.chosen, 100.0 * report.dbar)});
  const bool poor = report.dbar > Judge::kPoorFitDbar;
  if (poor && report.unreachable >= 0.1)
    notes.push_back({true, format("poor fit, D̄ %.1f%% with %zu light%s: %.0f%% of the target's light is on points that no "
                                  "place a light may stand can see (inside solids, or shut off by the --place rules)",
                                  100.0 * report.dbar, report.chosen, plural, 100.0 * report.unreachable)});
  else if (poor)
    notes.push_back({true, format("poor fit, D̄ %.1f%% with %zu light%s: parts of the target may be unreachable by any "
                                  "light, or need another light count (--lights N) or spotlight hints (--spot-hints)",
                                  100.0 * report.dbar, report.chosen, plural)});
  // A poor fit under the building default may be the default's doing: say how to lift it.
  if (poor && asked.building_default)
    notes.push_back({false, "the lights were held on the ceiling (a building's default): if the target's lamps hang lower, "
                            "--place anywhere frees them"});
  return notes;
}

} // namespace hilight
