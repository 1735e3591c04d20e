#pragma once
// What the Solver's translation units share (solver.cpp orchestrates;
// refine/solver_polish.cpp and refine/solver_count_edits.cpp refine and
// edit the count): its thresholds and a stopwatch. Not installed.
#include <chrono>

namespace hilight::solver_detail {

/// D̄ below which a light more is noise-fitting, not a missing lamp: the same
/// order as ε_w (a light worth keeping explains 5% of ‖Ψ‖), and invisible.
constexpr double kVisibleDbar = 5e-3;
/// D̄ above which point lights (all the count rule would add) leave the
/// target to spotlights (issue 10 §3), and how many at most. Point lights
/// leave a stage's pools at 24–65%; a renderer's own floor (ism-vulkan's
/// bounce, 2–4%) or the far lights of a product (2–4%) must not start a
/// spot search that cannot pay.
constexpr double kSpotDbar = 0.05;
constexpr int kMaxSpots = 4;
/// D̄ at the samples above which a light is tried split in two: a fit this
/// poor is missing a lamp; below it, a light more mostly fits the remaining
/// error of far or bounce-lit lights (the product sweep: 20 of 20 at 1%, 19
/// at 0.5%).
constexpr double kSplitDbar = 0.01;
/// D̄ above which a solve with an asymmetric luminaire tries the template
/// turned to its other spins (a whole solve each): a fit this poor may be a
/// wrong turn (a luminaire turned 90° from the template: 33%); below it the
/// turn is right, and each light's own turn is still chosen afterwards.
constexpr double kTurnDbar = 0.01;
/// D̄ at the samples below which fine-tune's polish is not settled further:
/// lights that produce the target stay where they are (and a direct-light
/// polish gets there itself).
constexpr double kSettledDbar = 1e-4;
/// D̄ above which a solve looks for the cause (unreachable painted light).
constexpr double kPoorFitDbar = 0.05;

class Stopwatch {
public:
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count(); }

private:
  std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

} // namespace hilight::solver_detail
