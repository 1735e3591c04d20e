// The solve's whole-answer alternatives (solve/alternative.hpp) and their
// runner, on a scripted context: each solve "from nothing" returns the
// answer the script gives for the light space and the luminaire's turn it
// is asked in, so every verdict, every stage line and every change of the
// light space or the turn is checked against the judge's rules. The real
// solves they make are covered by the recovery tests (open space: the
// product; spot search: the stage; turns: test_luminaire_aim.cpp).
#include "hilight/photometry.hpp"
#include "hilight/solve/alternatives.hpp"
#include "hilight/solve/solve_plans.hpp"

#include <catch2/catch.hpp>
#include <map>

using namespace hilight;

namespace {

/// One scripted answer: its light count and D̄ over the target.
struct Scripted {
  size_t lights = 0;
  double dbar = 0;
};

Lighting lights_of(size_t n) {
  Lighting lights;
  for (size_t i = 0; i < n; ++i) lights.push_back(Light::point({float(i), 1.f, 0.f}, Rgb(1.f)));
  return lights;
}

class ScriptedContext final : public AlternativeContext {
public:
  SolveSettings settings_;
  Judge judge_;
  bool open = false, has_open_sides = true;
  float spin = 0.f;
  std::map<float, Scripted> points_by_spin;  ///< the point solve in the closed space, per turn
  Scripted points_open, spots;
  std::vector<std::string> said;      ///< the progress line
  std::vector<float> turns;           ///< every turn asked for

  const Judge& judge() const override { return judge_; }
  const SolveSettings& settings() const override { return settings_; }
  void stage(const std::string& name) const override { const_cast<ScriptedContext*>(this)->said.push_back(name); }
  Lighting solve_points(SolveReport& report) override {
    const Scripted s = open ? points_open : points_by_spin.at(spin);
    return answer(s, "points", report);
  }
  Lighting solve_spots(double, SolveReport& report) override {
    if (spots.lights == 0) return {};
    return answer(spots, "spots", report);
  }
  bool can_open_space() const override { return !open && has_open_sides; }
  void open_space(bool o) override { open = o; }
  void turn_luminaire(float spin_deg) override {
    spin = spin_deg;
    turns.push_back(spin_deg);
  }

private:
  /// A solve logs its own stage and time, as the plans do.
  static Lighting answer(const Scripted& s, const std::string& what, SolveReport& report) {
    report.dbar = s.dbar;
    report.stages.push_back({what, 0, 1.0, s.dbar, false, true, {}});
    report.seconds[what] += 1;
    return lights_of(s.lights);
  }
};

Answer first_answer(size_t lights, double dbar) {
  Answer a{lights_of(lights), {}};
  a.report.dbar = dbar;
  a.report.stages.push_back({"points", 0, 1.0, dbar, false, true, {}});
  return a;
}

std::vector<std::string> names(const Alternatives& list) {
  std::vector<std::string> n;
  for (const auto& a : list) n.push_back(a->name());
  return n;
}

/// A luminaire whose profile is symmetric in its quadrants: turns 0 and 90 told apart.
Light quadrant_luminaire(float spin) {
  auto profile = std::make_shared<Photometry>();
  profile->symmetry = Photometry::Symmetry::Quadrants;
  Light l = Light::point({0, 2, 0}, Rgb(1.f));
  l.profile = profile;
  l.spin_deg = spin;
  return l;
}

} // namespace

TEST_CASE("alternatives: the list is data, from the settings", "[alternatives]") {
  SolveSettings s;
  CHECK(names(answer_alternatives(s)) == std::vector<std::string>{"open space", "spot search"});
  s.placement.ceiling_offset = 0.1f;  // hung under the ceiling: nothing beyond the open sides
  CHECK(names(answer_alternatives(s)) == std::vector<std::string>{"spot search"});
  s.fixed_count = 3;  // the user's count: no spots instead
  CHECK(answer_alternatives(s).empty());
  SolveSettings lum;
  lum.luminaire = quadrant_luminaire(0.f);  // the designer's luminaire: its turns, no spots
  CHECK(names(answer_alternatives(lum)) == std::vector<std::string>{"luminaire turns", "open space"});
  auto round = std::make_shared<Photometry>();
  round->symmetry = Photometry::Symmetry::Rotational;
  lum.luminaire->profile = round;
  CHECK(names(answer_alternatives(lum)) == std::vector<std::string>{"open space"});  // one turn: nothing to try
}

TEST_CASE("alternatives: a fitting answer logs each alternative's skip with its reason", "[alternatives]") {
  ScriptedContext ctx;
  const Answer kept = run_alternatives(answer_alternatives(ctx.settings_), ctx, first_answer(4, 0.004));
  REQUIRE(kept.report.stages.size() == 3);  // the first solve, then a line for each alternative skipped
  const StageRecord& open = kept.report.stages[1];
  CHECK(open.name == "open space");
  CHECK(open.skipped == "the lights inside fit (D̄ at most open_space_dbar)");
  const StageRecord& skip = kept.report.stages.back();
  CHECK(skip.name == "spot search");
  CHECK(skip.skipped == "the point lights fit (D̄ at most kSpotDbar)");
  for (const StageRecord& s : {open, skip}) {
    CHECK(s.target);
    CHECK_FALSE(s.kept);
    CHECK(s.dbar_before == 0.004);
    CHECK(s.dbar_after == 0.004);
  }
  CHECK(kept.lights.size() == 4);
  CHECK(ctx.said.empty());  // nothing solved again
}

TEST_CASE("alternatives: the open space is kept when it lowers D̄ by a fifth, and the space stays open", "[alternatives]") {
  ScriptedContext ctx;
  ctx.points_open = {2, 0.30 * Judge::kOpenSpaceGain * 0.99};
  const Answer kept = run_alternatives({open_space_alternative()}, ctx, first_answer(3, 0.30));
  CHECK(ctx.open);
  CHECK(kept.lights.size() == 2);
  CHECK(kept.report.open_space);
  CHECK(kept.report.dbar_closed == 0.30);
  REQUIRE(kept.report.stages.size() == 3);  // the first solve, the open solve's own, the verdict
  CHECK(kept.report.stages[1].name == "points");
  CHECK(kept.report.stages[2].name == "open space");
  CHECK(kept.report.stages[2].kept);
  CHECK(kept.report.stages[2].dbar_before == 0.30);
  CHECK(kept.report.stages[2].dbar_after == ctx.points_open.dbar);
  CHECK(ctx.said == std::vector<std::string>{"looking beyond the scene's bounds"});
}

TEST_CASE("alternatives: a near tie stays inside, the space closed again, what the open solve did still logged", "[alternatives]") {
  ScriptedContext ctx;
  ctx.points_open = {2, 0.30 * Judge::kOpenSpaceGain * 1.01};
  const Answer kept = run_alternatives({open_space_alternative()}, ctx, first_answer(3, 0.30));
  CHECK_FALSE(ctx.open);
  CHECK(kept.lights.size() == 3);
  CHECK_FALSE(kept.report.open_space);
  CHECK(kept.report.dbar == 0.30);
  CHECK(kept.report.dbar_closed == 0.30);
  CHECK(kept.report.seconds.at("points") == 1);  // the losing solve's time is carried
  REQUIRE(kept.report.stages.size() == 3);
  CHECK_FALSE(kept.report.stages[2].kept);
  CHECK(kept.report.stages[2].dbar_after == ctx.points_open.dbar);
}

TEST_CASE("alternatives: no open side, or a fitting answer, and the open space is not tried, its skip logged with the reason",
          "[alternatives]") {
  ScriptedContext ctx;
  ctx.has_open_sides = false;
  Answer kept = run_alternatives({open_space_alternative()}, ctx, first_answer(3, 0.30));
  REQUIRE(kept.report.stages.size() == 2);
  CHECK(kept.report.stages[1].skipped == "the space is open already, or the scene has no open side");
  ctx.has_open_sides = true;
  kept = run_alternatives({open_space_alternative()}, ctx, first_answer(3, ctx.settings_.open_space_dbar));
  REQUIRE(kept.report.stages.size() == 2);
  CHECK(kept.report.stages[1].skipped == "the lights inside fit (D̄ at most open_space_dbar)");
  CHECK_FALSE(kept.report.stages[1].kept);
  CHECK(ctx.said.empty());
}

TEST_CASE("alternatives: spots win by the judge's eq. 9 and none found leaves D̄ as it was", "[alternatives]") {
  ScriptedContext ctx;
  SECTION("fewer spots, D̄ not ε_impro worse") {
    ctx.spots = {2, 0.31};
    const Answer kept = run_alternatives({spot_search_alternative()}, ctx, first_answer(4, 0.30));
    CHECK(kept.lights.size() == 2);
    CHECK(kept.report.stages.back().kept);
    CHECK(kept.report.stages.back().dbar_after == 0.31);
  }
  SECTION("more spots that do not pay") {
    ctx.spots = {5, 0.25};
    const Answer kept = run_alternatives({spot_search_alternative()}, ctx, first_answer(4, 0.30));
    CHECK(kept.lights.size() == 4);
    CHECK_FALSE(kept.report.stages.back().kept);
  }
  SECTION("no spot helps") {
    const Answer kept = run_alternatives({spot_search_alternative()}, ctx, first_answer(4, 0.30));
    CHECK(kept.lights.size() == 4);
    REQUIRE(kept.report.stages.size() == 2);
    CHECK(kept.report.stages.back().name == "spot search");
    CHECK(kept.report.stages.back().dbar_after == 0.30);
    CHECK_FALSE(kept.report.stages.back().kept);
  }
}

TEST_CASE("alternatives: the luminaire's turns each compete with the best so far, and the best turn stays", "[alternatives]") {
  ScriptedContext ctx;
  Light luminaire = quadrant_luminaire(30.f);
  luminaire.profile = std::make_shared<Photometry>();  // no symmetry: 0, 90, 180, 270
  ctx.settings_.luminaire = luminaire;
  ctx.spin = 30.f;
  ctx.points_by_spin = {{120.f, {2, 0.20}}, {210.f, {2, 0.02}}, {300.f, {2, 0.05}}};
  const Alternatives list = answer_alternatives(ctx.settings_);
  REQUIRE(names(list).front() == "luminaire turns");
  const Answer kept = run_alternatives({list.front()}, ctx, first_answer(2, 0.10));
  CHECK(ctx.spin == 210.f);
  CHECK(kept.report.dbar == 0.02);
  std::vector<std::pair<std::string, bool>> lines;
  for (const auto& st : kept.report.stages)
    if (st.target) lines.push_back({st.name, st.kept});
  CHECK(lines == std::vector<std::pair<std::string, bool>>{{"luminaire turned 90°", false}, {"luminaire turned 180°", true},
                                                           {"luminaire turned 270°", false}});
  SECTION("an answer that fits tries no turn") {
    ScriptedContext fits;
    fits.settings_.luminaire = luminaire;
    const Answer same = run_alternatives(answer_alternatives(fits.settings_), fits, first_answer(2, Judge::kTurnDbar));
    REQUIRE(same.report.stages.size() == 3);  // the first solve, the turns' skip, the open space's skip
    CHECK(same.report.stages[1].name == "luminaire turns");
    CHECK(same.report.stages[1].skipped == "the template's turn fits (D̄ at most kTurnDbar)");
    CHECK(fits.turns.empty());
  }
}
