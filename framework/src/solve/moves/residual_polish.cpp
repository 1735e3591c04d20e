// The residual polish: D̄ measured over the target (the report's), and
// where the whole target is explained worse than the samples say, the
// target points that hold most of the remaining squared error — often a few
// hot spots under lamps that the samples barely touch — join the samples
// and the reference polishes again; kept if the target's D̄ falls.
#include "hilight/solve/moves.hpp"

#include "hilight/solve/solve_context.hpp"
#include "../solver_internal.hpp"

#include <algorithm>
#include <numeric>

namespace hilight {

namespace {

using solver_detail::Stopwatch;

class ResidualPolish final : public Move {
public:
  explicit ResidualPolish(bool keep_count) : m_keep_count(keep_count) {}
  std::string name() const override { return "residual polish"; }
  std::string premise_fails(const SolveContext& ctx, const Fit& fit) const override {
    if (fit.lights.empty()) return "no lights";
    return ctx.settings.residual_samples ? std::string() : "turned off (--no-residual-samples)";
  }
  Fit run(SolveContext& ctx, const Fit& fit) override;

private:
  bool m_keep_count;
};

Fit ResidualPolish::run(SolveContext& ctx, const Fit& fit) {
  SolveReport& report = ctx.report;
  const Target& target = ctx.target;
  Stopwatch watch;
  const SampleSet measured = ctx.evaluation_set();
  std::vector<Rgb> lit = ctx.reference.illuminate(measured.points, fit.lights);
  report.dbar = normalized_difference(lit, measured);
  report.dbar_points = measured.size();
  report.seconds["evaluation"] += watch.seconds();
  // Below 0.2% D̄ there is nothing a designer would see; and where the whole
  // target is explained about as well as the samples, the samples saw what
  // matters (an infeasible target stays infeasible with more of them).
  if (!ctx.judge.add_residual_samples(report.dbar, fit.dbar)) return fit;
  std::vector<double> residual(measured.size());
  double total = 0;
  for (size_t i = 0; i < measured.size(); ++i) {
    const DVec3 d = DVec3(measured.target[i]) - DVec3(lit[i]);
    residual[i] = double(measured.weight[i]) * glm::dot(d, d);
    total += residual[i];
  }
  std::vector<uint32_t> order(measured.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return residual[a] > residual[b] || (residual[a] == residual[b] && a < b); });
  SampleSet samples = ctx.samples;
  std::vector<char> sampled(target.size(), 0);
  for (uint32_t i : samples.target_index) sampled[i] = 1;
  const size_t cap = std::max<size_t>(16, samples.size() / 2);
  size_t added = 0;
  double covered = 0;
  for (uint32_t k : order) {
    if (added >= cap || covered >= 0.5 * total) break;
    covered += residual[k];
    const uint32_t i = measured.target_index[k];
    if (sampled[i]) continue;
    samples.add(target, i);
    ++added;
  }
  if (added == 0) return fit;
  Stopwatch polish_watch;
  Fit polished = polish_with_reference(ctx, samples, fit.lights, m_keep_count);
  report.seconds["residual polish"] += polish_watch.seconds();
  Stopwatch again;
  const double dbar = normalized_difference(ctx.reference.illuminate(measured.points, polished.lights), measured);
  report.seconds["evaluation"] += again.seconds();
  if (!(dbar < report.dbar)) return fit;
  report.dbar = dbar;
  report.residual_samples = added;
  report.samples = samples.size();
  return polished;  // its D̄ at the grown samples becomes the report's dbar_samples
}

} // namespace

std::shared_ptr<Move> residual_polish_move(bool keep_count) { return std::make_shared<ResidualPolish>(keep_count); }

} // namespace hilight
