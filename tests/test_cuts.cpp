// The cut choice and the count walk (solve/cuts.cpp) on tables of D̄:
// eq. 9's improvement ratio, the walk down, the knee when no cut is good,
// the floor below which no light is added, and --lights N.
#include "hilight/solve/cuts.hpp"

#include <catch2/catch.hpp>
#include <map>

using namespace hilight;

namespace {
/// A refine callback over a table of refined D̄s that records what it refined.
struct Refiner {
  std::map<size_t, double> table;
  std::vector<size_t> asked;
  std::function<double(size_t)> fn() {
    return [this](size_t k) {
      asked.push_back(k);
      return table.at(k);
    };
  }
};
} // namespace

TEST_CASE("cuts: the first N_cut cuts below eps_opt are chosen", "[cuts]") {
  JudgeSettings rule;
  CHECK(choose_cuts({0.9, 0.5, 0.14, 0.1, 0.09, 0.08, 0.07}, Judge(rule)) == std::vector<size_t>{3, 4, 5, 6});
  rule.n_cut = 2;
  CHECK(choose_cuts({0.9, 0.5, 0.14, 0.1, 0.09}, Judge(rule)) == std::vector<size_t>{3, 4});
}

TEST_CASE("cuts: with no cut below eps_opt the choice starts at the knee", "[cuts]") {
  JudgeSettings rule;
  // Best 0.25 at 11 lights; within 1.6x of it (0.40) first at 4 lights.
  const std::vector<double> initial = {0.97, 0.61, 0.41, 0.35, 0.32, 0.30, 0.28, 0.27, 0.26, 0.257, 0.25, 0.252};
  CHECK(choose_cuts(initial, Judge(rule)) == std::vector<size_t>{4, 5, 6, 7});
}

TEST_CASE("cuts: --lights N chooses exactly that cut and walks nowhere", "[cuts]") {
  JudgeSettings rule;
  rule.fixed_count = 2;
  const std::vector<double> initial = {0.5, 0.1, 0.01};
  const auto chosen = choose_cuts(initial, Judge(rule));
  REQUIRE(chosen == std::vector<size_t>{2});
  CHECK(first_neighbour(initial, chosen, Judge(rule)) == FirstNeighbour::None);
  Refiner r{{{2, 0.08}}, {}};
  CHECK(walk_count(initial, chosen, Judge(rule), r.fn()) == 2);
  CHECK(r.asked == std::vector<size_t>{2});
}

TEST_CASE("cuts: the walk goes up while a light more improves D-bar by eps_impro", "[cuts]") {
  JudgeSettings rule;
  const std::vector<double> initial = {0.6, 0.4, 0.12, 0.11, 0.10};
  const auto chosen = choose_cuts(initial, Judge(rule));
  REQUIRE(chosen == std::vector<size_t>{3, 4, 5});
  CHECK(first_neighbour(initial, chosen, Judge(rule)) == FirstNeighbour::Above);
  Refiner r{{{3, 0.05}, {4, 0.01}, {5, 0.008}}, {}};
  CHECK(walk_count(initial, chosen, Judge(rule), r.fn()) == 4);  // 0.05/0.01 = 5 >= 1.6; 0.01/0.008 < 1.6
}

TEST_CASE("cuts: the walk goes down to a smaller cut that refines as well", "[cuts]") {
  JudgeSettings rule;
  // Cut 2 is above eps_opt before refinement but below eps_impro*eps_opt = 0.24.
  const std::vector<double> initial = {0.6, 0.2, 0.1, 0.09};
  const auto chosen = choose_cuts(initial, Judge(rule));
  REQUIRE(chosen.front() == 3);
  CHECK(first_neighbour(initial, chosen, Judge(rule)) == FirstNeighbour::Below);
  Refiner r{{{2, 0.004}, {3, 0.0035}, {4, 0.003}}, {}};
  CHECK(walk_count(initial, chosen, Judge(rule), r.fn()) == 2);  // 0.004/0.0035 < 1.6
}

TEST_CASE("cuts: no light is added once D-bar is below the visible floor", "[cuts]") {
  JudgeSettings rule;
  const std::vector<double> initial = {0.6, 0.1, 0.05};
  Refiner r{{{2, 0.001}, {3, 0.0001}}, {}};  // a ratio of 10, but of invisible D̄s
  CHECK(walk_count(initial, choose_cuts(initial, Judge(rule)), Judge(rule), r.fn()) == 2);
  rule.visible_dbar = 0;
  Refiner again{{{2, 0.001}, {3, 0.0001}}, {}};
  CHECK(walk_count(initial, choose_cuts(initial, Judge(rule)), Judge(rule), again.fn()) == 3);
}

TEST_CASE("cuts: the walk refines only the cuts it needs", "[cuts]") {
  JudgeSettings rule;
  const std::vector<double> initial = {0.5, 0.1, 0.09, 0.08, 0.07};
  Refiner r{{{2, 0.05}, {3, 0.045}, {4, 0.04}, {5, 0.03}}, {}};
  CHECK(walk_count(initial, choose_cuts(initial, Judge(rule)), Judge(rule), r.fn()) == 2);
  for (size_t k : r.asked) CHECK(k <= 3);
}
