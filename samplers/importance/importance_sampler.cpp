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
#include "hilight/version.hpp"
#include "hilight/registry.hpp"
#include "hilight/sampler.hpp"

#include <cmath>
#include <tbb/parallel_for.h>
#include <unordered_map>

namespace {

using namespace hilight;

float luminance(const Rgb& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

/// Uniform hash grid over points, for neighbourhood means.
struct PointGrid {
  float cell;
  std::unordered_map<uint64_t, std::vector<uint32_t>> cells;
  static uint64_t key(int x, int y, int z) {
    return (uint64_t(uint32_t(x) & 0x1FFFFF) << 42) | (uint64_t(uint32_t(y) & 0x1FFFFF) << 21) | uint64_t(uint32_t(z) & 0x1FFFFF);
  }
  glm::ivec3 coord(const Vec3& p) const { return glm::ivec3(glm::floor(p / cell)); }
};

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
    PointGrid grid{std::max(radius, 1e-6f), {}};
    for (uint32_t i = 0; i < n; ++i) {
      glm::ivec3 c = grid.coord(target.points.positions[i]);
      grid.cells[PointGrid::key(c.x, c.y, c.z)].push_back(i);
    }
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
    std::vector<std::pair<glm::ivec3, const std::vector<uint32_t>*>> cells;
    cells.reserve(grid.cells.size());
    for (const auto& [key, members] : grid.cells) cells.emplace_back(grid.coord(target.points.positions[members.front()]), &members);
    tbb::parallel_for(size_t(0), cells.size(), [&](size_t k) {
      const glm::ivec3 c = cells[k].first;
      std::vector<Vec3> near_position;
      std::vector<float> near_luminance;
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz) {
            auto it = grid.cells.find(PointGrid::key(c.x + dx, c.y + dy, c.z + dz));
            if (it == grid.cells.end()) continue;
            for (uint32_t j : it->second) {
              near_position.push_back(target.points.positions[j]);
              near_luminance.push_back(luminance(target.value[j]));
            }
          }
      for (uint32_t i : *cells[k].second) {
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
