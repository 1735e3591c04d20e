#include "hilight/solve/hierarchy.hpp"

#include "hilight/solve/fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <tbb/parallel_for.h>

namespace hilight {

LightHierarchy LightHierarchy::build(ResponseModel& model, const Lighting& leaves, const std::vector<Rgb>& leaf_phi,
                                     const std::vector<Rgb>& fixed_phi, const std::vector<Rgb>& fixed_intensity,
                                     const HierarchySettings& settings, const MayStandAt& may_stand_at) {
  const SampleSet& samples = model.samples();
  const size_t m = samples.size();
  LightHierarchy h;
  h.m_leaf_count = leaves.size();
  for (size_t j = 0; j < leaves.size(); ++j) {
    Cluster c;
    c.position = leaves[j].position;
    c.intensity = leaves[j].intensity;
    c.phi.assign(leaf_phi.begin() + std::ptrdiff_t(j * m), leaf_phi.begin() + std::ptrdiff_t((j + 1) * m));
    h.m_nodes.push_back(std::move(c));
  }
  if (leaves.empty()) return h;

  // Residual r = Ψ − Σ φ l over every current cluster and the fixed lights.
  std::vector<DVec3> r(m);
  for (size_t i = 0; i < m; ++i) r[i] = DVec3(samples.target[i]);
  auto subtract = [&](const std::vector<Rgb>& phi, const Rgb& l, double sign) {
    for (size_t i = 0; i < m; ++i) r[i] -= sign * DVec3(phi[i] * l);
  };
  for (const auto& c : h.m_nodes) subtract(c.phi, c.intensity, 1.0);
  for (size_t j = 0; j < fixed_intensity.size(); ++j)
    for (size_t i = 0; i < m; ++i) r[i] -= DVec3(fixed_phi[j * m + i] * fixed_intensity[j]);

  std::vector<int> active(leaves.size());
  for (size_t j = 0; j < active.size(); ++j) active[j] = int(j);
  std::map<std::pair<int, int>, std::vector<Rgb>> weighted_phi;  // φ at eq. 7's position, per pair

  while (active.size() > 1) {
    // Candidate pairs.
    std::vector<std::pair<int, int>> pairs;
    if (active.size() <= settings.all_pairs_limit) {
      for (size_t a = 0; a < active.size(); ++a)
        for (size_t b = a + 1; b < active.size(); ++b) pairs.emplace_back(active[a], active[b]);
    } else {
      for (int a : active) {
        std::vector<std::pair<float, int>> d;
        for (int b : active)
          if (b != a) d.emplace_back(glm::length(h.m_nodes[a].position - h.m_nodes[b].position), b);
        size_t k = std::min(settings.neighbours, d.size());
        std::partial_sort(d.begin(), d.begin() + std::ptrdiff_t(k), d.end());
        for (size_t q = 0; q < k; ++q) pairs.emplace_back(std::min(a, d[q].second), std::max(a, d[q].second));
      }
      std::sort(pairs.begin(), pairs.end());
      pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    }
    // Eq. 7 positions whose φ is not known yet: one batch.
    std::vector<Vec3> weighted_pos(pairs.size());
    std::vector<char> weighted_allowed(pairs.size(), 1);
    Lighting missing;
    std::vector<size_t> missing_pair;
    for (size_t p = 0; p < pairs.size(); ++p) {
      const Cluster &a = h.m_nodes[pairs[p].first], &b = h.m_nodes[pairs[p].second];
      // Eq. 7 weights: ‖φ l‖ of each cluster.
      const double na = contribution(a.phi, 0, a.intensity, samples), nb = contribution(b.phi, 0, b.intensity, samples);
      weighted_pos[p] = na + nb > 0 ? Vec3((DVec3(a.position) * na + DVec3(b.position) * nb) / (na + nb))
                                    : 0.5f * (a.position + b.position);
      weighted_allowed[p] = !may_stand_at || may_stand_at(weighted_pos[p], a.position, b.position);
      if (weighted_allowed[p] && !weighted_phi.count(pairs[p])) {
        missing.push_back(Light::point(weighted_pos[p], Rgb(1.f)));
        missing_pair.push_back(p);
      }
    }
    if (!missing.empty()) {
      std::vector<Rgb> phi = model.responses(missing);
      for (size_t q = 0; q < missing.size(); ++q)
        weighted_phi[pairs[missing_pair[q]]].assign(phi.begin() + std::ptrdiff_t(q * m), phi.begin() + std::ptrdiff_t((q + 1) * m));
    }
    // ‖r + φ_a l_a + φ_b l_b − φ_x (l_a + l_b)‖² for x in {x_a, x_b, x_w}.
    std::vector<std::array<double, 3>> cost(pairs.size());
    tbb::parallel_for(size_t(0), pairs.size(), [&](size_t p) {
      const Cluster &a = h.m_nodes[pairs[p].first], &b = h.m_nodes[pairs[p].second];
      const std::vector<Rgb>& pw = weighted_allowed[p] ? weighted_phi.at(pairs[p]) : a.phi;  // (unused when not allowed)
      const DVec3 la(a.intensity), lb(b.intensity), lab = la + lb;
      std::array<double, 3> s = {0, 0, 0};
      for (size_t i = 0; i < m; ++i) {
        DVec3 base = r[i] + DVec3(a.phi[i]) * la + DVec3(b.phi[i]) * lb;
        DVec3 da = base - DVec3(a.phi[i]) * lab, db = base - DVec3(b.phi[i]) * lab, dw = base - DVec3(pw[i]) * lab;
        double w = samples.weight[i];
        s[0] += w * glm::dot(da, da);
        s[1] += w * glm::dot(db, db);
        s[2] += w * glm::dot(dw, dw);
      }
      if (!weighted_allowed[p]) s[2] = std::numeric_limits<double>::infinity();
      cost[p] = s;
    });
    size_t best_p = 0;
    int best_k = 0;
    for (size_t p = 0; p < pairs.size(); ++p)
      for (int k = 0; k < 3; ++k)
        if (cost[p][k] < cost[best_p][best_k]) best_p = p, best_k = k;

    const int ia = pairs[best_p].first, ib = pairs[best_p].second;
    Cluster merged;
    merged.left = ia;
    merged.right = ib;
    merged.intensity = h.m_nodes[ia].intensity + h.m_nodes[ib].intensity;
    if (best_k == 0) merged.position = h.m_nodes[ia].position, merged.phi = h.m_nodes[ia].phi;
    else if (best_k == 1) merged.position = h.m_nodes[ib].position, merged.phi = h.m_nodes[ib].phi;
    else merged.position = weighted_pos[best_p], merged.phi = weighted_phi.at(pairs[best_p]);
    subtract(h.m_nodes[ia].phi, h.m_nodes[ia].intensity, -1.0);
    subtract(h.m_nodes[ib].phi, h.m_nodes[ib].intensity, -1.0);
    subtract(merged.phi, merged.intensity, 1.0);
    h.m_nodes.push_back(std::move(merged));
    active.erase(std::remove_if(active.begin(), active.end(), [&](int x) { return x == ia || x == ib; }), active.end());
    active.push_back(int(h.m_nodes.size() - 1));
  }
  return h;
}

std::vector<int> LightHierarchy::cut(size_t k) const {
  if (m_nodes.empty()) return {};
  k = std::clamp<size_t>(k, 1, m_leaf_count);
  std::vector<int> cut = {int(m_nodes.size() - 1)};
  while (cut.size() < k) {
    // Split the latest-formed cluster in the cut (highest index with children).
    auto it = std::max_element(cut.begin(), cut.end(), [&](int a, int b) {
      bool ia = m_nodes[a].left >= 0, ib = m_nodes[b].left >= 0;
      return ia != ib ? !ia : a < b;
    });
    int node = *it;
    if (m_nodes[node].left < 0) break;
    cut.erase(it);
    cut.push_back(m_nodes[node].left);
    cut.push_back(m_nodes[node].right);
  }
  std::sort(cut.begin(), cut.end());
  return cut;
}

} // namespace hilight
