#pragma once
/// Candidate spotlights for what the lights found so far leave unexplained.
/// A cone's direct light is its apex's point-light response times the cone,
/// so one render per apex (a grid over free space, rendered once) serves every
/// aim and cutoff of every round: each apex's best cone is an arithmetic
/// screen over aims spread across the lit samples and cutoffs of 2–60°.
#include "hilight/light_space.hpp"
#include "hilight/solve/samples.hpp"
#include "hilight/renderer.hpp"

#include <vector>

namespace hilight {

struct SpotScreenSettings {
  int apex_cells = 10;          ///< apex grid: cells along the light space's longest axis
  float aim_spacing = 0.025f;   ///< aims at least this far apart (share of the diagonal)
  size_t max_aims = 96;         ///< aims over the lit samples, brightest first
};

class SpotScreen {
public:
  SpotScreen(const SampleSet& samples, const LightSpace& space, Renderer& renderer, const SpotScreenSettings& settings = {});
  ~SpotScreen();

  /// Up to `count` hard-edged spots (intensities fitted alone, the soft edge
  /// a guess) that each remove most of `residual` (Ψ − the current fit, at the
  /// samples), best first, from apexes at least half a grid cell apart — the
  /// hard cones cannot tell a pool's lamp from one on its mirror side or
  /// nearer along its axis; the caller refines them all and the fit decides.
  Lighting candidates(const std::vector<Rgb>& residual, size_t count) const;

  struct Apex;  ///< (spot_screening.cpp)

private:
  const SampleSet& m_samples;
  std::vector<Apex> m_apexes;
  std::vector<uint32_t> m_aims;  ///< samples the cones aim at
  float m_apart = 0.f;
};

} // namespace hilight
