#include "hilight/solve/refine_problem.hpp"

#include "hilight/solve/fit.hpp"

#include <algorithm>
#include <cstring>

namespace hilight {

namespace {
// Everything but the intensity decides φ.
std::string geometry_key(const Light& l) {
  float data[10] = {float(l.type == LightType::Spot), l.position.x, l.position.y, l.position.z, l.direction.x,
                    l.direction.y, l.direction.z, l.cutoff_deg, l.falloff_deg, 0.f};
  if (l.type != LightType::Spot) std::fill(data + 4, data + 10, 0.f);
  return std::string(reinterpret_cast<const char*>(data), sizeof(data));
}
// The responses kept for lights already asked about, at most this many
// bytes: a refinement revisits its current and recent lights, not the whole
// walk (a simplex run is 20 evaluations), and two cuts refined at once each
// keep their own (4,096 responses over the bench building's samples held
// 220 MB each).
constexpr size_t kMaxStoredBytes = size_t(16) << 20;
size_t max_stored_responses(size_t samples) { return std::max<size_t>(64, kMaxStoredBytes / (sizeof(Rgb) * std::max<size_t>(1, samples))); }
} // namespace

const std::vector<Rgb>& SampleRefineProblem::phi_of(const Light& light) {
  std::string key = geometry_key(light);
  auto it = m_phi.find(key);
  if (it != m_phi.end()) return it->second;
  if (m_phi.size() >= max_stored_responses(m_model.samples().size())) m_phi.clear();
  return m_phi.emplace(key, m_model.responses(std::span<const Light>(&light, 1))).first->second;
}

std::vector<Rgb> SampleRefineProblem::responses(std::span<const Light> lights) {
  std::vector<size_t> index(lights.size());
  for (size_t j = 0; j < index.size(); ++j) index[j] = j;
  return responses_as(lights, index);
}

std::vector<Rgb> SampleRefineProblem::responses_as(std::span<const Light> lights, std::span<const size_t> anchor_index) {
  const size_t m = m_model.samples().size();
  std::vector<Rgb> out(lights.size() * m);
  // Batch the lights not yet known: one renderer call for all of them.
  Lighting missing;
  for (const auto& l : lights)
    if (!m_phi.count(geometry_key(l))) missing.push_back(l);
  if (!missing.empty()) {
    if (m_phi.size() + missing.size() > max_stored_responses(m)) m_phi.clear();
    std::vector<Rgb> phi = m_model.responses(missing);
    for (size_t q = 0; q < missing.size(); ++q)
      m_phi[geometry_key(missing[q])].assign(phi.begin() + std::ptrdiff_t(q * m), phi.begin() + std::ptrdiff_t((q + 1) * m));
  }
  for (size_t j = 0; j < lights.size(); ++j) {
    const auto& p = phi_of(lights[j]);
    Rgb* dst = &out[j * m];
    const size_t a = anchor_index[j];
    if (a < m_correction.size() && !m_correction[a].empty())
      for (size_t i = 0; i < m; ++i) dst[i] = glm::max(p[i] + m_correction[a][i], Rgb(0.f));
    else
      std::copy(p.begin(), p.end(), dst);
  }
  return out;
}

void SampleRefineProblem::anchor(const Lighting& lights) {
  m_correction.clear();
  if (!m_exact) return;
  const size_t m = m_model.samples().size();
  std::vector<Rgb> exact = m_exact->responses(lights);
  m_correction.resize(lights.size());
  for (size_t j = 0; j < lights.size(); ++j) {
    const auto& approx = phi_of(lights[j]);
    m_correction[j].resize(m);
    for (size_t i = 0; i < m; ++i) m_correction[j][i] = exact[j * m + i] - approx[i];
  }
}

bool SampleRefineProblem::place(std::vector<Light>& lights) const {
  for (auto& l : lights) {
    const auto p = m_space.place(l.position);
    if (!p || !m_space.admissible(*p)) return false;
    l.position = *p;
  }
  return true;
}

double SampleRefineProblem::objective(std::span<const Light> given) {
  std::vector<Light> lights(given.begin(), given.end());
  if (!place(lights)) return 1e300;
  const SampleSet& s = m_model.samples();
  std::vector<Rgb> intensities;
  for (const auto& l : lights) intensities.push_back(l.intensity);
  double d = difference(combine(responses(lights), intensities, s.size()), s);
  return d * d;
}

double SampleRefineProblem::objective_with_best_intensities(std::vector<Light>& lights) {
  if (!place(lights)) return 1e300;
  const SampleSet& s = m_model.samples();
  std::vector<Rgb> phi = responses(lights);
  std::vector<Rgb> l = fit_intensities(phi, lights.size(), s);
  for (size_t j = 0; j < lights.size(); ++j) lights[j].intensity = l[j];
  double d = difference(combine(phi, l, s.size()), s);
  return d * d;
}

double SampleRefineProblem::negligible() const {
  const double floor = 1e-4 * m_model.samples().target_norm();
  return floor * floor;
}

bool SampleRefineProblem::admissible(const Vec3& p) const {
  const auto placed = m_space.place(p);
  return placed && m_space.admissible(*placed);
}

} // namespace hilight
