#include "cell_refiner.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tbb/parallel_for.h>

namespace hilight::adaptive {

namespace {

float luminance(const Rgb& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

uint64_t key(const glm::ivec3& q) { return uint64_t(q.x) | uint64_t(q.y) << 21 | uint64_t(q.z) << 42; }

/// A cell of the frontier (the newest level) and what is known of it.
struct Candidate {
  size_t cell = 0;
  double priority = 0;  ///< its parent's error: children of the worst cells are tested first
  double error = -1;    ///< the blend's relative error at its centre; −1: not tested
  int test = -1;        ///< index of its traced centre in the level's tests
};

class Refiner {
public:
  Refiner(const LightCacheScene& in, const RefineSettings& settings, CellTree& tree, NodeResponses& nodes)
      : m_in(in), m_settings(settings), m_tree(tree), m_nodes(nodes), m_clearance(1e-3f * in.scene.diagonal()) {}

  void run() {
    make_base_cells();
    std::vector<Candidate> frontier;
    for (size_t i = 0; i < m_tree.cells.size(); ++i) frontier.push_back({i, 1.0});
    add_corners(frontier);
    m_budget = size_t(m_settings.growth * double(m_nodes.count()));
    for (int level = 0; level <= m_tree.depth && !frontier.empty(); ++level) {
      test_centres(frontier, level);
      if (level == m_tree.depth) {
        keep_centres(frontier);  // the deepest level is only tested: its centres become centre nodes
        break;
      }
      frontier = split_worst(frontier);
    }
  }

private:
  void make_base_cells() {
    const Vec3 extent = m_in.bounds.extent();
    const float longest = std::max({extent.x, extent.y, extent.z});
    m_tree.depth = m_settings.depth;
    // The base lattice is the grid cache's: nodes at the centres of `cells`
    // cells along the longest axis, half a cell from the bounding walls
    // (a node nearer a wall sees the wall's near field, which a blend would
    // spread over the whole cell); base cells span neighbouring nodes.
    for (int k = 0; k < 3; ++k) {
      const int nodes = std::max(1, int(std::ceil(extent[k] / (longest / float(m_settings.cells)) - 1e-4f)));
      const float spacing = extent[k] / float(nodes);
      m_tree.origin[k] = m_in.bounds.lo[k] + 0.5f * spacing;
      m_tree.base_cells[k] = std::max(1, nodes - 1);
      m_tree.base_size[k] = nodes > 1 ? spacing : 1e-4f * longest;  // one layer: its two corner layers coincide
    }
    m_nodes = NodeResponses(m_in.scene.positions.size());
    const int span = m_tree.cell_span(0);
    for (int z = 0; z < m_tree.base_cells.z; ++z)
      for (int y = 0; y < m_tree.base_cells.y; ++y)
        for (int x = 0; x < m_tree.base_cells.x; ++x) {
          Cell c;
          c.lo = glm::ivec3(x, y, z) * span;
          m_tree.cells.push_back(c);
        }
  }

  glm::ivec3 corner_of(const Cell& c, int corner) const {
    return c.lo + glm::ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1) * m_tree.cell_span(c.level);
  }
  glm::ivec3 centre_of(const Cell& c) const { return c.lo + glm::ivec3(m_tree.cell_span(c.level) / 2); }
  bool free(const glm::ivec3& q) const { return node_is_free(m_in.rays, m_tree.position(q), m_clearance); }
  size_t traced() const { return m_nodes.count() + m_tests.count(); }

  /// Makes nodes of the cells' corners that are not nodes yet (the free ones
  /// traced in one batch, or taken from this level's tests when a corner is a
  /// centre traced already), and gives the cells their corner slots.
  void add_corners(const std::vector<Candidate>& cells) {
    std::map<uint64_t, glm::ivec3> wanted;
    for (const auto& c : cells)
      for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 q = corner_of(m_tree.cells[c.cell], corner);
        if (!m_slot.count(key(q))) wanted.emplace(key(q), q);
      }
    std::vector<glm::ivec3> points;
    for (const auto& [k, q] : wanted) points.push_back(q);
    std::vector<uint8_t> is_free(points.size());
    tbb::parallel_for(size_t(0), points.size(), [&](size_t i) { is_free[i] = free(points[i]); });
    std::vector<Vec3> to_trace;
    std::vector<uint64_t> traced_keys;
    for (size_t i = 0; i < points.size(); ++i) {
      const uint64_t k = key(points[i]);
      if (!is_free[i]) {
        m_slot[k] = kNoNode;
      } else if (const auto test = m_test_of.find(k); test != m_test_of.end()) {
        m_slot[k] = uint32_t(m_nodes.count());
        m_nodes.append(m_tests, test->second);
      } else {
        to_trace.push_back(m_tree.position(points[i]));
        traced_keys.push_back(k);
      }
    }
    for (size_t j = 0; j < traced_keys.size(); ++j) m_slot[traced_keys[j]] = uint32_t(m_nodes.count() + j);
    m_nodes.trace(m_in.scene, m_in.renderer, to_trace);
    for (const auto& c : cells)
      for (int corner = 0; corner < 8; ++corner) m_tree.cells[c.cell].corner[corner] = m_slot.at(key(corner_of(m_tree.cells[c.cell], corner)));
  }

  /// Traces the centres of the frontier's cells (those of the worst parents
  /// first, as many as half the budget left allows) and measures each
  /// cell's blend against it.
  void test_centres(std::vector<Candidate>& frontier, int level) {
    m_tests = NodeResponses(m_in.scene.positions.size());
    m_test_of.clear();
    std::stable_sort(frontier.begin(), frontier.end(), [](const Candidate& a, const Candidate& b) { return a.priority > b.priority; });
    const size_t left = m_budget > m_nodes.count() ? m_budget - m_nodes.count() : 0;
    // Half of what is left, so that splits can still be paid for; all of it at the deepest level.
    const size_t allowed = level == m_tree.depth ? left : left / 2;
    std::vector<Vec3> centres;
    for (auto& c : frontier) {
      if (centres.size() >= allowed) break;
      const glm::ivec3 q = centre_of(m_tree.cells[c.cell]);
      if (!free(q)) continue;
      c.test = int(centres.size());
      m_test_of[key(q)] = centres.size();
      centres.push_back(m_tree.position(q));
    }
    m_tests.trace(m_in.scene, m_in.renderer, centres);
    const size_t vc = m_in.scene.positions.size();
    tbb::parallel_for(size_t(0), frontier.size(), [&](size_t j) {
      Candidate& c = frontier[j];
      const Cell& cell = m_tree.cells[c.cell];
      if (c.test < 0) {
        // Centre in a solid (a slab, a wall) between free corners: the blend
        // mixes what the solid separates, so the cell is worth splitting.
        bool any_free = false;
        for (uint32_t s : cell.corner) any_free |= s != kNoNode;
        c.error = any_free && !free(centre_of(cell)) ? 1.0 : -1.0;
        return;
      }
      uint32_t slots[8];
      int used = 0;
      for (uint32_t s : cell.corner)
        if (s != kNoNode) slots[used++] = s;
      double wrong = 0, total = 0;
      // A block of vertices at a time, each node unpacked once.
      std::vector<Rgb> exact(NodeResponses::kBlock), blended(NodeResponses::kBlock), corner(NodeResponses::kBlock);
      for (size_t block = 0; block < m_tests.blocks(); ++block) {
        const size_t n = std::min(NodeResponses::kBlock, vc - block * NodeResponses::kBlock);
        m_tests.block_values(size_t(c.test), block, exact.data());
        std::fill_n(blended.begin(), n, Rgb(0.f));
        for (int k = 0; k < used; ++k) {
          m_nodes.block_values(slots[k], block, corner.data());
          for (size_t v = 0; v < n; ++v) blended[v] += corner[v];
        }
        for (size_t v = 0; v < n; ++v) {
          if (used) blended[v] /= float(used);
          wrong += std::abs(double(luminance(exact[v])) - double(luminance(blended[v])));
          total += double(luminance(exact[v]));
        }
      }
      c.error = total > 0 ? wrong / total : (wrong > 0 ? 1.0 : 0.0);
    });
  }

  /// Splits the frontier's cells whose blend is wrong, worst first, while
  /// the budget lasts; the cells not split keep their traced centre as a
  /// centre node. Returns the new cells (the next frontier).
  std::vector<Candidate> split_worst(std::vector<Candidate>& frontier) {
    std::stable_sort(frontier.begin(), frontier.end(), [](const Candidate& a, const Candidate& b) { return a.error > b.error; });
    std::vector<Candidate> children;
    std::map<uint64_t, bool> planned;  // lattice points the chosen splits add → free
    size_t fresh_traced = 0;           // of them, those to trace (free and not a tested centre)
    for (auto& c : frontier) {
      if (c.error <= m_settings.tolerance) break;
      const Cell p = m_tree.cells[c.cell];
      const int half = m_tree.cell_span(p.level) / 2;
      size_t cost = 0;
      std::vector<std::pair<uint64_t, bool>> fresh;
      for (int z = 0; z <= 2; ++z)
        for (int y = 0; y <= 2; ++y)
          for (int x = 0; x <= 2; ++x) {
            const glm::ivec3 q = p.lo + glm::ivec3(x, y, z) * half;
            if (m_slot.count(key(q)) || planned.count(key(q))) continue;
            const bool is_free = free(q);
            fresh.emplace_back(key(q), is_free);
            cost += is_free && !m_test_of.count(key(q));
          }
      if (traced() + fresh_traced + cost > m_budget) continue;  // a cheaper split may still fit
      fresh_traced += cost;
      planned.insert(fresh.begin(), fresh.end());
      m_tree.cells[c.cell].first_child = int32_t(m_tree.cells.size());
      for (int child = 0; child < 8; ++child) {
        Cell k;
        k.level = p.level + 1;
        k.lo = p.lo + glm::ivec3(child & 1, (child >> 1) & 1, (child >> 2) & 1) * half;
        children.push_back({m_tree.cells.size(), c.error});
        m_tree.cells.push_back(k);
      }
    }
    add_corners(children);
    keep_centres(frontier);
    return children;
  }

  /// Tested centres of cells left unsplit become their centre nodes (the
  /// centres of split cells became corners of their children).
  void keep_centres(const std::vector<Candidate>& cells) {
    for (const auto& c : cells) {
      Cell& cell = m_tree.cells[c.cell];
      if (c.test < 0 || cell.first_child >= 0) continue;
      cell.centre = uint32_t(m_nodes.count());
      m_nodes.append(m_tests, size_t(c.test));
    }
    m_tests = NodeResponses(m_in.scene.positions.size());
    m_test_of.clear();
  }

  const LightCacheScene& m_in;
  const RefineSettings& m_settings;
  CellTree& m_tree;
  NodeResponses& m_nodes;
  float m_clearance;
  size_t m_budget = 0;  ///< traced lights in all
  std::map<uint64_t, uint32_t> m_slot;   ///< lattice point → node slot (kNoNode: not free)
  NodeResponses m_tests;                 ///< this level's traced centres
  std::map<uint64_t, size_t> m_test_of;  ///< lattice point → index in m_tests
};

} // namespace

void refine_cells(const LightCacheScene& in, const RefineSettings& settings, CellTree& tree, NodeResponses& nodes) {
  Refiner(in, settings, tree, nodes).run();
}

} // namespace hilight::adaptive
