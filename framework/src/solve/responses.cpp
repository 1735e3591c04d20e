#include "hilight/solve/responses.hpp"

#include "hilight/light_cache.hpp"

namespace hilight {

std::vector<Rgb> ResponseModel::responses(std::span<const Light> lights) {
  const size_t m = m_samples.size();
  m_evaluations += lights.size();
  if (!m_cache) return m_renderer.unit_responses(m_samples.points, lights, Transport::All);
  // Point lights: traced direct light + cached bounce. Spots: all traced.
  std::vector<Rgb> out = m_renderer.unit_responses(m_samples.points, lights, Transport::DirectOnly);
  std::vector<Light> spots;
  std::vector<size_t> spot_index;
  for (size_t j = 0; j < lights.size(); ++j) {
    if (lights[j].type == LightType::Spot) {
      spots.push_back(lights[j]);
      spot_index.push_back(j);
    } else {
      m_cache->add_indirect(lights[j].position, &out[j * m]);
    }
  }
  if (!spots.empty()) {
    std::vector<Rgb> bounce = m_renderer.unit_responses(m_samples.points, spots, Transport::IndirectOnly);
    for (size_t s = 0; s < spots.size(); ++s)
      for (size_t i = 0; i < m; ++i) out[spot_index[s] * m + i] += bounce[s * m + i];
  }
  return out;
}

} // namespace hilight
