#pragma once
// What the solve's translation units share (solver.cpp, move.cpp and the
// moves in moves/): a stopwatch. Every threshold is the Judge's
// (hilight/solve/judge.hpp). Not installed.
#include <chrono>

namespace hilight::solver_detail {

class Stopwatch {
public:
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count(); }

private:
  std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

} // namespace hilight::solver_detail
