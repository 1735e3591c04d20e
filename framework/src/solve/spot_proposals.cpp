#include "hilight/solve/spot_proposals.hpp"

#include "hilight/solve/fit.hpp"
#include "hilight/solve/moves.hpp"
#include "hilight/solve/round_extrapolation.hpp"
#include "hilight/solve/spot_refinement.hpp"
#include "hilight/solve/spot_screening.hpp"

#include <algorithm>
#include <optional>

namespace hilight {

namespace {

/// Candidates refined per round: the screening's best few from distinct apexes.
constexpr size_t kStarts = 6;
/// Each bounce estimate serves this many Levenberg–Marquardt steps: more are
/// spent following a bounce that is already out of date.
constexpr int kRoundIterations = 15;

/// How spots are refined: bounce rounds at most, whose bounce (the fast
/// renderer's is 3x cheaper and ~25% off: enough to compare candidates, not
/// to place the answer), how over-lighting counts (refine_spots), and the
/// widest soft edge as a share of the cutoff.
struct Pass {
  int rounds;
  bool fast_bounce;
  double over_weight;
  double falloff_share;
};
/// While the set is built, a spot keeps an edge (soft edge at most half its
/// cutoff): an edgeless lobe fits under several pools at once and then
/// holds them all.
constexpr double kBuildingFalloffShare = 0.5;
/// Spots refined together while the set is built...
constexpr Pass kJoint{12, false, 1.0, kBuildingFalloffShare};
/// ...and once it is: every edge free.
constexpr Pass kFree{12, false, 1.0, 1.0};
/// Settling (Model::settle), the answer's last word: past the slopes' stop,
/// a simplex. A shadow edge sweeping over samples as a lamp moves is a kink
/// the finite differences do not see (they leave those samples out), and it
/// can hold Levenberg–Marquardt a few cm off (the curved models turned,
/// with the bounce: 5 cm, D̄ 1.3%; settled, within 0.2 mm, D̄ 0.02%).
/// Rounds at most in each of its two phases, the simplex's evaluations at
/// most per round...
constexpr int kSettleRounds = 12, kSettleSimplexEvaluations = 600;
/// ...and rounds in a row without a 2% gain on the best before it stops:
/// the bounce's roughness (each gather hit crosses shadow edges on its own)
/// makes a round fit worse now and then on the way down (measured, fine-tune
/// after a turn, D̄·10⁴ in the rounds fitted without the spikes: 2.74, then
/// 3.32, 2.78, 2.57, 2.31, 0.98; stopping after two such rounds left the
/// spot 10⁻⁴ of the size from the lamp, after three 1.4·10⁻⁵).
constexpr int kSettlePatience = 3;
/// A D̄ the settling stops at: float renders of the same lights differ by
/// ~10⁻⁷ of the target, so no round can show a gain below this (measured:
/// the curved models' spot at D̄ 4.7·10⁻⁷ stood 2·10⁻⁷ of the size from
/// the lamp, and four more rounds moved it by nothing).
constexpr double kSettledDbar = 1e-6;
/// The simplex settles up to this many lights together. With more, its
/// dimensions (7 a spot, 3 a point light) outgrow what
/// kSettleSimplexEvaluations can search (measured on the curved models:
/// every run over 13 or 17 dimensions used all its evaluations, those over
/// 10 converged) while each evaluation renders every light. The home's four
/// lamps and a downlight settled in 23 s with it, 5 s without, as well (D̄
/// over the whole target 1.52% with, 1.37% without); the curved models'
/// three-light trial (wide_spots_as_points) made their solve 56 s with it,
/// 40 s without, for lamps within 1.5·10⁻⁵ and 1.3·10⁻⁵ of the size (the
/// answer's own settling, two lights, keeps its simplex).
constexpr size_t kSimplexMaxLights = 2;
/// A candidate beside the spots found so far: it may light less than the
/// target (lamps not yet found will add) but over-lighting counts 100
/// times: otherwise the best single spot for two or three pools is one wide
/// cone over all of them.
constexpr Pass kCandidate{2, true, 100.0, kBuildingFalloffShare};
/// Two candidates together (a spot split in two).
constexpr Pass kPair{2, true, 1.0, kBuildingFalloffShare};

/// A sample holding more than this many times the mean squared residual of
/// the samples still kept is a spike (without_spikes).
constexpr double kSpike = 100.0;

/// `samples`' weights with the spikes of `residual` left out, again and
/// again while any stands out of the rest. Near the lights that made the
/// target, what the bounce re-taken gets wrong is a handful of samples: a
/// gather hit that crossed a shadow edge as the lights moved changes its
/// sample by 1/128 of a lit hit (measured on a turned scene, 0.4 mm from
/// the lamps: 20 of 6,708 points held 99.9% of the bounce's difference,
/// against 500 for 55% of the direct light's). Fitted with them, the rounds
/// stop where their spikes balance the direct light's pull (0.1–0.7 mm
/// off); without them the direct light alone places the lights.
std::vector<float> without_spikes(const SampleSet& samples, const std::vector<Rgb>& residual) {
  const size_t m = samples.size();
  std::vector<double> e(m);
  for (size_t i = 0; i < m; ++i) e[i] = double(samples.weight[i]) * glm::dot(DVec3(residual[i]), DVec3(residual[i]));
  std::vector<float> weight = samples.weight;
  for (bool dropped = true; dropped;) {
    double sum = 0;
    size_t kept = 0;
    for (size_t i = 0; i < m; ++i)
      if (weight[i] > 0.f) sum += e[i], ++kept;
    if (kept == 0 || !(sum > 0)) break;
    const double limit = kSpike * sum / double(kept);
    dropped = false;
    for (size_t i = 0; i < m; ++i)
      if (weight[i] > 0.f && e[i] > limit) weight[i] = 0.f, dropped = true;
  }
  return weight;
}

/// `a`'s lights stand where `b`'s do, aimed and opened alike (intensities aside).
bool same_geometry(const Lighting& a, const Lighting& b) {
  if (a.size() != b.size()) return false;
  for (size_t j = 0; j < a.size(); ++j)
    if (a[j].type != b[j].type || a[j].position != b[j].position || a[j].direction != b[j].direction ||
        a[j].cutoff_deg != b[j].cutoff_deg || a[j].falloff_deg != b[j].falloff_deg)
      return false;
  return true;
}

struct Model {
  const SampleSet& samples;
  const LightSpace& space;
  Renderer& renderer;   ///< direct light (and the fast bounce)
  Renderer& reference;  ///< the bounce estimates

  std::vector<Rgb> bounce_of(const Lighting& spots, bool fast = false) const {
    return (fast ? renderer : reference).unit_responses(samples.points, spots, Transport::IndirectOnly);
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
  /// ~2.5x a round). The Fit's D̄: the last round's, with the bounce it
  /// held. `bounce` (if given) gets the bounce where they end.
  Fit refine(Lighting spots, const std::vector<Rgb>& base_phi, size_t base_count, const Pass& pass,
             std::vector<Rgb>* bounce = nullptr) const {
    Fit fit{std::move(spots)};
    double previous = 1e300;
    SpotRefineSettings settings;
    settings.over_weight = pass.over_weight;
    settings.max_falloff_share = pass.falloff_share;
    settings.iterations = kRoundIterations;
    for (int round = 0; round < pass.rounds; ++round) {
      const std::vector<Rgb> estimate = bounce_of(fit.lights, pass.fast_bounce);
      fit = refine_spots(fit.lights, estimate, samples, space, renderer, base_phi, base_count, settings);
      if (fit.dbar > 0.98 * previous) break;  // the bounce no longer moves the spots
      previous = fit.dbar;
    }
    if (bounce) *bounce = bounce_of(fit.lights);
    return fit;
  }

  /// D̄ of `lights` with `bounce` (theirs), intensities fitted.
  double dbar_with(const Lighting& lights, const std::vector<Rgb>& bounce) const { return fit(responses(lights, bounce), lights.size()); }

  /// `lights` (alone: nothing held) settled: rounds as refine's, with a
  /// simplex after each round's Levenberg–Marquardt (spot_refinement.hpp),
  /// each round judged by its lights' D̄ with the bounce re-taken where they
  /// stand — the objective itself, not the held bounce it was refined with
  /// — and the best kept, so the answer is never worse than `lights`. While
  /// the set is built refine() moves on regardless (measured: stopping at a
  /// worse round there lost a turned scene's spot, D̄ 18%). Once the rounds
  /// stall (or reach kSettleRounds), with `despike`, as many more rounds
  /// again from the best fit the samples without the bounce's spikes
  /// (without_spikes; not from the start: far from the answer a lamp's own
  /// hot spot is a spike, and fitted without it the rounds went nowhere, D̄
  /// 0.6%). The best's intensities are those its D̄ was fitted with; the
  /// Fit's D̄ is that D̄ (with the bounce re-taken), `bounce` gets its bounce.
  Fit settle(Lighting lights, std::vector<Rgb>* bounce = nullptr, bool despike = false) const {
    SpotRefineSettings settings;
    settings.iterations = kRoundIterations;
    settings.simplex_evaluations = lights.size() <= kSimplexMaxLights ? kSettleSimplexEvaluations : 0;
    Lighting best;
    std::vector<Rgb> best_bounce, best_residual, residual, estimate, intensities;
    double best_dbar = 1e300;
    std::optional<SampleSet> despiked;  // the samples the rounds fit, once without the spikes
    bool moved = true, despiking = false;
    RoundExtrapolation extrapolation(space.rays().scene().diagonal());
    std::optional<Lighting> plain;  // the plain round's lights while `lights` is a guess ahead of them
    for (int round = 0, rounds_without_gain = 0;; ++round) {  // rounds counted in each phase
      if (moved) {
        estimate = bounce_of(lights);
        double d = fit(responses(lights, estimate), lights.size(), &residual, &intensities);
        if (plain) {  // the guess against the plain round, each with its own bounce
          std::vector<Rgb> plain_estimate = bounce_of(*plain), plain_residual, plain_intensities;
          const double plain_d = fit(responses(*plain, plain_estimate), plain->size(), &plain_residual, &plain_intensities);
          if (!(d < plain_d)) {
            lights = std::move(*plain), estimate = std::move(plain_estimate), residual = std::move(plain_residual);
            intensities = std::move(plain_intensities), d = plain_d;
          }
          plain.reset();
        }
        rounds_without_gain = d < 0.98 * best_dbar ? 0 : rounds_without_gain + 1;
        if (best.empty() || d < best_dbar) {
          best = lights, best_bounce = estimate, best_residual = residual, best_dbar = d;
          for (size_t j = 0; j < best.size(); ++j) best[j].intensity = intensities[j];
        }
      } else {
        rounds_without_gain = kSettlePatience;  // the same lights again: every round after would be this one
      }
      if (best_dbar <= kSettledDbar) break;  // as close as float renders show
      if (rounds_without_gain >= kSettlePatience || round == kSettleRounds) {
        if (!despike || despiking) break;
        // Direct light alone has no spikes of the bounce; and without any
        // left out the rounds would retrace the ones just run.
        const bool bounce_seen = std::any_of(best_bounce.begin(), best_bounce.end(), [](const Rgb& b) { return b != Rgb(0.f); });
        std::vector<float> weight = without_spikes(samples, best_residual);
        if (!bounce_seen || weight == samples.weight) break;
        despiked.emplace(samples).weight = std::move(weight);
        despiking = true, round = 0, rounds_without_gain = 0;
        lights = best, estimate = best_bounce, residual = best_residual;
        extrapolation.restart();
      } else if (despiking) {
        despiked->weight = without_spikes(samples, residual);
      }
      // (Its D̄, with the bounce held, is not comparable across rounds.)
      Lighting next = refine_spots(lights, estimate, despiked ? *despiked : samples, space, renderer, {}, 0, settings).lights;
      moved = !same_geometry(next, lights);
      if (moved)
        if (std::optional<Lighting> guess = extrapolation.ahead(lights, next); guess && place_within_bounds(space, *guess)) {
          plain = std::move(next), next = std::move(*guess);
          extrapolation.restart();  // the next step starts from the guess or the plain round, not from `next`
        }
      lights = std::move(next);
    }
    if (bounce) *bounce = std::move(best_bounce);
    return {std::move(best), best_dbar};
  }

  /// D̄ of lights with responses `phi` (n of them), intensities by NNLS
  /// (`intensities` gets them); `residual`: Ψ − the fit.
  double fit(const std::vector<Rgb>& phi, size_t n, std::vector<Rgb>* residual = nullptr, std::vector<Rgb>* intensities = nullptr) const {
    const size_t m = samples.size();
    std::vector<Rgb> fitted = fit_intensities(phi, n, samples);
    const std::vector<Rgb> lit = combine(phi, fitted, m);
    if (intensities) *intensities = std::move(fitted);
    if (residual) {
      residual->resize(m);
      for (size_t i = 0; i < m; ++i) (*residual)[i] = samples.target[i] - lit[i];
    }
    return normalized_difference(lit, samples);
  }
};

/// `spots` without spot `s`; `kept_bounce` gets the others' bounce.
Lighting without(const Lighting& spots, const std::vector<Rgb>& bounce, size_t s, size_t m, std::vector<Rgb>& kept_bounce) {
  Lighting kept = spots;
  kept.erase(kept.begin() + std::ptrdiff_t(s));
  kept_bounce = bounce;
  kept_bounce.erase(kept_bounce.begin() + std::ptrdiff_t(s * m), kept_bounce.begin() + std::ptrdiff_t((s + 1) * m));
  return kept;
}

/// The best of the screening's candidates for what `base` (responses
/// `base_phi`, with bounce) leaves, each refined with the base held: one
/// light and its D̄ beside them. No light when the screening has no candidate.
Fit best_candidate(const Model& model, const SpotScreen& screen, const std::vector<Rgb>& base_phi, size_t base_count) {
  std::vector<Rgb> residual;
  model.fit(base_phi, base_count, &residual);
  Fit best{{}, 1e300};
  for (const Light& start : screen.candidates(residual, kStarts)) {
    const Fit one = model.refine({start}, base_phi, base_count, kCandidate);
    if (one.dbar < best.dbar) best = {{one.lights[0]}, one.dbar};
  }
  return best;
}

/// Each of `spots` in turn replaced by the best candidate for what the
/// others leave, all then refined together; kept where D̄ falls (`bounce`,
/// the spots' own, follows them).
Fit replace_each(const Model& model, const SpotScreen& screen, Fit spots, std::vector<Rgb>& bounce, const Judge& judge) {
  for (size_t s = 0; s < spots.lights.size() && judge.light_more_visible(spots.dbar); ++s) {
    std::vector<Rgb> trial_bounce;
    Lighting trial = without(spots.lights, bounce, s, model.samples.size(), trial_bounce);
    const Fit other = best_candidate(model, screen, model.responses(trial, trial_bounce), trial.size());
    if (other.lights.empty()) continue;
    trial.push_back(other.lights[0]);
    Fit refined = model.refine(std::move(trial), {}, 0, kJoint, &trial_bounce);
    if (!(refined.dbar < spots.dbar)) continue;
    spots = std::move(refined), bounce = std::move(trial_bounce);
  }
  return spots;
}

/// `spots` with spot `s` in two: the best pair among the screening's
/// candidates for what the others leave, each refined alone and then every
/// pair together with the others held; then all refined together. A spot
/// over two overlapping pools is the best single cone for both, so the two
/// are looked for together. No lights when no pair was found.
Fit split(const Model& model, const SpotScreen& screen, const Lighting& spots, const std::vector<Rgb>& bounce, size_t s,
          std::vector<Rgb>& split_bounce) {
  Lighting others = without(spots, bounce, s, model.samples.size(), split_bounce);
  const std::vector<Rgb> base = model.responses(others, split_bounce);
  std::vector<Rgb> residual;
  model.fit(base, others.size(), &residual);
  Lighting alone;
  for (const Light& start : screen.candidates(residual, kStarts))
    alone.push_back(model.refine({start}, base, others.size(), kCandidate).lights[0]);
  Fit best{{}, 1e300};
  for (size_t i = 0; i < alone.size(); ++i)
    for (size_t j = i + 1; j < alone.size(); ++j) {
      Fit pair = model.refine({alone[i], alone[j]}, base, others.size(), kPair);
      if (pair.dbar < best.dbar) best = std::move(pair);
    }
  if (best.lights.empty()) return {{}, 1.0};
  others.insert(others.end(), best.lights.begin(), best.lights.end());
  return model.refine(std::move(others), {}, 0, kJoint, &split_bounce);
}

/// Each spot at least kWideSpotDeg wide tried as a point light, all then
/// settled together (the trial shared with the solve's move,
/// moves/wide_spots_as_points.cpp). Only once the set is built: while it
/// is, a wide cone may be the first spot over two pools, and a point light,
/// once there, is never a spot again.
Fit wide_spots_as_points(const Model& model, const Judge& judge, const Fit& spots, std::vector<Rgb>& bounce) {
  std::vector<Rgb> trial_bounce;
  return hilight::wide_spots_as_points(
      judge, spots, [&](const Lighting& trial) { return model.settle(trial, &trial_bounce); }, [&] { bounce = trial_bounce; });
}

} // namespace

Fit propose_spots(const SampleSet& samples, const LightSpace& space, Renderer& renderer, Renderer& reference,
                  const SpotProposalSettings& settings) {
  const size_t m = samples.size();
  const Model model{samples, space, renderer, reference};
  const SpotScreen screen(samples, space, renderer);
  Fit spots;  // no light: all of Ψ is missing
  std::vector<Rgb> bounce;
  // One spot a round for what the others leave (eq. 9 forward, as the point
  // lights' add-missing move): each of the screening's candidates refined
  // with the others held, the best kept, then all refined together.
  const Judge& judge = settings.judge;
  while (spots.lights.size() < judge.max_spots() && judge.light_more_visible(spots.dbar)) {
    const Fit best = best_candidate(model, screen, spots.lights.empty() ? std::vector<Rgb>{} : model.responses(spots.lights, bounce),
                                    spots.lights.size());
    if (best.lights.empty()) break;
    Lighting more_lights = spots.lights;
    more_lights.push_back(best.lights[0]);
    std::vector<Rgb> more_bounce;
    Fit more = model.refine(std::move(more_lights), {}, 0, kJoint, &more_bounce);
    bool pays = judge.light_more_pays(spots.dbar, more.dbar);
    if (!pays && more.lights.size() > 1) {
      // Re-placed given the others, each spot may do better: the first spot
      // over pools that overlap is one wide cone; once others hold some of
      // them, its best place is one pool. Then the spot more may pay.
      more = replace_each(model, screen, std::move(more), more_bounce, judge);
      pays = judge.light_more_pays(spots.dbar, more.dbar);
    }
    if (!pays) break;
    spots = std::move(more), bounce = std::move(more_bounce);
  }
  if (spots.lights.empty()) return spots;
  // Poorly explained still: a spot may hold two pools that overlap. Each
  // spot tried as two, kept if the spot more pays (eq. 9).
  for (size_t s = 0; judge.split_spots(spots.dbar) && s < spots.lights.size() && spots.lights.size() < judge.max_spots(); ++s) {
    std::vector<Rgb> split_bounce;
    Fit two = split(model, screen, spots.lights, bounce, s, split_bounce);
    if (two.lights.empty() || !judge.light_more_pays(spots.dbar, two.dbar)) continue;
    spots = std::move(two), bounce = std::move(split_bounce);
  }
  // The set is built: every edge free, plain least squares.
  spots.lights = model.refine(std::move(spots.lights), {}, 0, kFree, &bounce).lights;
  // From here on each D̄ is with the bounce re-taken where the lights stand,
  // as the settling's is (the rounds' own is with the bounce they held).
  spots.dbar = model.dbar_with(spots.lights, bounce);
  spots = wide_spots_as_points(model, judge, spots, bounce);
  // Eq. 9 backwards: the spot whose loss the others bear best (intensities
  // re-fitted) goes if, the others refined without it, the loss is less
  // than ε_impro (and less than ε_w of ‖Ψ‖), or invisible.
  while (spots.lights.size() > 1) {
    const Lighting& lights = spots.lights;
    const std::vector<Rgb> phi = model.responses(lights, bounce);
    size_t weakest = 0;
    double least = 1e300;
    for (size_t s = 0; s < lights.size(); ++s) {
      std::vector<Rgb> without;
      for (size_t j = 0; j < lights.size(); ++j)
        if (j != s) without.insert(without.end(), phi.begin() + std::ptrdiff_t(j * m), phi.begin() + std::ptrdiff_t((j + 1) * m));
      if (const double d = model.fit(without, lights.size() - 1); d < least) least = d, weakest = s;
    }
    Lighting fewer_lights = lights;
    fewer_lights.erase(fewer_lights.begin() + std::ptrdiff_t(weakest));
    std::vector<Rgb> fewer_bounce;
    Fit fewer = model.refine(std::move(fewer_lights), {}, 0, kFree, &fewer_bounce);
    fewer.dbar = model.dbar_with(fewer.lights, fewer_bounce);
    if (judge.light_more_pays(fewer.dbar, spots.dbar) && judge.light_more_visible(fewer.dbar)) break;  // the spot pays: it stays
    spots = std::move(fewer), bounce = std::move(fewer_bounce);
  }
  // The last word: past the slopes' stop, a simplex over every light's
  // geometry (spot_refinement.hpp).
  return model.settle(std::move(spots.lights), &bounce, true);
}

Fit settle_lights(const SampleSet& samples, const LightSpace& space, Renderer& renderer, Renderer& reference, Lighting lights) {
  const Model model{samples, space, renderer, reference};
  return model.settle(std::move(lights), nullptr, true);
}

} // namespace hilight
