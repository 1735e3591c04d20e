// Eq. 9 backward on the fit: the nearest two point lights merged (eq. 7)
// and polished, kept while one fewer will do (a lamp the hierarchy left split).
#include "hilight/solve/moves.hpp"

#include "hilight/solve/solve_context.hpp"

#include <limits>

namespace hilight {

namespace {

/// Pairs further apart than this share of the scene's diagonal are different lamps, not a split one.
constexpr float kMergeDistance = 0.08f;

class MergePairs final : public Move {
public:
  std::string name() const override { return "merge pairs"; }
  std::string premise_fails(const SolveContext& ctx, const Fit& fit) const override {
    if (ctx.judge.count_fixed()) return "the count is fixed";
    if (fit.lights.size() <= ctx.judge.min_lights()) return "the count is at its minimum";
    return {};
  }
  Fit run(SolveContext& ctx, const Fit& fit) override;
};

Fit MergePairs::run(SolveContext& ctx, const Fit& start) {
  auto weight = [](const Light& l) { return double(l.intensity.r + l.intensity.g + l.intensity.b); };
  Fit fit = start;
  const Lighting& lights = fit.lights;
  while (lights.size() > ctx.judge.min_lights()) {
    size_t a = 0, b = 0;
    float nearest = std::numeric_limits<float>::max();
    for (size_t i = 0; i < lights.size(); ++i)
      for (size_t j = i + 1; j < lights.size(); ++j)
        if (lights[i].type == LightType::Point && lights[j].type == LightType::Point &&
            glm::length(lights[i].position - lights[j].position) < nearest)
          nearest = glm::length(lights[i].position - lights[j].position), a = i, b = j;
    if (nearest > kMergeDistance * ctx.scene.diagonal()) return fit;
    const double wa = weight(lights[a]), wb = weight(lights[b]);
    if (!(wa + wb > 0)) return fit;
    Lighting merged;
    for (size_t i = 0; i < lights.size(); ++i)
      if (i != a && i != b) merged.push_back(lights[i]);
    const Vec3 position = Vec3((wa * DVec3(lights[a].position) + wb * DVec3(lights[b].position)) / (wa + wb));
    if (!ctx.space.admissible(position)) return fit;
    merged.insert(merged.begin() + std::ptrdiff_t(std::min(a, merged.size())), Light::point(position, lights[a].intensity + lights[b].intensity));
    Fit polished = polish_with_reference(ctx, ctx.samples, merged, false);
    if (!ctx.judge.fewer_will_do(fit.dbar, polished.dbar)) return fit;
    fit = std::move(polished);
  }
  return fit;
}

} // namespace

std::shared_ptr<Move> merge_pairs_move() { return std::make_shared<MergePairs>(); }

} // namespace hilight
