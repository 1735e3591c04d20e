// Luminaires turned about their aim for a painted target (solve/luminaire_aim.hpp).
#include "hilight/solve/luminaire_aim.hpp"

#include "hilight/solve/fit.hpp"

#include <cmath>

namespace hilight {

Fit aim_luminaires(Renderer& reference, const SampleSet& samples, Lighting lights) {
  const size_t m = samples.size(), n = lights.size();
  std::vector<std::vector<float>> spins(n);  // per light: the turns tried, from its own
  Lighting batch;
  std::vector<size_t> first(n);
  for (size_t j = 0; j < n; ++j) {
    first[j] = batch.size();
    const Light& l = lights[j];
    spins[j] = l.type == LightType::Luminaire && l.profile ? distinct_spins(*l.profile) : std::vector<float>{0.f};
    for (float s : spins[j]) {
      Light turned = l;
      turned.spin_deg = std::fmod(l.spin_deg + s, 360.f);
      batch.push_back(turned);
    }
  }
  const std::vector<Rgb> all = reference.unit_responses(samples.points, batch);
  std::vector<size_t> choice(n, 0);
  const auto evaluate = [&](const std::vector<size_t>& c, std::vector<Rgb>& intensities) {
    std::vector<Rgb> phi;
    phi.reserve(n * m);
    for (size_t j = 0; j < n; ++j) {
      const auto* col = all.data() + (first[j] + c[j]) * m;
      phi.insert(phi.end(), col, col + m);
    }
    intensities = fit_intensities(phi, n, samples);
    return std::make_pair(difference(combine(phi, intensities, m), samples), phi);
  };
  std::vector<Rgb> intensities;
  auto [best, best_phi] = evaluate(choice, intensities);
  // Coordinate descent: each light's turn with the others held, a few passes.
  for (int pass = 0; pass < 3; ++pass) {
    bool changed = false;
    for (size_t j = 0; j < n; ++j)
      for (size_t s = 0; s < spins[j].size(); ++s) {
        if (s == choice[j]) continue;
        std::vector<size_t> trial = choice;
        trial[j] = s;
        std::vector<Rgb> fitted;
        auto [d, phi] = evaluate(trial, fitted);
        if (d < best * (1 - 1e-4)) {
          best = d;
          best_phi = std::move(phi);
          choice = std::move(trial);
          intensities = std::move(fitted);
          changed = true;
        }
      }
    if (!changed) break;
  }
  for (size_t j = 0; j < n; ++j) {
    lights[j] = batch[first[j] + choice[j]];
    lights[j].intensity = intensities[j];
  }
  const double dbar = normalized_difference(combine(best_phi, intensities, m), samples);
  return {std::move(lights), dbar};
}

} // namespace hilight
