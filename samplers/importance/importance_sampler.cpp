// The `importance` sampler (paper §3.2): points where the target changes
// quickly (shadow edges, highlights, painted detail) and points darker than
// their neighbourhood (in shadow) are drawn more often.
//
// | property       | default | meaning                                                    |
// |----------------|---------|------------------------------------------------------------|
// | contrast_gain  | 4       | importance = weight · (1 + contrast_gain · local contrast  |
// | shadow_gain    | 1       |                        + shadow_gain · darkness            |
// | energy_gain    | 1       |                        + energy_gain · min(16, lum²/mean)) |
//
// The energy term draws more samples where the squared norm of eq. 2 sits:
// the hot spots a lamp near a ceiling paints, which hold most of D̄ (a point
// 4x brighter than the mean weighs 16x in ‖Ψ − I‖²), capped so that one hot
// spot cannot take every sample.
#include "hilight/error.hpp"
#include "hilight/plugin.hpp"
#include "hilight/point_grid.hpp"
#include "hilight/version.hpp"
#include "hilight/registry.hpp"
#include "hilight/sampler.hpp"

#include <cmath>
#include <tbb/parallel_for.h>

namespace {

using namespace hilight;

float luminance(const Rgb& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

class ImportanceSampler final : public Sampler {
public:
  ImportanceSampler(float contrast_gain, float shadow_gain, float energy_gain)
      : m_contrast_gain(contrast_gain), m_shadow_gain(shadow_gain), m_energy_gain(energy_gain) {}

  SampleSet draw(const Target& target, const SampleRequest& request) override {
    if (request.count >= target.size()) return all_samples(target);
    return draw_by_weight(target, importance(target, request.neighbourhood_radius), request.count, request.seed);
  }

private:
  std::vector<double> importance(const Target& target, float radius) const {
    const size_t n = target.size();
    PointGrid grid(std::max(radius, 1e-6f));
    for (uint32_t i = 0; i < n; ++i) grid.add(target.points.positions[i], i);
    double mean_lum = 0, mean_square = 0;
    for (const auto& v : target.value) mean_lum += luminance(v), mean_square += double(luminance(v)) * luminance(v);
    mean_lum = std::max(1e-12, mean_lum / double(n));
    mean_square = std::max(1e-24, mean_square / double(n));
    std::vector<double> out(n);
    const float r2 = radius * radius;
    // Cell by cell: a cell's points share the 27 cells around them, gathered
    // once into a flat list (in the order a point would visit them, so the
    // sums are the same to the bit). Each cell writes only its own points'
    // entries: parallel-safe and the same whatever the thread count.
    std::vector<const std::vector<uint32_t>*> cells;
    cells.reserve(grid.cell_count());
    grid.for_each_cell([&](const std::vector<uint32_t>& members) { cells.push_back(&members); });
    tbb::parallel_for(size_t(0), cells.size(), [&](size_t k) {
      std::vector<Vec3> near_position;
      std::vector<float> near_luminance;
      grid.for_each_near(target.points.positions[cells[k]->front()], [&](uint32_t j) {
        near_position.push_back(target.points.positions[j]);
        near_luminance.push_back(luminance(target.value[j]));
      });
      for (uint32_t i : *cells[k]) {
        const Vec3& p = target.points.positions[i];
        double sum = 0;
        int count = 0;
        for (size_t q = 0; q < near_position.size(); ++q) {
          const Vec3 d = near_position[q] - p;
          if (glm::dot(d, d) <= r2) {
            sum += near_luminance[q];
            ++count;
          }
        }
        double local = count ? sum / count : luminance(target.value[i]);
        double lum = luminance(target.value[i]);
        // Contrast relative to the scene's mean, so dark regions' edges count too.
        double contrast = std::min(1.0, std::abs(lum - local) / (0.25 * mean_lum + 0.5 * local));
        double shadow = lum < local ? std::min(1.0, (local - lum) / (local + 1e-12)) : 0.0;
        double energy = std::min(16.0, lum * lum / mean_square);
        out[i] = target.weight[i] * (1.0 + m_contrast_gain * contrast + m_shadow_gain * shadow + m_energy_gain * energy);
      }
    });
    return out;
  }

  float m_contrast_gain, m_shadow_gain, m_energy_gain;
};

void register_importance(PluginRegistrar& registrar) {
  registrar.sampler([](const Properties& props) -> std::unique_ptr<Sampler> {
    double contrast = props.get_double("contrast_gain", 4.0), shadow = props.get_double("shadow_gain", 1.0),
           energy = props.get_double("energy_gain", 1.0);
    if (!(contrast >= 0 && shadow >= 0 && energy >= 0)) throw InputError("sampler importance: gains must be >= 0");
    return std::make_unique<ImportanceSampler>(float(contrast), float(shadow), float(energy));
  });
}

} // namespace

HILIGHT_PLUGIN("sampler", HILIGHT_PLUGIN_NAME, HILIGHT_VERSION, "more samples at shadow edges, highlights and in shadow (the paper)",
               register_importance)
