#include "hilight/solve/spot_screening.hpp"

#include "hilight/math.hpp"
#include "hilight/solve/seeder.hpp"

#include <algorithm>
#include <cmath>
#include <tbb/parallel_for.h>

namespace hilight {

namespace {

/// Cones are screened in bins of the chord |d − axis| (≈ the angle in
/// radians) one degree wide, up to 60°: every cutoff at once by prefix sums.
constexpr float kBin = float(kPi / 180.0);
constexpr int kBins = 58;     // chord 1.0 = 60°
constexpr int kMinBins = 2;   // the narrowest cone: 2°
constexpr float kMaxChord = kBins * kBin;
/// An annulus lighter than this share of its cone so far does not set the floor.
constexpr double kSignificantAnnulus = 0.02;

float luminance(const Rgb& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

} // namespace

/// A candidate apex: the samples it lights directly, the unit directions to
/// them and its unit point-light response there.
struct SpotScreen::Apex {
  Vec3 position;
  std::vector<uint32_t> index;
  std::vector<Vec3> direction;
  std::vector<Rgb> phi;
};

namespace {

using Apex = SpotScreen::Apex;


/// A hard cone: apex, axis, the first `bins` chord bins; `gain`: how much
/// it lowers the weighted squared residual alone, at its best intensity per
/// channel (`intensity`).
struct Cone {
  size_t apex = 0;
  Vec3 axis{0.f, -1.f, 0.f};
  int bins = 0;
  double gain = 0.0;
  Rgb intensity{0.f};
};

std::vector<Apex> render_apexes(const std::vector<Vec3>& positions, const SampleSet& samples, Renderer& renderer) {
  const size_t m = samples.size();
  std::vector<Apex> out(positions.size());
  constexpr size_t kBatch = 64;  // bounds the memory of one call
  for (size_t first = 0; first < positions.size(); first += kBatch) {
    const size_t count = std::min(kBatch, positions.size() - first);
    Lighting lights;
    for (size_t a = first; a < first + count; ++a) lights.push_back(Light::point(positions[a], Rgb(1.f)));
    const std::vector<Rgb> phi = renderer.unit_responses(samples.points, lights, Transport::DirectOnly);
    tbb::parallel_for(size_t(0), count, [&](size_t k) {
      Apex& apex = out[first + k];
      apex.position = positions[first + k];
      for (size_t i = 0; i < m; ++i) {
        const Rgb& v = phi[k * m + i];
        if (!(v.r > 0.f || v.g > 0.f || v.b > 0.f)) continue;
        const Vec3 d = samples.points.positions[i] - apex.position;
        const float len = glm::length(d);
        if (!(len > 0.f)) continue;
        apex.index.push_back(uint32_t(i));
        apex.direction.push_back(d / len);
        apex.phi.push_back(v);
      }
    });
  }
  return out;
}

/// The best cutoff for one apex and axis against `residual`: the cone whose
/// direct light, at an intensity that keeps it under the residual annulus
/// by annulus (per channel), removes most of the weighted squared residual.
Cone best_cutoff(const Apex& apex, const Vec3& axis, const std::vector<Rgb>& residual, const SampleSet& samples) {
  double ar[kBins][3] = {}, aa[kBins][3] = {};
  const float max_c2 = kMaxChord * kMaxChord;
  for (size_t t = 0; t < apex.index.size(); ++t) {
    const float c2 = std::max(0.f, 2.f - 2.f * glm::dot(apex.direction[t], axis));
    if (c2 >= max_c2) continue;
    const int k = std::min(kBins - 1, int(std::sqrt(c2) / kBin));
    const uint32_t i = apex.index[t];
    const Rgb wphi = samples.weight[i] * apex.phi[t];
    for (int c = 0; c < 3; ++c) {
      ar[k][c] += double(wphi[c]) * double(residual[i][c]);
      aa[k][c] += double(wphi[c]) * double(apex.phi[t][c]);
    }
  }
  // The intensity is the least of the annuli's own ratios so far: a cone
  // over a dark gap between pools, or from an apex whose falloff does not
  // match the pool's, fits under the target only dimly.
  Cone best;
  best.axis = axis;
  double sum_ar[3] = {}, sum_aa[3] = {}, floor[3] = {1e300, 1e300, 1e300};
  for (int k = 0; k < kBins; ++k) {
    double gain = 0.0;
    Rgb intensity(0.f);
    for (int c = 0; c < 3; ++c) {
      sum_ar[c] += ar[k][c], sum_aa[c] += aa[k][c];
      if (aa[k][c] > kSignificantAnnulus * sum_aa[c]) floor[c] = std::min(floor[c], ar[k][c] / aa[k][c]);
      const double l = std::min(floor[c], sum_aa[c] > 0.0 ? sum_ar[c] / sum_aa[c] : 0.0);
      if (l > 0.0) gain += 2.0 * l * sum_ar[c] - l * l * sum_aa[c], intensity[c] = float(l);
    }
    if (k + 1 >= kMinBins && gain > best.gain) best.gain = gain, best.bins = k + 1, best.intensity = intensity;
  }
  return best;
}

/// Aims: lit samples, brightest first, at least `spacing` apart (indices).
std::vector<uint32_t> spread_aims(const SampleSet& samples, float spacing, size_t most) {
  std::vector<std::pair<float, size_t>> order;
  float brightest = 0.f;
  for (size_t i = 0; i < samples.size(); ++i) {
    const float v = luminance(samples.target[i]);
    brightest = std::max(brightest, v);
    if (v > 0.f) order.emplace_back(-v, i);
  }
  std::sort(order.begin(), order.end());
  std::vector<uint32_t> aims;
  for (const auto& [v, i] : order) {
    if (aims.size() >= most || -v < 0.02f * brightest) break;  // dimmer than 2%: no pool worth a spot
    const Vec3& p = samples.points.positions[i];
    bool apart = true;
    for (uint32_t q : aims) apart &= glm::length(samples.points.positions[q] - p) >= spacing;
    if (apart) aims.push_back(uint32_t(i));
  }
  return aims;
}


Light light_of(const Cone& cone, const Apex& apex) {
  const float edge = 2.f * std::asin(std::min(1.f, 0.5f * float(cone.bins) * kBin)) * float(180.0 / kPi);
  const float falloff = std::clamp(0.2f * edge, 1.f, 4.f);  // a guess: the refinement finds the edge
  return Light::spot(apex.position, cone.axis, edge + 0.5f * falloff, cone.intensity, falloff);
}

} // namespace

SpotScreen::SpotScreen(const SampleSet& samples, const LightSpace& space, Renderer& renderer, const SpotScreenSettings& settings)
    : m_samples(samples) {
  m_apexes = render_apexes(free_grid_points(space, settings.apex_cells), samples, renderer);
  m_aims = spread_aims(samples, settings.aim_spacing * space.rays().scene().diagonal(), settings.max_aims);
  const Vec3 extent = space.bounds().extent();
  m_apart = 0.5f * std::max({extent.x, extent.y, extent.z}) / float(settings.apex_cells);
}

SpotScreen::~SpotScreen() = default;

Lighting SpotScreen::candidates(const std::vector<Rgb>& residual, size_t count) const {
  // Aims where little is missing cannot centre the cone that is missing.
  float most = 0.f;
  for (uint32_t q : m_aims) most = std::max(most, luminance(residual[q]));
  std::vector<Vec3> aims;
  for (uint32_t q : m_aims)
    if (luminance(residual[q]) > 0.05f * most) aims.push_back(m_samples.points.positions[q]);
  std::vector<Cone> per_apex(m_apexes.size());
  tbb::parallel_for(size_t(0), m_apexes.size(), [&](size_t a) {
    per_apex[a].apex = a;
    for (const Vec3& aim : aims) {
      const Vec3 to = aim - m_apexes[a].position;
      const float len = glm::length(to);
      if (!(len > 0.f)) continue;
      Cone c = best_cutoff(m_apexes[a], to / len, residual, m_samples);
      if (c.gain > per_apex[a].gain) c.apex = a, per_apex[a] = c;
    }
  });
  std::vector<size_t> order(per_apex.size());
  for (size_t a = 0; a < order.size(); ++a) order[a] = a;
  std::stable_sort(order.begin(), order.end(), [&](size_t x, size_t y) { return per_apex[x].gain > per_apex[y].gain; });
  Lighting out;
  for (size_t a : order) {
    if (out.size() >= count || !(per_apex[a].gain > 0.0)) break;
    const Vec3& at = m_apexes[a].position;
    if (std::any_of(out.begin(), out.end(), [&](const Light& l) { return glm::length(l.position - at) < m_apart; })) continue;
    out.push_back(light_of(per_apex[a], m_apexes[a]));
  }
  return out;
}

} // namespace hilight
