#pragma once
/// Intensities by NNLS for lights at fixed positions (eq. 5), the three
/// colour channels as independent problems, and the differences of eq. 2/8.
#include "hilight/lighting.hpp"
#include "hilight/solve/samples.hpp"

#include <span>
#include <vector>

namespace hilight {

/// What every move of the solve takes and gives: lights and their D̄ at the
/// samples (the solve's own objective; which renderer measured it is the
/// move's to say). A move returns a new Fit, or the one it was given.
struct Fit {
  Lighting lights;
  double dbar = 1.0;  ///< no light: all of Ψ is missing
};

/// Best non-negative intensities (per channel) for lights with responses
/// `phi` (light-major, m per light) against the samples' target. `scale`
/// (one per sample, or empty) multiplies the samples' weights per channel.
std::vector<Rgb> fit_intensities(const std::vector<Rgb>& phi, size_t light_count, const SampleSet& samples,
                                 std::span<const Rgb> scale = {});

/// Σ_j φ_j ⊙ l_j at every sample.
std::vector<Rgb> combine(const std::vector<Rgb>& phi, std::span<const Rgb> intensities, size_t m);

/// Weighted ‖Ψ − I‖ (eq. 2) and its normalized form D̄ (eq. 8).
double difference(const std::vector<Rgb>& illumination, const SampleSet& samples);
double normalized_difference(const std::vector<Rgb>& illumination, const SampleSet& samples);

/// ‖φ_j l_j‖ (weighted), the contribution of eq. 6.
double contribution(const std::vector<Rgb>& phi, size_t j, const Rgb& intensity, const SampleSet& samples);

} // namespace hilight
