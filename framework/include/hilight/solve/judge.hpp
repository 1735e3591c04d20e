#pragma once
/// The one judge of the solve: eq. 9 of the paper ("one more light pays"),
/// eq. 6's weak light, and every D̄ threshold at which the solve changes
/// course. Every move asks the judge; no move keeps a threshold of its own,
/// so a value changed here changes it everywhere (tests/test_judge.cpp).

#include <algorithm>
#include <cstddef>

namespace hilight {

/// D̄ below which a light more is noise-fitting, not a missing lamp: the
/// same order as ε_w (a light worth keeping explains 5% of ‖Ψ‖), and
/// invisible. A ratio of two tiny D̄s says nothing.
constexpr double kVisibleDbar = 5e-3;

struct JudgeSettings {
  double eps_impro = 1.6;    ///< ε_impro of eq. 9 (--eps-impro)
  double eps_w = 0.05;       ///< ε_w of eq. 6 (--weak-threshold): a light worth keeping explains this share of ‖Ψ‖
  double eps_opt = 0.15;     ///< ε_opt: cuts below this D̄ are worth refining (--eps-opt)
  size_t n_cut = 4;          ///< N_cut: cuts refined (--n-cut)
  size_t fixed_count = 0;    ///< --lights N (0: automatic)
  size_t min_count = 0, max_count = 0;  ///< count:MIN:MAX of --place (0: none)
  double visible_dbar = kVisibleDbar;   ///< no light more is taken at or below this D̄ (tables may set 0)
};

class Judge {
public:
  // ---- D̄ thresholds: each a point where the solve changes course. ----

  /// D̄ above which point lights (all the count rule would add) leave the
  /// target to spotlights (issue 10 §3). Point lights leave a stage's pools
  /// at 24–65%; a renderer's own floor (ism-vulkan's bounce, 2–4%) or the
  /// far lights of a product (2–4%) must not start a spot search that
  /// cannot pay.
  static constexpr double kSpotDbar = 0.05;
  /// Spots the search proposes at most (a stage rig: 1–3).
  static constexpr size_t kMaxSpots = 4;
  /// D̄ at the samples above which a point light is tried split in two: a
  /// fit this poor is missing a lamp; below it, a light more mostly fits
  /// the remaining error of far or bounce-lit lights (the product sweep: 20
  /// of 20 at 1%, 19 at 0.5%).
  static constexpr double kSplitLampDbar = 0.01;
  /// D̄ at the samples up to which a poor point fit is taken as one lamp's
  /// light missing (a downlight's pool among lamps: 3–6% in the home); above
  /// it the points miss far more (a stage of spots: 23–36%, a product lit
  /// from outside seen from inside: 25–32%) and the whole-answer
  /// alternatives look (the open space, the spot search).
  static constexpr double kMissingLampDbar = 0.10;
  /// D̄ above which, once the spot set is built, each spot is tried as two.
  /// Not kSplitLampDbar (issue 33 found the two "kept twice"): they judge
  /// different moves and both values are measured. A spot is refined with a
  /// bounce estimate that is itself ~1–2% off while the set is built, so
  /// below 2% a split fits the estimate, not a second pool (the stage sweep
  /// was tuned at 2%); the point lights' split is judged on the exact
  /// model and pays from 1%.
  static constexpr double kSplitSpotDbar = 0.02;
  /// D̄ above which a solve with an asymmetric luminaire tries the template
  /// turned to its other spins (a whole solve each): a fit this poor may be
  /// a wrong turn (a luminaire turned 90° from the template: 33%); below it
  /// the turn is right, and each light's own turn is still chosen after.
  static constexpr double kTurnDbar = 0.01;
  /// D̄ at the samples below which fine-tune's polish is not settled further,
  /// and below which the reference polish stops: lights that produce the
  /// target stay where they are, and nothing is left anyone could see.
  static constexpr double kSettledDbar = 1e-4;
  /// D̄ of the result above which it is a poor fit: the CLI warns (and the
  /// report's poor_fit), and the solve looks for the cause (unreachable
  /// painted light). One value for both, so the warning and the diagnosis
  /// never disagree (the CLI's kPoorFit was a copy of the same 5%).
  static constexpr double kPoorFitDbar = 0.05;
  /// D̄ over every target point below which no residual samples are added:
  /// nothing a designer would see.
  static constexpr double kResidualDbar = 2e-3;
  /// ...nor while the whole target's D̄ is within this factor of the samples':
  /// the samples saw what matters (an infeasible target stays infeasible).
  static constexpr double kResidualOverSamples = 1.25;
  /// The open space's answer replaces the closed one when its D̄ is below
  /// this share of it ("lowers D̄ by a fifth"): a larger box coarsens the
  /// seeding and the cache, so a near tie stays inside.
  static constexpr double kOpenSpaceGain = 0.8;

  Judge() = default;
  explicit Judge(const JudgeSettings& settings) : m_settings(settings) {}
  const JudgeSettings& settings() const { return m_settings; }
  double eps_impro() const { return m_settings.eps_impro; }
  double eps_w() const { return m_settings.eps_w; }

  // ---- Eq. 9: the count. `without`/`with`: D̄ without and with the light. ----

  /// The ratio clause alone: the light more improves D̄ by ε_impro.
  bool ratio_pays(double without, double with) const { return without >= m_settings.eps_impro * with; }
  /// One more light pays: the ratio clause, or eq. 6's measure — it takes at
  /// least ε_w of ‖Ψ‖ off the residual (with several lamps missing each
  /// explains only its share, and no single one improves D̄ by ε_impro).
  bool light_more_pays(double without, double with) const {
    return ratio_pays(without, with) || without - with >= m_settings.eps_w;
  }
  /// One light fewer will do: D̄ grows by no more than ε_impro. A tie goes
  /// to the fewer (simpler) lights, so a rounding difference never decides.
  bool fewer_will_do(double with, double without) const { return without <= m_settings.eps_impro * with; }
  /// A D̄ at which a light more may still be a lamp (above visible_dbar).
  bool light_more_visible(double dbar) const { return dbar > m_settings.visible_dbar; }

  /// Spots (D̄ `d_spots`, `n_spots` lights) replace point lights (`d_points`,
  /// `n_points`): the same count and a lower D̄; fewer lights and a D̄ not
  /// ε_impro worse; more lights that pay by ε_impro. And within the count bounds.
  bool spots_win(size_t n_spots, double d_spots, size_t n_points, double d_points) const;

  // ---- The count bounds (--lights N, count:MIN:MAX). ----
  size_t min_lights() const { return m_settings.fixed_count ? m_settings.fixed_count : m_settings.min_count; }
  size_t max_lights() const { return m_settings.fixed_count ? m_settings.fixed_count : m_settings.max_count; }
  bool count_fixed() const { return m_settings.fixed_count != 0; }
  bool count_allowed(size_t n) const { return n >= min_lights() && (max_lights() == 0 || n <= max_lights()); }
  /// Spots the search may propose: kMaxSpots within the count bound.
  size_t max_spots() const;
  /// `k` within the count bounds (count:MIN:MAX).
  size_t clamp_count(size_t k) const {
    if (min_lights()) k = std::max(k, min_lights());
    if (max_lights()) k = std::min(k, max_lights());
    return k;
  }
  /// ε_opt and N_cut: which cuts of the hierarchy are refined (cuts.hpp).
  double eps_opt() const { return m_settings.eps_opt; }
  size_t n_cut() const { return m_settings.n_cut; }
  /// This judge for a hierarchy of `leaves` point lights, as the cuts
  /// (cuts.hpp) ask it: a count the seeding cannot reach (--lights N,
  /// count:MIN) takes every seeded light; the add-missing move adds the rest.
  Judge for_leaves(size_t leaves) const;

  // ---- Eq. 6: the weak light. ----
  /// A light whose contribution ‖φ_j l_j‖ is under ε_w of ‖Ψ‖ is weak.
  bool weak(double contribution, double target_norm) const { return contribution < m_settings.eps_w * target_norm; }

  // ---- Where the solve changes course. ----
  bool poor_fit(double dbar) const { return dbar > kPoorFitDbar; }
  bool look_for_spots(double dbar) const { return dbar > kSpotDbar; }
  bool split_lamps(double dbar) const { return dbar > kSplitLampDbar; }
  bool one_lamp_missing(double dbar) const { return dbar <= kMissingLampDbar; }
  bool split_spots(double dbar) const { return dbar > kSplitSpotDbar; }
  bool try_turns(double dbar) const { return dbar > kTurnDbar; }
  bool settled(double dbar) const { return dbar <= kSettledDbar; }
  bool add_residual_samples(double dbar_points, double dbar_samples) const {
    return dbar_points > kResidualDbar && dbar_points > kResidualOverSamples * dbar_samples;
  }
  bool open_space_wins(double d_open, double d_closed) const { return d_open < kOpenSpaceGain * d_closed; }

private:
  JudgeSettings m_settings;
};

} // namespace hilight
