// The luminaire's turns: an asymmetric luminaire (--luminaire) whose answer
// fits poorly may be turned wrong (a luminaire turned 90° from the
// template: D̄ 33%). The whole point solve again with the template turned to
// each spin its profile tells apart; the lowest D̄ keeps its turn. Each
// light's own turn is still chosen after (the luminaire aim plan).
#include "hilight/solve/alternatives.hpp"

#include "hilight/photometry.hpp"

#include <cmath>

namespace hilight {

namespace {

class LuminaireTurns final : public Alternative {
public:
  explicit LuminaireTurns(const Light& luminaire) : m_base(luminaire.spin_deg), m_best(luminaire.spin_deg) {
    for (float spin : distinct_spins(*luminaire.profile))
      if (spin != 0.f) m_spins.push_back(spin);  // the template's own turn is the answer so far
  }
  std::string name() const override { return "luminaire turns"; }
  std::string premise_fails(const AlternativeContext& ctx, const Answer& current) const override {
    return ctx.judge().try_turns(current.report.dbar) ? "" : "the template's turn fits (D̄ at most kTurnDbar)";
  }
  std::vector<std::string> candidates() const override {
    std::vector<std::string> names;
    for (float spin : m_spins) names.push_back("luminaire turned " + std::to_string(int(spin)) + "°");
    return names;
  }
  Lighting propose(AlternativeContext& ctx, const Answer&, size_t i, SolveReport& report) override {
    ctx.stage("solving with the luminaire turned " + std::to_string(int(m_spins[i])) + "°");
    m_turned = std::fmod(m_base + m_spins[i], 360.f);
    ctx.turn_luminaire(m_turned);
    return ctx.solve_points(report);
  }
  bool wins(const Judge&, const Answer& candidate, const Answer& current) const override {
    return candidate.report.dbar < current.report.dbar;
  }
  void kept(AlternativeContext&, Answer&, const Answer&) override { m_best = m_turned; }
  void rejected(AlternativeContext& ctx, Answer&) override { ctx.turn_luminaire(m_best); }

private:
  float m_base, m_best, m_turned = 0.f;
  std::vector<float> m_spins;
};

} // namespace

std::shared_ptr<Alternative> luminaire_turns_alternative(const Light& luminaire) {
  return std::make_shared<LuminaireTurns>(luminaire);
}

} // namespace hilight
