// The Judge (solve/judge.hpp) on tables of D̄: eq. 9 forward and backward,
// eq. 6's share, the visibility floor, spots against point lights, the
// count bounds, and the thresholds where the solve changes course.
#include "hilight/solve/judge.hpp"

#include <catch2/catch.hpp>

using namespace hilight;

namespace {
struct PaysRow {
  double without, with;
  bool ratio, more;
};
struct FewerRow {
  double with, without;
  bool fewer;
};
} // namespace

TEST_CASE("judge: one more light pays by the ratio or by eps_w's share", "[judge]") {
  const Judge judge;  // ε_impro 1.6, ε_w 5%
  const PaysRow rows[] = {
      {0.2, 0.125, true, true},     // exactly ε_impro (1.6 · 0.125 = 0.2 in doubles): pays
      {0.159, 0.10, false, true},   // ratio just short, but 5.9% of ‖Ψ‖ taken off ≥ ε_w
      {0.30, 0.24, false, true},    // ratio 1.25, but 6% of ‖Ψ‖ taken off: several lamps missing
      {0.30, 0.26, false, false},   // ratio 1.15, 4%: neither
      {0.02, 0.01, true, true},     // ratio 2
      {0.10, 0.10, false, false},   // no change
      {0.10, 0.12, false, false},   // worse
  };
  for (const auto& r : rows) {
    INFO("without " << r.without << ", with " << r.with);
    CHECK(judge.ratio_pays(r.without, r.with) == r.ratio);
    CHECK(judge.light_more_pays(r.without, r.with) == r.more);
  }
}

TEST_CASE("judge: one light fewer will do while D-bar grows by at most eps_impro, a tie to the fewer", "[judge]") {
  const Judge judge;
  const FewerRow rows[] = {
      {0.125, 0.2, true},     // exactly ε_impro: the fewer lights
      {0.125, 0.201, false},  // a hair more: the light pays
      {0.10, 0.10, true},    // no change
      {0.10, 0.05, true},    // fewer is better
      {0.0, 0.0, true},      // both perfect
      {0.0, 1e-9, false},    // a perfect fit against any error
  };
  for (const auto& r : rows) {
    INFO("with " << r.with << ", without " << r.without);
    CHECK(judge.fewer_will_do(r.with, r.without) == r.fewer);
  }
}

TEST_CASE("judge: eps_impro and eps_w come from the settings", "[judge]") {
  JudgeSettings s;
  s.eps_impro = 2.0;
  s.eps_w = 0.01;
  const Judge judge(s);
  CHECK_FALSE(judge.ratio_pays(0.19, 0.10));
  CHECK(judge.ratio_pays(0.20, 0.10));
  CHECK(judge.light_more_pays(0.12, 0.10));  // 2% of ‖Ψ‖ ≥ ε_w 1%
  CHECK_FALSE(judge.light_more_pays(0.105, 0.10));
  CHECK(judge.fewer_will_do(0.10, 0.20));
  CHECK(judge.weak(0.009, 1.0));
  CHECK_FALSE(judge.weak(0.01, 1.0));
}

TEST_CASE("judge: no light more at or below the visible D-bar", "[judge]") {
  const Judge judge;
  CHECK(judge.light_more_visible(0.006));
  CHECK_FALSE(judge.light_more_visible(kVisibleDbar));
  CHECK_FALSE(judge.light_more_visible(0.001));
  JudgeSettings s;
  s.visible_dbar = 0;
  CHECK(Judge(s).light_more_visible(1e-9));
}

TEST_CASE("judge: spots against point lights", "[judge]") {
  const Judge judge;
  struct Row {
    size_t n_spots;
    double d_spots;
    size_t n_points;
    double d_points;
    bool spots;
  };
  const Row rows[] = {
      {0, 0.0, 3, 0.3, false},   // no spot found
      {3, 0.10, 3, 0.12, true},  // same count, lower D̄
      {3, 0.12, 3, 0.12, false}, // same count, no better
      {2, 0.15, 3, 0.10, true},  // fewer, within ε_impro (0.15 < 0.16)
      {2, 0.2, 3, 0.125, false}, // fewer, exactly ε_impro worse: the points stay
      {4, 0.06, 3, 0.10, true},  // more, and they pay (0.10 ≥ 1.6·0.06)
      {4, 0.07, 3, 0.10, false}, // more, and they do not
  };
  for (const auto& r : rows) {
    INFO(r.n_spots << " spots at " << r.d_spots << " against " << r.n_points << " points at " << r.d_points);
    CHECK(judge.spots_win(r.n_spots, r.d_spots, r.n_points, r.d_points) == r.spots);
  }
  JudgeSettings s;
  s.max_count = 3;
  CHECK_FALSE(Judge(s).spots_win(4, 0.01, 3, 0.10));  // out of count:MIN:MAX
  s.max_count = 0;
  s.min_count = 3;
  CHECK_FALSE(Judge(s).spots_win(2, 0.01, 3, 0.10));
}

TEST_CASE("judge: the count bounds and the spots' cap", "[judge]") {
  JudgeSettings s;
  CHECK(Judge(s).max_spots() == Judge::kMaxSpots);
  s.max_count = 2;
  CHECK(Judge(s).max_spots() == 2);
  CHECK(Judge(s).count_allowed(2));
  CHECK_FALSE(Judge(s).count_allowed(3));
  s.fixed_count = 5;  // --lights N overrides count:MIN:MAX
  const Judge fixed(s);
  CHECK(fixed.count_fixed());
  CHECK(fixed.min_lights() == 5);
  CHECK(fixed.max_lights() == 5);
  const Judge hierarchy = fixed.for_leaves(3);  // the seeding found 3: every one taken
  CHECK(hierarchy.count_fixed());
  CHECK(hierarchy.min_lights() == 3);
  CHECK(hierarchy.settings().visible_dbar == kVisibleDbar);
  s.fixed_count = 0;
  s.min_count = 4;  // count:4:6 over 3 seeded lights: the cuts take all 3
  s.max_count = 6;
  CHECK(Judge(s).for_leaves(3).min_lights() == 3);
  CHECK(Judge(s).for_leaves(3).max_lights() == 6);
}

TEST_CASE("judge: where the solve changes course", "[judge]") {
  const Judge judge;
  CHECK(judge.poor_fit(0.051));
  CHECK_FALSE(judge.poor_fit(Judge::kPoorFitDbar));
  CHECK(judge.look_for_spots(0.06));
  CHECK_FALSE(judge.look_for_spots(0.04));
  // The two splits keep their own thresholds: a point light from 1%, a spot from 2%.
  CHECK(judge.split_lamps(0.015));
  CHECK_FALSE(judge.split_spots(0.015));
  CHECK(judge.split_spots(0.021));
  CHECK(judge.try_turns(0.02));
  CHECK_FALSE(judge.try_turns(0.01));
  CHECK(judge.settled(1e-4));
  CHECK_FALSE(judge.settled(2e-4));
  CHECK_FALSE(judge.add_residual_samples(0.002, 0.001));  // invisible
  CHECK_FALSE(judge.add_residual_samples(0.010, 0.009));  // the samples saw it
  CHECK(judge.add_residual_samples(0.010, 0.005));
  CHECK(judge.open_space_wins(0.099, 0.125));
  CHECK_FALSE(judge.open_space_wins(0.1, 0.125));  // exactly a fifth lower (0.8 · 0.125 = 0.1): stays inside
}
