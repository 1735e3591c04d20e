#pragma once
// The walk over layouts of the design's places (illuminance_design.hpp):
// each layout's dimming by the linear program, fewer luminaires, spread
// apart, searched on the lattice.
#include "design_parts.hpp"

namespace hilight::design {

class Walker {
public:
  Walker(const Program& program, const std::vector<Place>& places, const std::vector<Field>& fields, std::vector<Footprint> outlines,
         SpacingRules rules, float plane_y, size_t observers)
      : m_program(program), m_places(places), m_fields(fields), m_outlines(std::move(outlines)), m_rules(rules), m_plane_y(plane_y),
        m_observers(observers), m_penalty(penalty(program)) {}

  /// Lights asked for by count are kept lit (dimmed no lower than this).
  void set_least_dimming(double least) { m_least = least; }

  Layout evaluate(std::vector<size_t> lights) const {
    LinearProgram lp;
    lp.rows = m_program.rows();
    lp.cols = lights.size();
    lp.a.assign(lp.rows * lp.cols, 0.0);
    for (size_t j = 0; j < lights.size(); ++j)
      for (size_t r = 0; r < lp.rows; ++r) lp.a[r * lp.cols + j] = m_program.column[lights[j]][r];
    lp.b = m_program.b;
    lp.c.assign(lp.cols, 1.0);
    lp.lo.assign(lp.cols, m_least);
    lp.hi.assign(lp.cols, 1.0);
    Layout out;
    const LpSolution s = solve_lp_with_slack(lp, m_penalty * double(std::max<size_t>(lights.size(), 1)), out.shortfall);
    if (!s.feasible) {  // numerical trouble only: count it as hopeless
      out.shortfall = 1e30;
      out.lights = std::move(lights);
      out.dimming.assign(out.lights.size(), std::max(m_least, 0.0));
      return out;
    }
    out.flux = s.objective;
    out.duals = s.duals;
    // Lights the program leaves dark are no lights.
    for (size_t j = 0; j < lights.size(); ++j)
      if (s.x[j] > 1e-6 || m_least > 0) {
        out.lights.push_back(lights[j]);
        out.dimming.push_back(std::max(s.x[j], m_least));
      }
    out.ugr = ugr(out);
    return out;
  }

  double ugr(const Layout& l) const {
    if (!m_observers) return kNaN;
    std::vector<const Field*> f;
    for (size_t c : l.lights) f.push_back(&m_fields[c]);
    return layout_ugr(f, l.dimming, m_observers);
  }

  /// One light fewer: the weakest deleted, or merged with its nearest at
  /// their dimming-weighted place (eq. 7), whichever the program likes better.
  Layout fewer(const Layout& from) const {
    if (from.lights.empty()) return from;
    const size_t w = size_t(std::min_element(from.dimming.begin(), from.dimming.end()) - from.dimming.begin());
    std::vector<size_t> deleted = from.lights;
    deleted.erase(deleted.begin() + long(w));
    Layout best = evaluate(deleted);
    size_t n = w;
    float nearest = std::numeric_limits<float>::max();
    for (size_t j = 0; j < from.lights.size(); ++j) {
      const float d = glm::length(position(from.lights[j]) - position(from.lights[w]));
      if (j != w && d < nearest) nearest = d, n = j;
    }
    if (n != w) {
      const double a = from.dimming[w], b = from.dimming[n];
      const Vec3 at = (float(a) * position(from.lights[w]) + float(b) * position(from.lights[n])) / float(a + b);
      const size_t merged = closest(at, m_places[from.lights[a > b ? w : n]].turn);
      std::vector<size_t> lights;
      for (size_t j = 0; j < from.lights.size(); ++j)
        if (j != w && j != n) lights.push_back(from.lights[j]);
      if (std::find(lights.begin(), lights.end(), merged) == lights.end()) {
        lights.push_back(merged);
        Layout m = evaluate(lights);
        if (m.better_than(best)) best = std::move(m);
      }
    }
    return best;
  }

  /// Moves lights to lattice neighbours (and other spins) while the
  /// program's duals say a neighbour is cheaper and the program agrees;
  /// never where a luminaire would come too close to another.
  Layout search(Layout layout, int passes = 6) const {
    for (int pass = 0; pass < passes; ++pass) {
      bool moved = false;
      for (size_t l = 0; l < layout.lights.size(); ++l) {
        const size_t from = layout.lights[l];
        // Reduced cost of a neighbour: its flux less what its rows are worth.
        size_t best = from;
        double best_cost = reduced_cost(layout, from) - 1e-9;
        for (size_t m : neighbours(from)) {
          if (std::find(layout.lights.begin(), layout.lights.end(), m) != layout.lights.end()) continue;
          if (!fits(m, layout.lights, l)) continue;
          const double rc = reduced_cost(layout, m);
          if (rc < best_cost) best_cost = rc, best = m;
        }
        if (best == from) continue;
        std::vector<size_t> lights = layout.lights;
        lights[l] = best;
        Layout tried = evaluate(lights);
        if (tried.better_than(layout)) {
          layout = std::move(tried);
          moved = true;
        }
      }
      if (!moved) break;
    }
    return layout;
  }

  /// The layout with luminaires that come too close moved apart: the
  /// brightest keep their places, each other goes to the nearest place
  /// that keeps its distance from those kept; the program then dims them.
  Layout spread(const Layout& from) const {
    std::vector<size_t> order(from.lights.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return from.dimming[a] > from.dimming[b]; });
    std::vector<size_t> kept;
    for (size_t k : order) {
      const size_t c = from.lights[k];
      if (fits(c, kept)) {
        kept.push_back(c);
        continue;
      }
      // The nearest place that keeps its distance from those kept (nearest first, so the first that fits).
      std::vector<std::pair<float, size_t>> by_distance;
      by_distance.reserve(m_places.size());
      for (size_t m = 0; m < m_places.size(); ++m) {
        const Vec3 d = m_places[m].position - m_places[c].position;
        by_distance.push_back({glm::dot(d, d), m});
      }
      std::sort(by_distance.begin(), by_distance.end());
      for (const auto& [d2, m] : by_distance)
        if (fits(m, kept)) {
          kept.push_back(m);
          break;
        }
    }
    return evaluate(kept);
  }

  /// Every pair keeps the spacing rules, and no luminaire is farther from
  /// its nearest than the spacing-to-height ratio allows.
  bool feasible(const Layout& l) const {
    for (size_t a = 0; a < l.lights.size(); ++a)
      for (size_t b = a + 1; b < l.lights.size(); ++b)
        if (too_close(m_outlines[l.lights[a]], m_outlines[l.lights[b]], m_rules)) return false;
    if (m_rules.max_spacing_ratio > 0 && l.lights.size() > 1)
      for (size_t a = 0; a < l.lights.size(); ++a) {
        float nearest = std::numeric_limits<float>::max();
        for (size_t b = 0; b < l.lights.size(); ++b)
          if (a != b) nearest = std::min(nearest, horizontal_distance(l.lights[a], l.lights[b]));
        const double h = double(m_places[l.lights[a]].position.y - m_plane_y);
        if (double(nearest) > m_rules.max_spacing_ratio * h + 1e-6) return false;
      }
    return true;
  }

  /// The place of the lattice farthest from every light (keeping the spacing), or none.
  std::optional<size_t> farthest(const std::vector<size_t>& lights) const {
    std::optional<size_t> best;
    float far = -1.f;
    for (size_t m = 0; m < m_places.size(); ++m) {
      if (std::find(lights.begin(), lights.end(), m) != lights.end() || !fits(m, lights)) continue;
      float nearest = std::numeric_limits<float>::max();
      for (size_t c : lights) nearest = std::min(nearest, horizontal_distance(m, c));
      if (nearest > far) far = nearest, best = m;
    }
    return best;
  }

private:
  static double penalty(const Program& p) {
    // Falling short by one lux must cost more than any light's flux can
    // save: a light at full output is 1, so more than 1 per lux of the largest bound.
    const double largest = std::max(1.0, *std::max_element(p.b.begin(), p.b.end()));
    return 1e3 / largest;
  }
  Vec3 position(size_t c) const { return m_places[c].position; }
  float horizontal_distance(size_t a, size_t b) const {
    const Vec3 d = m_places[a].position - m_places[b].position;
    return std::hypot(d.x, d.z);
  }
  /// Place `m` keeps the spacing rules with every light but the `skip`-th.
  bool fits(size_t m, const std::vector<size_t>& lights, size_t skip = size_t(-1)) const {
    for (size_t k = 0; k < lights.size(); ++k)
      if (k != skip && too_close(m_outlines[m], m_outlines[lights[k]], m_rules)) return false;  // a place taken is too close to itself
    return true;
  }
  double reduced_cost(const Layout& layout, size_t c) const {
    if (layout.duals.empty()) return 0;
    double worth = 0;
    for (size_t r = 0; r < layout.duals.size(); ++r) worth += layout.duals[r] * m_program.column[c][r];
    return 1.0 - worth;
  }
  size_t closest(const Vec3& p, float turn) const {
    size_t best = 0;
    float d2 = std::numeric_limits<float>::max();
    for (size_t c = 0; c < m_places.size(); ++c) {
      if (m_places[c].turn != turn) continue;
      const Vec3 d = m_places[c].position - p;
      if (glm::dot(d, d) < d2) d2 = glm::dot(d, d), best = c;
    }
    return best;
  }
  std::vector<size_t> neighbours(size_t c) const {
    std::vector<size_t> out;
    const glm::ivec4 at = m_places[c].cell;
    for (size_t m = 0; m < m_places.size(); ++m) {
      const glm::ivec4 d = glm::abs(m_places[m].cell - at);
      const bool beside = d.w == 0 && std::max({d.x, d.y, d.z}) == 1;
      const bool turned = d.w != 0 && d.x == 0 && d.y == 0 && d.z == 0;
      if (beside || turned) out.push_back(m);
    }
    return out;
  }

  const Program& m_program;
  const std::vector<Place>& m_places;
  const std::vector<Field>& m_fields;
  std::vector<Footprint> m_outlines;
  SpacingRules m_rules;
  float m_plane_y;
  size_t m_observers;
  double m_penalty;
  double m_least = 0;
};

} // namespace hilight::design
