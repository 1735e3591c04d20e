#include "hilight/pipeline/spot_proposals.hpp"

#include "hilight/pipeline/fit.hpp"
#include "hilight/pipeline/spot_refinement.hpp"
#include "hilight/pipeline/spot_screening.hpp"

#include <cstdio>
#include <optional>
#include <cstdlib>

namespace hilight {

namespace {

/// Candidates refined per round: the screening's best few from distinct apexes.
constexpr size_t kStarts = 6;

struct Model {
  const SampleSet& samples;
  const LightSpace& space;
  Renderer& renderer;   ///< direct light
  Renderer& reference;  ///< the bounce estimates

  std::vector<Rgb> bounce_of(const Lighting& spots) const {
    return reference.unit_responses(samples.points, spots, Transport::IndirectOnly);
  }
  /// Each spot's direct light plus its `bounce`.
  std::vector<Rgb> responses(const Lighting& spots, const std::vector<Rgb>& bounce) const {
    std::vector<Rgb> phi = renderer.unit_responses(samples.points, spots, Transport::DirectOnly);
    for (size_t i = 0; i < phi.size(); ++i) phi[i] += bounce[i];
    return phi;
  }

  /// `spots` refined with `base` held, their bounce taken where they stand,
  /// again and again where they went: the bounce follows the cone slowly, so
  /// the rounds converge (measured: the error along a spot's valley falls
  /// ~2.5x a round). `bounce` gets the last estimate.
  Lighting refine(Lighting spots, const std::vector<Rgb>& base_phi, size_t base_count, int rounds, std::vector<Rgb>& bounce,
                  double& dbar) const {
    double previous = 1e300;
    for (int round = 0; round < rounds; ++round) {
      bounce = bounce_of(spots);
      spots = refine_spots(spots, bounce, samples, space, renderer, base_phi, base_count, dbar);
      if (dbar > 0.9 * previous) break;  // the bounce no longer moves the spots
      previous = dbar;
    }
    bounce = bounce_of(spots);
    return spots;
  }

  /// D̄ of lights with responses `phi` (n of them), intensities by NNLS; `residual`: Ψ − the fit.
  double fit(const std::vector<Rgb>& phi, size_t n, std::vector<Rgb>* residual = nullptr) const {
    const size_t m = samples.size();
    const std::vector<Rgb> lit = combine(phi, fit_intensities(phi, n, samples), m);
    if (residual) {
      residual->resize(m);
      for (size_t i = 0; i < m; ++i) (*residual)[i] = samples.target[i] - lit[i];
    }
    return normalized_difference(lit, samples);
  }
};

void show(const char* what, const Lighting& spots, double dbar) {
  static const bool debug = std::getenv("HILIGHT_SPOT_DEBUG");
  if (!debug) return;
  std::fprintf(stderr, "%s: D̄ %.4f\n", what, dbar);
  for (const auto& l : spots)
    std::fprintf(stderr, "  (%.3f %.3f %.3f) dir (%.3f %.3f %.3f) cutoff %.2f falloff %.2f I %.2f\n", l.position.x, l.position.y,
                 l.position.z, l.direction.x, l.direction.y, l.direction.z, l.cutoff_deg, l.falloff_deg, l.intensity.g);
}

/// The best of the screening's candidates for what `base` (responses
/// `base_phi`, with bounce) leaves, each refined with the base held; `dbar`
/// its D̄ beside them. Nothing when the screening has no candidate.
std::optional<Light> best_candidate(const Model& model, const SpotScreen& screen, const std::vector<Rgb>& base_phi, size_t base_count,
                                    double& dbar) {
  std::vector<Rgb> residual;
  model.fit(base_phi, base_count, &residual);
  std::optional<Light> best;
  dbar = 1e300;
  for (const Light& start : screen.candidates(residual, kStarts)) {
    std::vector<Rgb> bounce;
    double d = 1.0;
    const Lighting one = model.refine({start}, base_phi, base_count, 2, bounce, d);
    if (d < dbar) dbar = d, best = one[0];
  }
  return best;
}

} // namespace

Lighting propose_spots(const SampleSet& samples, const LightSpace& space, Renderer& renderer, Renderer& reference,
                       const SpotProposalSettings& settings, double& dbar) {
  const size_t m = samples.size();
  const Model model{samples, space, renderer, reference};
  const SpotScreen screen(samples, space, renderer);
  Lighting spots;
  std::vector<Rgb> bounce;
  dbar = 1.0;  // no light: all of Ψ is missing
  // One spot a round for what the others leave (eq. 9 forward, as the point
  // lights' add_missing_lights): each of the screening's candidates refined
  // with the others held, the best kept, then all refined together.
  while (spots.size() < settings.max_spots && dbar > settings.visible_dbar) {
    double one_dbar = 1.0;
    const auto best = best_candidate(model, screen, spots.empty() ? std::vector<Rgb>{} : model.responses(spots, bounce), spots.size(), one_dbar);
    if (!best) break;
    Lighting more = spots;
    more.push_back(*best);
    std::vector<Rgb> more_bounce;
    double more_dbar = one_dbar;
    if (more.size() > 1) more = model.refine(std::move(more), {}, 0, 6, more_bounce, more_dbar);
    else more_bounce = model.bounce_of(more);
    show("added", more, more_dbar);
    // Each spot re-placed given the others: the first spot over two pools
    // that overlap is one wide cone; once a second holds one pool, the
    // first's best place is the other pool.
    for (size_t s = 0; more.size() > 1 && s < more.size(); ++s) {
      Lighting others = more;
      others.erase(others.begin() + std::ptrdiff_t(s));
      std::vector<Rgb> others_bounce(more_bounce);
      others_bounce.erase(others_bounce.begin() + std::ptrdiff_t(s * m), others_bounce.begin() + std::ptrdiff_t((s + 1) * m));
      double d = 1.0;
      const auto other = best_candidate(model, screen, model.responses(others, others_bounce), others.size(), d);
      if (!other || !(d < 0.98 * more_dbar)) continue;
      others.insert(others.begin() + std::ptrdiff_t(s), *other);
      double joint = d;
      std::vector<Rgb> joint_bounce;
      others = model.refine(std::move(others), {}, 0, 6, joint_bounce, joint);
      if (!(joint < more_dbar)) continue;
      more = std::move(others), more_bounce = std::move(joint_bounce), more_dbar = joint;
      show("swapped", more, more_dbar);
    }
    const bool pays = dbar >= settings.eps_impro * more_dbar || dbar - more_dbar >= settings.weak_threshold;
    if (!pays) break;
    spots = std::move(more), bounce = std::move(more_bounce), dbar = more_dbar;
  }
  // Eq. 9 backwards: the spot whose loss the others bear best (intensities
  // re-fitted) goes if, the others refined without it, the loss is less
  // than ε_impro (and less than ε_w of ‖Ψ‖), or invisible.
  while (spots.size() > 1) {
    const std::vector<Rgb> phi = model.responses(spots, bounce);
    size_t weakest = 0;
    double least = 1e300;
    for (size_t s = 0; s < spots.size(); ++s) {
      std::vector<Rgb> without;
      for (size_t j = 0; j < spots.size(); ++j)
        if (j != s) without.insert(without.end(), phi.begin() + std::ptrdiff_t(j * m), phi.begin() + std::ptrdiff_t((j + 1) * m));
      if (const double d = model.fit(without, spots.size() - 1); d < least) least = d, weakest = s;
    }
    Lighting fewer = spots;
    fewer.erase(fewer.begin() + std::ptrdiff_t(weakest));
    std::vector<Rgb> fewer_bounce;
    double fewer_dbar = least;
    fewer = model.refine(std::move(fewer), {}, 0, 6, fewer_bounce, fewer_dbar);
    const bool pays = fewer_dbar >= settings.eps_impro * dbar || fewer_dbar - dbar >= settings.weak_threshold;
    if (pays && fewer_dbar > settings.visible_dbar) break;
    spots = std::move(fewer), bounce = std::move(fewer_bounce), dbar = fewer_dbar;
    show("pruned", spots, dbar);
  }
  return spots;
}

} // namespace hilight
