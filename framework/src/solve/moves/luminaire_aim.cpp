// Each luminaire turned about its aim (luminaire_aim.hpp): the solve places
// a luminaire with the template's spin; a profile that is not rotationally
// symmetric may fit better turned, light by light.
#include "hilight/solve/moves.hpp"

#include "hilight/solve/luminaire_aim.hpp"
#include "hilight/solve/solve_context.hpp"

#include <algorithm>

namespace hilight {

namespace {

class LuminaireAim final : public Move {
public:
  std::string name() const override { return "luminaire aim"; }
  std::string premise_fails(const SolveContext&, const Fit& fit) const override {
    const bool any = std::any_of(fit.lights.begin(), fit.lights.end(), [](const Light& l) { return l.type == LightType::Luminaire; });
    return any ? std::string() : "no luminaire";
  }
  Fit run(SolveContext& ctx, const Fit& fit) override {
    return aim_luminaires(ctx.reference, ctx.samples, fit.lights);
  }
};

} // namespace

std::shared_ptr<Move> luminaire_aim_move() { return std::make_shared<LuminaireAim>(); }

} // namespace hilight
