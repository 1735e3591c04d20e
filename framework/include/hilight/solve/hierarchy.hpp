#pragma once
/// The light hierarchy (paper §3.3, Fig. 3): bottom-up, the pair of clusters
/// whose merge leaves the least difference to the target is merged, at the
/// best of three positions (eq. 7), with l_new = l_a + l_b, until one remains.
///
/// Speed trade: with more than `all_pairs_limit` clusters only each cluster's
/// `neighbours` nearest clusters are candidate partners (distant lights are
/// rarely the best merge, and the pair count falls from O(n²) to O(n·k)); the
/// residual is updated incrementally and each pair's weighted-position φ is
/// computed once and kept, since clusters never change after they form.
///
/// Rooms: eq. 7's weighted position of two clusters in different rooms can
/// fall in the wall between them or in a third room; `may_stand_at(x, a, b)`
/// (the solver: x is a free light position in a's or b's region) keeps such
/// an x out of the candidates, so a merge across rooms puts the light where
/// one of the two stood — and, like every merge, happens only when it
/// explains the target best of all merges left.
#include "hilight/solve/responses.hpp"

#include <functional>
#include <vector>

namespace hilight {

struct HierarchySettings {
  size_t all_pairs_limit = 24;
  size_t neighbours = 8;
};

struct Cluster {
  Vec3 position;
  Rgb intensity;
  std::vector<Rgb> phi;  ///< unit response at the samples
  int left = -1, right = -1;  ///< children (-1: a leaf)
};

class LightHierarchy {
public:
  /// `leaves`: the seed's point lights with their φ; `fixed_phi`/`fixed_l`:
  /// lights that never merge (spots), part of every cut's illumination.
  using MayStandAt = std::function<bool(const Vec3& merged, const Vec3& a, const Vec3& b)>;
  static LightHierarchy build(ResponseModel& model, const Lighting& leaves, const std::vector<Rgb>& leaf_phi,
                              const std::vector<Rgb>& fixed_phi, const std::vector<Rgb>& fixed_intensity,
                              const HierarchySettings& settings = {}, const MayStandAt& may_stand_at = {});

  size_t leaf_count() const { return m_leaf_count; }
  const std::vector<Cluster>& nodes() const { return m_nodes; }
  /// The cut with `k` clusters (1 ≤ k ≤ leaf_count): the root split in
  /// reverse merge order (the latest-formed cluster first). Node indices.
  std::vector<int> cut(size_t k) const;

private:
  std::vector<Cluster> m_nodes;  ///< leaves first, then merges in order
  size_t m_leaf_count = 0;
};

} // namespace hilight
