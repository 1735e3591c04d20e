#pragma once
// What the solve's translation units share (solver.cpp, move.cpp and the
// moves in moves/): a stopwatch and the progress line. Every threshold is
// the Judge's (hilight/solve/judge.hpp). Not installed.
#include "hilight/solve/solver.hpp"
#include "hilight/solve/stoppable_renderer.hpp"

#include <chrono>
#include <stop_token>
#include <string>

namespace hilight::solver_detail {

class Stopwatch {
public:
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count(); }

private:
  std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

/// Says `name` on the progress line; SolveCancelled once `stop` is requested.
inline void announce_stage(const std::stop_token& stop, const ProgressFn& progress, const std::string& name) {
  if (stop.stop_requested()) throw SolveCancelled();
  if (progress) progress(name);
}

} // namespace hilight::solver_detail
