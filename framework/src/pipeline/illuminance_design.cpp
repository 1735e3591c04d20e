// Lights for illuminance criteria: candidates, the linear program, the count
// walk and the lattice search (pipeline/illuminance_design.hpp).
#include "hilight/pipeline/illuminance_design.hpp"

#include "hilight/error.hpp"
#include "hilight/pipeline/linear_program.hpp"
#include "hilight/units.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

namespace hilight {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Candidate {
  Vec3 position;
  float spin = 0.f;
  glm::ivec4 cell{0};  ///< lattice x, layer, z, spin index
};

/// The program's rows, one column per candidate: per grid, its mean
/// (Ē ≥ lux, with a hair of margin so that rounding never misses it) and,
/// with u0 > 0, per point E_i − u0·Ē ≥ 0.
struct Program {
  std::vector<double> b;
  std::vector<std::vector<double>> column;  ///< per candidate, per row
  size_t rows() const { return b.size(); }
};

Program make_program(const IlluminanceCriteria& criteria, const std::vector<std::vector<double>>& lux_at) {
  Program p;
  for (const auto& g : criteria.grids) {
    p.b.push_back(g.lux * (1.0 + 1e-4));
    if (g.u0 > 0) p.b.insert(p.b.end(), g.points.size(), 0.0);
  }
  for (const auto& e : lux_at) {
    std::vector<double> col;
    col.reserve(p.b.size());
    size_t first = 0;
    for (const auto& g : criteria.grids) {
      const size_t n = g.points.size();
      const double mean = std::accumulate(e.begin() + long(first), e.begin() + long(first + n), 0.0) / double(n);
      col.push_back(mean);
      if (g.u0 > 0)
        for (size_t i = 0; i < n; ++i) col.push_back(e[first + i] - g.u0 * mean);
      first += n;
    }
    p.column.push_back(std::move(col));
  }
  return p;
}

/// A layout: which candidates, their dimming, its flux (in luminaires at
/// full output) and how far it falls short of the criteria (lux, summed).
struct Layout {
  std::vector<size_t> lights;
  std::vector<double> dimming;
  std::vector<double> duals;
  double flux = 0, shortfall = 0;
  /// Falls short by no more than `other` (a hair of rounding allowed).
  bool as_met_as(const Layout& o) const { return shortfall <= o.shortfall * (1 + 1e-3) + 1e-6; }
  /// Better: falls shorter of the criteria, else as short with less flux.
  bool better_than(const Layout& o) const {
    if (!as_met_as(o)) return false;
    if (!o.as_met_as(*this)) return true;
    return flux < o.flux * (1 - 1e-7);
  }
};

class Walker {
public:
  Walker(const Program& program, const std::vector<Candidate>& candidates)
      : m_program(program), m_candidates(candidates), m_penalty(penalty(program)) {}

  Layout evaluate(std::vector<size_t> lights) const {
    LinearProgram lp;
    lp.rows = m_program.rows();
    lp.cols = lights.size();
    lp.a.assign(lp.rows * lp.cols, 0.0);
    for (size_t j = 0; j < lights.size(); ++j)
      for (size_t r = 0; r < lp.rows; ++r) lp.a[r * lp.cols + j] = m_program.column[lights[j]][r];
    lp.b = m_program.b;
    lp.c.assign(lp.cols, 1.0);
    lp.lo.assign(lp.cols, 0.0);
    lp.hi.assign(lp.cols, 1.0);
    Layout out;
    const LpSolution s = solve_lp_with_slack(lp, m_penalty * double(std::max<size_t>(lights.size(), 1)), out.shortfall);
    if (!s.feasible) {  // numerical trouble only: count it as hopeless
      out.shortfall = 1e30;
      out.lights = std::move(lights);
      out.dimming.assign(out.lights.size(), 0.0);
      return out;
    }
    out.flux = s.objective;
    out.duals = s.duals;
    // Lights the program leaves dark are no lights.
    for (size_t j = 0; j < lights.size(); ++j)
      if (s.x[j] > 1e-6) {
        out.lights.push_back(lights[j]);
        out.dimming.push_back(s.x[j]);
      }
    return out;
  }

  /// One light fewer: the weakest deleted, or merged with its nearest at
  /// their dimming-weighted place (eq. 7), whichever the program likes better.
  Layout fewer(const Layout& from) const {
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
      const size_t merged = closest(at, m_candidates[from.lights[a > b ? w : n]].spin);
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
  /// program's duals say a neighbour is cheaper and the program agrees.
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

private:
  static double penalty(const Program& p) {
    // Falling short by one lux must cost more than any light's flux can
    // save: a light at full output is 1, so more than 1 per lux of the largest bound.
    const double largest = std::max(1.0, *std::max_element(p.b.begin(), p.b.end()));
    return 1e3 / largest;
  }
  Vec3 position(size_t c) const { return m_candidates[c].position; }
  double reduced_cost(const Layout& layout, size_t c) const {
    if (layout.duals.empty()) return 0;
    double worth = 0;
    for (size_t r = 0; r < layout.duals.size(); ++r) worth += layout.duals[r] * m_program.column[c][r];
    return 1.0 - worth;
  }
  size_t closest(const Vec3& p, float spin) const {
    size_t best = 0;
    float d2 = std::numeric_limits<float>::max();
    for (size_t c = 0; c < m_candidates.size(); ++c) {
      if (m_candidates[c].spin != spin) continue;
      const Vec3 d = m_candidates[c].position - p;
      if (glm::dot(d, d) < d2) d2 = glm::dot(d, d), best = c;
    }
    return best;
  }
  std::vector<size_t> neighbours(size_t c) const {
    std::vector<size_t> out;
    const glm::ivec4 at = m_candidates[c].cell;
    for (size_t m = 0; m < m_candidates.size(); ++m) {
      const glm::ivec4 d = glm::abs(m_candidates[m].cell - at);
      const bool beside = d.w == 0 && std::max({d.x, d.y, d.z}) == 1;
      const bool turned = d.w != 0 && d.x == 0 && d.y == 0 && d.z == 0;
      if (beside || turned) out.push_back(m);
    }
    return out;
  }

  const Program& m_program;
  const std::vector<Candidate>& m_candidates;
  double m_penalty;
};

std::vector<Candidate> make_candidates(const LightSpace& space, const Light& luminaire, const IlluminanceCriteria& criteria,
                                       const DesignSettings& settings) {
  Bounds area;
  double finest = std::numeric_limits<double>::max();
  float plane = -std::numeric_limits<float>::max();
  for (const auto& g : criteria.grids) {
    for (const Vec3& p : g.points) area.extend(p);
    if (g.spacing > 0) finest = std::min(finest, g.spacing);
    if (g.kind == CriterionGrid::Kind::WorkPlane)
      for (const Vec3& p : g.points) plane = std::max(plane, p.y);
  }
  if (plane == -std::numeric_limits<float>::max()) plane = area.center().y;
  const float step = settings.candidate_spacing > 0                  ? float(settings.candidate_spacing)
                     : finest < std::numeric_limits<double>::max() ? float(finest / 3.0)
                                                                   : area.diagonal() / 20.f;
  if (!(step > 0.f)) throw InputError("the criteria's points are all in one place: no room to spread luminaires");
  const Vec3 lo = area.lo - Vec3(step), e = area.extent() + Vec3(2.f * step);
  const int nx = int(std::floor(e.x / step)) + 1, nz = int(std::floor(e.z / step)) + 1;
  if (double(nx) * nz > 4e4) throw InputError("--candidate-spacing " + std::to_string(step) + " makes over 40,000 places: give a larger one");
  // On a ceiling mount one layer; else three between the work plane and the top of the space.
  std::vector<float> layers;
  if (space.rules().ceiling_offset) {
    layers = {plane + 1e-3f};
  } else {
    const float bottom = std::max(space.bounds().lo.y, plane + step), top = space.bounds().hi.y - 1e-3f;
    for (int k = 0; k < 3; ++k) layers.push_back(bottom + (top - bottom) * float(k + 1) / 3.f);
  }
  const std::vector<float> spins = distinct_spins(*luminaire.profile);
  std::vector<Candidate> out;
  for (int iz = 0; iz < nz; ++iz)
    for (size_t iy = 0; iy < layers.size(); ++iy)
      for (int ix = 0; ix < nx; ++ix) {
        const auto at = space.place(Vec3(lo.x + float(ix) * step, layers[iy], lo.z + float(iz) * step));
        if (!at || !space.admissible(*at)) continue;
        for (size_t s = 0; s < spins.size(); ++s)
          out.push_back({*at, luminaire.spin_deg + spins[s], glm::ivec4(ix, int(iy), iz, int(s))});
      }
  return out;
}

} // namespace

Lighting design_for_illuminance(Renderer& reference, const LightSpace& space, const Light& luminaire,
                                const IlluminanceCriteria& criteria, const DesignSettings& settings, DesignReport& report) {
  if (luminaire.type != LightType::Luminaire || !luminaire.profile)
    throw InputError("illuminance criteria need a luminaire (--luminaire FILE)");
  const Photometry& profile = *luminaire.profile;
  const double peak = profile.peak(), rated = profile.flux();
  auto light_at = [&](const Candidate& c, double dimming) {
    Light l = luminaire;
    l.position = c.position;
    l.spin_deg = c.spin;
    l.intensity = Rgb(float(dimming * peak / kLumensPerWatt));
    return l;
  };
  const auto t0 = Clock::now();
  std::vector<Candidate> candidates = make_candidates(space, luminaire, criteria, settings);
  if (candidates.empty())
    throw InputError("no place for a luminaire over the criteria's area (" + space.rules().describe() +
                     "): give --place rules that leave room");
  // Every candidate's illuminance at every point, at full output.
  const SurfacePoints points = criteria.points();
  Lighting unit;
  for (const auto& c : candidates) unit.push_back(light_at(c, kLumensPerWatt / peak));
  const std::vector<Rgb> phi = reference.unit_responses(points, unit);
  std::vector<Candidate> useful;
  std::vector<std::vector<double>> lux_at;
  for (size_t j = 0; j < candidates.size(); ++j) {
    std::vector<double> e = lux_from_radiance(std::span<const Rgb>(phi.data() + j * points.size(), points.size()));
    for (double& v : e) v *= peak / kLumensPerWatt;  // φ is for 1 W/sr at the peak; full output is peak/683
    if (*std::max_element(e.begin(), e.end()) <= 0) continue;  // lights no point: another room
    useful.push_back(candidates[j]);
    lux_at.push_back(std::move(e));
  }
  report.candidates = useful.size();
  report.seconds["candidates"] = since(t0);
  if (useful.empty()) throw InputError("no place a luminaire may stand lights any of the criteria's points");

  const auto t1 = Clock::now();
  const Program program = make_program(criteria, lux_at);
  const Walker walker(program, useful);
  std::vector<size_t> all(useful.size());
  std::iota(all.begin(), all.end(), size_t(0));
  const Layout bound = walker.evaluate(all);
  report.least_flux_lm = bound.flux * rated;
  report.shortfall_lux = bound.shortfall;
  Layout chosen = bound;
  {
    // Criteria that cannot be met are met as nearly as the bound meets them.
    const double allowed = bound.flux * (1.0 + settings.energy_tolerance);
    const auto acceptable = [&](const Layout& l) {
      return l.as_met_as(bound) && l.flux <= allowed && l.lights.size() >= std::max<size_t>(settings.min_count, 1);
    };
    // Walk down from the program's lights, coarsely while there are many.
    Layout at = bound;
    const size_t least = size_t(std::ceil(bound.flux - 1e-9));
    while (at.lights.size() > 2 * least + 8) {
      std::vector<size_t> order(at.lights.size());
      std::iota(order.begin(), order.end(), size_t(0));
      std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return at.dimming[a] > at.dimming[b]; });
      std::vector<size_t> kept;
      for (size_t k = 0; k < order.size() - order.size() / 4; ++k) kept.push_back(at.lights[order[k]]);
      Layout next = walker.evaluate(kept);
      if (!acceptable(next)) break;
      at = std::move(next);
      report.walk.push_back({at.lights.size(), at.flux * rated});
    }
    chosen = at;
    int misses = 0;
    while (at.lights.size() > std::max<size_t>(settings.min_count, 1) && misses < 3) {
      at = walker.fewer(at);
      if (at.as_met_as(bound)) report.walk.push_back({at.lights.size(), at.flux * rated});
      if (acceptable(at)) {
        chosen = at;
        misses = 0;
      } else {
        ++misses;
      }
    }
    // Move the chosen lights on the lattice, then see whether fewer still do.
    chosen = walker.search(chosen);
    while (chosen.lights.size() > std::max<size_t>(settings.min_count, 1)) {
      Layout next = walker.search(walker.fewer(chosen));
      if (!acceptable(next)) break;
      chosen = std::move(next);
      report.walk.push_back({chosen.lights.size(), chosen.flux * rated});
    }
  }
  if (settings.max_count > 0 && chosen.lights.size() > settings.max_count) {
    while (chosen.lights.size() > settings.max_count) chosen = walker.search(walker.fewer(chosen));
  }
  report.seconds["program"] = since(t1);

  // The lights found, measured as `hilight render` would.
  const auto t2 = Clock::now();
  Lighting lights;
  for (size_t j = 0; j < chosen.lights.size(); ++j) lights.push_back(light_at(useful[chosen.lights[j]], chosen.dimming[j]));
  report.lux = lux_from_radiance(reference.illuminate(points, lights));
  report.met = true;
  size_t first = 0;
  for (const auto& g : criteria.grids) {
    report.figures.push_back(grid_figures(g, std::span<const double>(report.lux.data() + first, g.points.size())));
    report.met = report.met && report.figures.back().met;
    first += g.points.size();
  }
  report.flux_lm = 0;
  report.power_w = 0;
  for (size_t j = 0; j < lights.size(); ++j) {
    report.flux_lm += chosen.dimming[j] * rated;
    report.power_w += chosen.dimming[j] * profile.input_watts;
  }
  report.seconds["measure"] = since(t2);
  report.seconds["total"] = since(t0);
  return lights;
}

} // namespace hilight
