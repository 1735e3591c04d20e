// Lights for illuminance criteria: candidates, the linear program, the count
// walk, the lattice search and the arrays (solve/illuminance_design.hpp).
#include "hilight/solve/illuminance_design.hpp"

#include "hilight/error.hpp"
#include "hilight/solve/linear_program.hpp"
#include "hilight/units.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <set>
#include <unordered_set>

namespace hilight {

const char* to_string(DesignSettings::Posture posture) { return posture == DesignSettings::Posture::Standing ? "standing" : "seated"; }

const char* to_string(LayoutChoice choice) {
  switch (choice) {
    case LayoutChoice::Auto: return "auto";
    case LayoutChoice::Array: return "array";
    case LayoutChoice::Free: return "free";
  }
  return "?";
}

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// A luminaire asked for by count is never dimmed below this (a dark one is no luminaire).
constexpr double kLeastDimming = 0.1;

std::string metres(double v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f", v);
  return text;
}

struct Place {
  Vec3 position;
  float turn = 0.f;                 ///< degrees from the template, about its aim
  glm::ivec4 cell{-1, -1, -1, -1};  ///< lattice x, layer, z, spin index (arrays: none)
};

/// Where every place's light is rendered: the criteria's points (grid after
/// grid), then per grid the points between them (with a margin), then the
/// observers' eyes (vertical, facing the view).
struct Points {
  SurfacePoints all;
  size_t criteria = 0;
  std::vector<std::pair<size_t, size_t>> between;  ///< per grid: first, count in `all`
  size_t eyes_first = 0;
  /// With an Ēz criterion: after the eyes, 4 points a place of the cylinder
  /// (vertical, facing ±x and ±z), `cylinders` of them.
  size_t cylinders_first = 0, cylinders = 0;
};

/// The cylinders Ēz is taken at: over the work planes' points at `height`
/// above the floor, out of solids.
std::vector<Vec3> cylinder_places(const RayScene& rays, const IlluminanceCriteria& criteria, float floor_y, float height) {
  std::vector<Vec3> out;
  for (const auto& g : criteria.grids)
    if (g.kind == CriterionGrid::Kind::WorkPlane)
      for (const Vec3& p : g.points) {
        const Vec3 at(p.x, floor_y + height, p.z);
        if (!rays.inside_solid(at)) out.push_back(at);
      }
  return out;
}
const Vec3 kCylinderNormals[4] = {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)};

/// A work plane's points halfway between its points and on its cells'
/// corners: where its illuminance dips between the calculation points.
/// Only those the plane reaches from its point unobstructed, out of solids.
void add_between(const RayScene& rays, const CriterionGrid& g, SurfacePoints& out) {
  if (g.kind != CriterionGrid::Kind::WorkPlane || g.points.size() < 2) return;
  // The cells: the smallest steps between points of a row and of a column.
  const auto step = [&](int along, int across) {
    std::vector<std::pair<float, float>> v;
    for (const Vec3& p : g.points) v.push_back({p[across], p[along]});
    std::sort(v.begin(), v.end());
    float best = std::numeric_limits<float>::max();
    for (size_t i = 1; i < v.size(); ++i)
      if (std::abs(v[i].first - v[i - 1].first) < 1e-4f && v[i].second - v[i - 1].second > 1e-4f)
        best = std::min(best, v[i].second - v[i - 1].second);
    return best < std::numeric_limits<float>::max() ? best : float(g.spacing);
  };
  const float cx = step(0, 2), cz = step(2, 0);
  if (!(cx > 0.f) || !(cz > 0.f)) return;
  const Vec3 o = g.points.front();
  const auto key = [&](const Vec3& p) {
    const int64_t i = std::llround(2.0 * double(p.x - o.x) / double(cx)), k = std::llround(2.0 * double(p.z - o.z) / double(cz));
    return uint64_t(i + (1 << 30)) << 32 | uint64_t(k + (1 << 30));
  };
  std::unordered_set<uint64_t> taken;
  for (const Vec3& p : g.points) taken.insert(key(p));
  const Vec3 lift(0.f, 4.f * rays.epsilon(), 0.f);
  for (const Vec3& p : g.points)
    for (int a = -1; a <= 1; ++a)
      for (int b = -1; b <= 1; ++b) {
        if (!a && !b) continue;
        const Vec3 q = p + Vec3(0.5f * float(a) * cx, 0.f, 0.5f * float(b) * cz);
        const uint64_t k = key(q);
        if (taken.count(k)) continue;
        const Vec3 d = q - p;
        const float len = glm::length(d);
        if (rays.occluded(p + lift, d / len, len) || rays.inside_solid(q + lift)) continue;
        taken.insert(k);
        out.positions.push_back(q);
        out.normals.push_back(Vec3(0.f, 1.f, 0.f));
      }
}

/// What one place's luminaire gives at full output.
struct Field {
  std::vector<double> lux;       ///< maintained, at the criteria's points and between them
  double cylindrical = 0;        ///< maintained Ēz over the cylinders (with an Ēz criterion)
  std::vector<double> indirect;  ///< per observer: illuminance at the eye less the direct (new)
  std::vector<double> glare;     ///< per observer: L²ω/p²
};

/// The program's rows, one column per candidate: per grid, its mean
/// (Ē ≥ (1+m)·lux, with a hair more so that rounding never misses it) and,
/// with u0 > 0, per point (and per point between, with a margin)
/// E_i − (1+m)·u0·Ē ≥ 0.
struct Program {
  std::vector<double> b;
  std::vector<std::vector<double>> column;  ///< per candidate, per row
  size_t rows() const { return b.size(); }
};

std::vector<double> program_column(const IlluminanceCriteria& criteria, const Points& pts, double margin, const Field& f) {
  const std::vector<double>& e = f.lux;
  std::vector<double> col;
  if (pts.cylinders) col.push_back(f.cylindrical);  // Ēz ≥ (1+m)·wanted
  size_t first = 0;
  for (size_t g = 0; g < criteria.grids.size(); ++g) {
    const auto& grid = criteria.grids[g];
    const size_t n = grid.points.size();
    const double mean = std::accumulate(e.begin() + long(first), e.begin() + long(first + n), 0.0) / double(n);
    col.push_back(mean);
    if (grid.u0 > 0) {
      const double u0 = grid.u0 * (1 + margin);
      for (size_t i = 0; i < n; ++i) col.push_back(e[first + i] - u0 * mean);
      const auto [from, count] = pts.between[g];
      for (size_t i = 0; i < count; ++i) col.push_back(e[from + i] - u0 * mean);
    }
    first += n;
  }
  return col;
}

std::vector<double> program_bounds(const IlluminanceCriteria& criteria, const Points& pts, double margin, double cylindrical_min) {
  std::vector<double> b;
  if (pts.cylinders) b.push_back(cylindrical_min * (1 + margin) * (1.0 + 1e-4));
  for (size_t g = 0; g < criteria.grids.size(); ++g) {
    const auto& grid = criteria.grids[g];
    b.push_back(grid.lux * (1 + margin) * (1.0 + 1e-4));
    if (grid.u0 > 0) b.insert(b.end(), grid.points.size() + pts.between[g].second, 0.0);
  }
  return b;
}

/// A layout: which candidates, their dimming, its flux (in luminaires at
/// full output) and how far it falls short of the criteria (lux, summed).
struct Layout {
  std::vector<size_t> lights;
  std::vector<double> dimming;
  std::vector<double> duals;
  double flux = 0, shortfall = 0;
  double ugr = kNaN;
  /// Falls short by no more than `other` (a hair of rounding allowed).
  bool as_met_as(const Layout& o) const { return shortfall <= o.shortfall * (1 + 1e-3) + 1e-6; }
  /// Better: falls shorter of the criteria, else as short with less flux.
  bool better_than(const Layout& o) const {
    if (!as_met_as(o)) return false;
    if (!o.as_met_as(*this)) return true;
    return flux < o.flux * (1 - 1e-7);
  }
};

/// The largest UGR over the observers of luminaires dimmed `x` (NaN: none in view).
double layout_ugr(const std::vector<const Field*>& fields, const std::vector<double>& x, size_t observers) {
  double worst = kNaN;
  for (size_t o = 0; o < observers; ++o) {
    double glare = 0, indirect = 0;
    for (size_t j = 0; j < fields.size(); ++j) {
      glare += x[j] * x[j] * fields[j]->glare[o];
      indirect += x[j] * fields[j]->indirect[o];
    }
    const double u = unified_glare_rating(glare, indirect);
    if (std::isfinite(u) && !(u <= worst)) worst = u;
  }
  return worst;
}

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

/// The mount height over the criteria's area: where the LightSpace puts a
/// luminaire over its points (the median), or the top of the space.
std::vector<float> candidate_layers(const LightSpace& space, float plane, float step) {
  if (space.rules().ceiling_offset) return {plane + 1e-3f};
  const float bottom = std::max(space.bounds().lo.y, plane + step), top = space.bounds().hi.y - 1e-3f;
  std::vector<float> layers;
  for (int k = 0; k < 3; ++k) layers.push_back(bottom + (top - bottom) * float(k + 1) / 3.f);
  return layers;
}

} // namespace

void check_design_settings(const DesignSettings& s) {
  if (!(s.maintenance_factor > 0 && s.maintenance_factor <= 1))
    throw InputError("--maintenance-factor " + std::to_string(s.maintenance_factor) +
                     ": must be in (0, 1] (maintained = MF × new; 0.8 is a clean office's)");
  if (!(s.margin >= 0 && s.margin < 1)) throw InputError("--margin " + std::to_string(s.margin) + ": must be in [0, 1)");
}

Lighting design_for_illuminance(Renderer& reference, const LightSpace& space, const Light& luminaire,
                                const IlluminanceCriteria& criteria, const DesignSettings& settings, DesignReport& report) {
  const bool with_profile = luminaire.profile && (luminaire.type == LightType::Luminaire || is_area(luminaire.type));
  if (!with_profile) throw InputError("illuminance criteria need a luminaire (--luminaire FILE)");
  check_design_settings(settings);
  const RayScene& rays = space.rays();
  const Photometry& profile = *luminaire.profile;
  const double peak = profile.peak(), rated = profile.flux(), mf = settings.maintenance_factor, margin = settings.margin;
  report.maintenance_factor = mf;
  report.margin = margin;
  const auto light_at = [&](const Place& c, double dimming) {
    Light l = turned(luminaire, c.turn);
    l.position = c.position;
    l.intensity = Rgb(float(dimming * peak / kLumensPerWatt));
    return l;
  };
  const auto t0 = Clock::now();

  // The area, the lattice step, the mount and the room.
  Bounds area;
  double finest = std::numeric_limits<double>::max();
  float plane = -std::numeric_limits<float>::max();
  for (const auto& g : criteria.grids) {
    for (const Vec3& p : g.points) area.extend(p);
    if (g.spacing > 0) finest = std::min(finest, g.spacing);
    if (g.kind == CriterionGrid::Kind::WorkPlane)
      for (const Vec3& p : g.points) plane = std::max(plane, p.y);
  }
  if (area.empty()) throw InputError("the criteria have no point");
  if (plane == -std::numeric_limits<float>::max()) plane = area.center().y;
  // A third of the finest grid's spacing, but no finer than 15 cm (the zones' narrow bands have fine grids).
  const float step = settings.candidate_spacing > 0                  ? float(settings.candidate_spacing)
                     : finest < std::numeric_limits<double>::max() ? std::max(float(finest / 3.0), 0.15f)
                                                                   : area.diagonal() / 20.f;
  if (!(step > 0.f)) throw InputError("the criteria's points are all in one place: no room to spread luminaires");
  const std::vector<float> layers = candidate_layers(space, plane, step);
  std::vector<float> mounts;
  for (const auto& g : criteria.grids)
    for (size_t i = 0; i < g.points.size(); i += std::max<size_t>(1, g.points.size() / 25))
      if (const auto at = space.place(Vec3(g.points[i].x, layers.back(), g.points[i].z)); at && space.admissible(*at)) mounts.push_back(at->y);
  std::sort(mounts.begin(), mounts.end());
  const float mount_y = mounts.empty() ? layers.back() : mounts[mounts.size() / 2];
  const RoomFrame room = room_frame(space, criteria, mount_y);
  report.room = room;
  const glm::vec2 size = luminaire_size(luminaire);
  report.luminaire_size = size;
  const double luminous_area = luminaire.type == LightType::Disk || (luminaire.type == LightType::Luminaire && profile.opening_round)
                                   ? kPi / 4 * double(size[0]) * double(size[0])
                                   : double(size[0]) * double(size[1]);
  report.luminous_area = luminous_area;

  // What cannot fit the room.
  const float L = room.length(), W = room.width();
  const std::string room_size = metres(L) + " × " + metres(W) + " m";
  if (std::max(size[0], size[1]) > std::max(L, W) + 1e-4f || std::min(size[0], size[1]) > std::min(L, W) + 1e-4f)
    throw InputError("a luminaire of " + metres(size[0]) + " × " + metres(size[1]) + " m does not fit the room the criteria lie in (" +
                     room_size + ")");
  if (settings.spacing.min_spacing > double(std::hypot(L, W)))
    throw InputError("--min-spacing " + metres(settings.spacing.min_spacing) + ": no two luminaires fit that far apart in the room (" +
                     room_size + ")");
  if (settings.ceiling_grid > 0 && settings.ceiling_grid > double(std::min(L, W)) + 1e-4)
    throw InputError("--ceiling-grid " + metres(settings.ceiling_grid) + ": a tile larger than the room (" + room_size + ")");
  if (settings.ugr_max > 0 && !(luminous_area > 0))
    throw InputError("--ugr-max needs the luminaire's luminance, so its luminous area: " + profile.source +
                     " gives no opening (give --luminaire-size W,L)");
  if (settings.fixed_count && settings.max_count && settings.fixed_count > settings.max_count)
    throw InputError("--lights " + std::to_string(settings.fixed_count) + " is more than --place count allows (" +
                     std::to_string(settings.max_count) + ")");

  // Observers, points.
  const std::vector<GlareObserver> observers = luminous_area > 0 ? standard_observers(room, settings.eye_height()) : std::vector<GlareObserver>{};
  Points pts;
  pts.all = criteria.points();
  pts.criteria = pts.all.positions.size();
  for (const auto& g : criteria.grids) {
    const size_t from = pts.all.positions.size();
    if (margin > 0) add_between(rays, g, pts.all);
    pts.between.push_back({from, pts.all.positions.size() - from});
  }
  pts.eyes_first = pts.all.positions.size();
  for (const auto& o : observers) {
    pts.all.positions.push_back(o.eye);
    pts.all.normals.push_back(glm::normalize(o.view));
  }
  pts.cylinders_first = pts.all.positions.size();
  if (settings.cylindrical_min > 0) {
    const std::vector<Vec3> cylinders = cylinder_places(rays, criteria, room.floor_y, settings.eye_height());
    if (cylinders.empty()) throw InputError("--cylindrical-min: no work plane point has room for a person's head over it");
    for (const Vec3& at : cylinders)
      for (const Vec3& n : kCylinderNormals) {
        pts.all.positions.push_back(at);
        pts.all.normals.push_back(n);
      }
    pts.cylinders = cylinders.size();
  }
  pts.all.albedo.assign(pts.all.positions.size(), Rgb(1.f));
  const size_t lux_points = pts.eyes_first;

  // Renders places: their maintained lux at full output, and their glare.
  const auto render = [&](const std::vector<Place>& places) {
    Lighting unit;
    for (const auto& c : places) unit.push_back(light_at(c, kLumensPerWatt / peak));
    const std::vector<Rgb> phi = reference.unit_responses(pts.all, unit);
    std::vector<Field> fields(places.size());
    const size_t n = pts.all.positions.size();
    for (size_t j = 0; j < places.size(); ++j) {
      std::vector<double> e = lux_from_radiance(std::span<const Rgb>(phi.data() + j * n, n));
      for (double& v : e) v *= peak / kLumensPerWatt;  // φ is for 1 W/sr at the peak; full output is peak/683
      fields[j].lux.assign(e.begin(), e.begin() + long(lux_points));
      for (double& v : fields[j].lux) v *= mf;
      if (pts.cylinders) {
        double sum = 0;
        for (size_t k = 0; k < 4 * pts.cylinders; ++k) sum += e[pts.cylinders_first + k];
        fields[j].cylindrical = mf * sum / double(4 * pts.cylinders);
      }
      const Light full = light_at(places[j], 1.0);
      for (size_t o = 0; o < observers.size(); ++o) {
        const GlareTerms t = glare_terms(rays, full, luminous_area, observers[o]);
        fields[j].glare.push_back(t.glare);
        fields[j].indirect.push_back(std::max(0.0, e[pts.eyes_first + o] - t.direct_lux));
      }
    }
    return fields;
  };
  const auto lights_some = [&](const Field& f) { return *std::max_element(f.lux.begin(), f.lux.begin() + long(pts.criteria)) > 0; };

  // 1. The lattice over the area and the room, where a luminaire may stand and its outline clears the walls.
  Bounds lattice = area;
  for (float a : {room.u_lo, room.u_hi})
    for (float b : {room.v_lo, room.v_hi}) lattice.extend(room.at(a, b, plane));
  const Vec3 lo = lattice.lo - Vec3(step), e = lattice.extent() + Vec3(2.f * step);
  const int nx = int(std::floor(e.x / step)) + 1, nz = int(std::floor(e.z / step)) + 1;
  if (double(nx) * nz > 4e4) throw InputError("--candidate-spacing " + std::to_string(step) + " makes over 40,000 places: give a larger one");
  std::vector<float> spins = distinct_spins(profile);
  if (spins.size() == 1 && std::abs(size[0] - size[1]) > 1e-4f) spins.push_back(90.f);  // an oblong outline fits either way
  std::vector<Place> candidates;
  for (int iz = 0; iz < nz; ++iz)
    for (size_t iy = 0; iy < layers.size(); ++iy)
      for (int ix = 0; ix < nx; ++ix) {
        const auto at = space.place(Vec3(lo.x + float(ix) * step, layers[iy], lo.z + float(iz) * step));
        if (!at || !space.admissible(*at)) continue;
        for (size_t s = 0; s < spins.size(); ++s) {
          const Place c{*at, spins[s], glm::ivec4(ix, int(iy), iz, int(s))};
          if (clear_of_walls(rays, footprint_of(light_at(c, 1.0), size))) candidates.push_back(c);
        }
      }
  if (candidates.empty())
    throw InputError("no place for a luminaire over the criteria's area (" + space.rules().describe() +
                     "): give --place rules that leave room");
  std::vector<Field> all_fields = render(candidates);
  std::vector<Place> useful;
  std::vector<Field> fields;
  for (size_t j = 0; j < candidates.size(); ++j)
    if (lights_some(all_fields[j])) {
      useful.push_back(candidates[j]);
      fields.push_back(std::move(all_fields[j]));
    }
  all_fields.clear();
  report.candidates = useful.size();
  report.seconds["candidates"] = since(t0);
  if (useful.empty()) throw InputError("no place a luminaire may stand lights any of the criteria's points");

  // 2. The program and its bound.
  const auto t1 = Clock::now();
  Program program;
  program.b = program_bounds(criteria, pts, margin, settings.cylindrical_min);
  for (const auto& f : fields) program.column.push_back(program_column(criteria, pts, margin, f));
  std::vector<Footprint> outlines;
  for (const auto& c : useful) outlines.push_back(footprint_of(light_at(c, 1.0), size));
  Walker walker(program, useful, fields, outlines, settings.spacing, plane, observers.size());
  std::vector<size_t> all(useful.size());
  std::iota(all.begin(), all.end(), size_t(0));
  const Layout bound = walker.evaluate(all);
  report.least_flux_lm = bound.flux * rated;
  report.shortfall_lux = bound.shortfall;
  const double ugr_limit = settings.ugr_max > 0 ? settings.ugr_max * (1 - margin) : 0;
  const auto ugr_ok = [&](double ugr) { return !(ugr_limit > 0) || !(ugr > ugr_limit); };
  const size_t least_count = std::max<size_t>(settings.min_count, 1);
  const double allowed = bound.flux * (1.0 + settings.energy_tolerance);
  const auto count_ok = [&](size_t n) { return n >= least_count && (!settings.max_count || n <= settings.max_count); };
  // Criteria that cannot be met are met as nearly as the bound meets them.
  const auto relaxed = [&](const Layout& l) { return l.as_met_as(bound) && l.flux <= allowed; };
  const auto acceptable = [&](const Layout& l) {
    return relaxed(l) && count_ok(l.lights.size()) && walker.feasible(l) && ugr_ok(l.ugr);
  };
  const auto buildable = [&](const Layout& l) { return walker.feasible(l) ? l : walker.search(walker.spread(l)); };

  // 3. Free layouts: walk down from the program's lights.
  Layout free_layout = bound;
  bool free_found = false;
  {
    std::optional<Layout> best, fallback;
    // Layouts of more luminaires than an array may have are walked through, not built.
    constexpr size_t kMostToBuild = 400;
    const auto consider = [&](const Layout& at) {
      if (at.lights.size() > kMostToBuild) return;
      Layout f = buildable(at);
      if (acceptable(f)) {
        report.walk.push_back({f.lights.size(), f.flux * rated});
        if (!best || f.lights.size() < best->lights.size() || (f.lights.size() == best->lights.size() && f.flux < best->flux)) best = f;
      }
      // Else the nearest to it: feasible, within the UGR limit if any is, as met as possible, then the least flux.
      if (walker.feasible(f) && count_ok(f.lights.size()) &&
          (!fallback || (ugr_ok(f.ugr) && !ugr_ok(fallback->ugr)) || (ugr_ok(f.ugr) == ugr_ok(fallback->ugr) && f.better_than(*fallback))))
        fallback = f;
    };
    Layout at = bound;
    const size_t least = size_t(std::ceil(bound.flux - 1e-9));
    while (at.lights.size() > 2 * least + 8) {  // coarsely while there are many
      std::vector<size_t> order(at.lights.size());
      std::iota(order.begin(), order.end(), size_t(0));
      std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return at.dimming[a] > at.dimming[b]; });
      std::vector<size_t> kept;
      for (size_t k = 0; k < order.size() - order.size() / 4; ++k) kept.push_back(at.lights[order[k]]);
      Layout next = walker.evaluate(kept);
      if (!relaxed(next)) break;
      at = std::move(next);
    }
    consider(at);
    int misses = 0;
    while (at.lights.size() > least_count && misses < 3) {
      at = walker.fewer(at);
      if (relaxed(at)) {
        consider(at);
        misses = 0;
      } else {
        ++misses;
      }
    }
    if (best) {
      // Move the chosen lights on the lattice, then see whether fewer still do.
      Layout chosen = walker.search(*best);
      if (!acceptable(chosen)) chosen = *best;
      while (chosen.lights.size() > least_count) {
        Layout next = buildable(walker.search(walker.fewer(chosen)));
        if (!acceptable(next)) break;
        chosen = std::move(next);
        report.walk.push_back({chosen.lights.size(), chosen.flux * rated});
      }
      free_layout = chosen;
      free_found = true;
      report.fewest_free = chosen.lights.size();
    } else if (fallback) {
      free_layout = *fallback;
      free_found = true;
    } else {  // nothing small enough to build was walked through (criteria far out of reach): the last, spread
      free_layout = walker.spread(at);
      free_found = true;
    }
    if (settings.max_count && free_layout.lights.size() > settings.max_count) {
      while (free_layout.lights.size() > settings.max_count) free_layout = buildable(walker.search(walker.fewer(free_layout)));
      free_found = true;
    }
  }
  // --lights N: exactly N, walked down to or filled up to.
  if (settings.fixed_count) {
    const size_t n = settings.fixed_count;
    Layout at = free_found && free_layout.lights.size() >= n ? free_layout : bound;
    while (at.lights.size() > n) at = walker.fewer(at);
    walker.set_least_dimming(kLeastDimming);
    at = walker.evaluate(buildable(at).lights);
    while (at.lights.size() < n) {
      const auto more = walker.farthest(at.lights);
      if (!more)
        throw InputError("--lights " + std::to_string(n) + ": only " + std::to_string(at.lights.size()) +
                         " luminaires fit where --place lets them stand with the spacing asked for (room " + room_size + ")");
      std::vector<size_t> lights = at.lights;
      lights.push_back(*more);
      at = walker.evaluate(lights);
    }
    free_layout = walker.search(at);
    free_found = true;
    walker.set_least_dimming(0);
  }
  report.free.tried = settings.layout != LayoutChoice::Array || settings.fixed_count;
  report.free.found = free_found;
  report.seconds["free"] = since(t1);

  // 4. Arrays, the fewest first.
  const auto t2 = Clock::now();
  struct ArrayResult {
    ArrayLayout shape;
    std::vector<Field> fields;
    double x = 0, flux = 0, shortfall = 0, ugr = kNaN;
    bool met = false;
  };
  std::optional<ArrayResult> array;
  if (settings.layout != LayoutChoice::Free) {
    ArrayRules rules;
    rules.size = size;
    rules.spacing = settings.spacing;
    rules.height_over_plane = mount_y - plane;
    rules.tile = settings.ceiling_grid;
    rules.grid_origin = settings.grid_origin;
    rules.exact_count = settings.fixed_count;
    // Turns that line the luminaire up with the room, as its symmetry tells them apart (and its outline).
    const Vec3 axis = length_axis(luminaire), nadir = glm::normalize(luminaire.direction);
    const float to_u = float(std::atan2(double(glm::dot(room.u, glm::cross(axis, nadir))), double(glm::dot(room.u, axis))) * 180.0 / kPi);
    std::vector<float> turns;
    for (int k = 0; k < 4; ++k)
      if (size_t(k) < spins.size() || (k == 1 && std::abs(size[0] - size[1]) > 1e-4f)) turns.push_back(to_u + 90.f * float(k));
    const auto evaluate = [&](ArrayResult& r) {
      // One dimming for all: Ē rows need x ≥ b/col; U0 rows need col ≥ 0 whatever x.
      const size_t rows = program.rows();
      Field sum;
      sum.lux.assign(lux_points, 0.0);
      for (const auto& f : r.fields) {
        for (size_t i = 0; i < sum.lux.size(); ++i) sum.lux[i] += f.lux[i];
        sum.cylindrical += f.cylindrical;
      }
      const std::vector<double> col = program_column(criteria, pts, margin, sum);
      double x = 0;
      for (size_t k = 0; k < rows; ++k)
        if (program.b[k] > 0) x = std::max(x, col[k] > 0 ? program.b[k] / col[k] : std::numeric_limits<double>::infinity());
      r.x = std::min(x, 1.0);
      if (settings.fixed_count) r.x = std::max(r.x, kLeastDimming);
      r.shortfall = 0;
      for (size_t k = 0; k < rows; ++k) r.shortfall += std::max(0.0, program.b[k] - r.x * col[k]);
      r.flux = r.x * double(r.fields.size());
      std::vector<const Field*> f;
      for (const auto& field : r.fields) f.push_back(&field);
      r.ugr = layout_ugr(f, std::vector<double>(r.fields.size(), r.x), observers.size());
      r.met = r.shortfall <= bound.shortfall * (1 + 1e-3) + 1e-6 && ugr_ok(r.ugr);
    };
    std::vector<ArrayResult> results;
    // Arrays of up to 400 luminaires (20 × 20) unless a count asks for more.
    constexpr size_t kMostInArray = 400;
    const size_t first = settings.fixed_count
                             ? settings.fixed_count
                             : std::clamp<size_t>(size_t(std::floor(0.85 * bound.flux)), least_count, std::max(least_count, kMostInArray));
    const size_t last = settings.fixed_count ? settings.fixed_count
                        : settings.max_count ? settings.max_count
                                             : std::min(std::max(first, kMostInArray), std::max<size_t>(first + 12, 3 * size_t(std::ceil(bound.flux)) + 8));
    size_t met_at = 0;
    ArrayFitCache fits;
    for (size_t n = std::max<size_t>(first, 1); n <= last && n <= 2000; ++n) {
      if (met_at && n > met_at + 4) break;
      std::vector<ArrayLayout> shapes = room_arrays(space, room, luminaire, rules, turns, n, &fits);
      if (shapes.empty()) continue;
      std::vector<Place> places;
      for (const auto& s : shapes)
        for (const Vec3& p : s.positions) places.push_back({p, s.turn});
      std::vector<Field> rendered = render(places);
      size_t at = 0;
      for (auto& s : shapes) {
        ArrayResult r;
        r.fields.assign(std::make_move_iterator(rendered.begin() + long(at)), std::make_move_iterator(rendered.begin() + long(at + s.positions.size())));
        at += s.positions.size();
        r.shape = std::move(s);
        evaluate(r);
        if (r.met && !met_at) met_at = n;
        results.push_back(std::move(r));
      }
    }
    // The fewest met whose flux is within the tolerance of the best met array's; else the least short.
    double least_met = std::numeric_limits<double>::infinity();
    for (const auto& r : results)
      if (r.met) least_met = std::min(least_met, r.flux);
    for (auto& r : results) {
      const bool pick = std::isfinite(least_met)
                            ? r.met && r.flux <= least_met * (1 + settings.energy_tolerance) &&
                                  (!array || r.fields.size() < array->fields.size() ||
                                   (r.fields.size() == array->fields.size() && r.flux < array->flux))
                            : !array || r.shortfall < array->shortfall * (1 - 1e-9) ||
                                  (r.shortfall <= array->shortfall * (1 + 1e-9) && r.flux < array->flux);
      if (pick) array = r;
    }
    report.array.tried = true;
  }
  report.seconds["arrays"] = since(t2);

  // 5. Which: the array where it costs nothing against the free layout.
  std::vector<Place> chosen_places;
  std::vector<double> chosen_dimming;
  const auto summary = [&](LayoutSummary& s, size_t count, double x_flux, double shortfall, double ugr, bool met) {
    s.found = true;
    s.count = count;
    s.flux_lm = x_flux * rated;
    s.power_w = x_flux * profile.input_watts;
    s.shortfall_lux = shortfall;
    s.ugr = ugr;
    s.met = met;
  };
  const bool free_met = free_found && free_layout.as_met_as(bound) && walker.feasible(free_layout) && ugr_ok(free_layout.ugr) &&
                        (!settings.fixed_count || free_layout.lights.size() == settings.fixed_count);
  if (free_found) summary(report.free, free_layout.lights.size(), free_layout.flux, free_layout.shortfall, free_layout.ugr, free_met);
  if (array) {
    summary(report.array, array->fields.size(), array->flux, array->shortfall, array->ugr, array->met);
    report.array.shape = array->shape.describe();
  }
  bool take_array = false;
  if (settings.layout == LayoutChoice::Array) {
    if (!array)
      throw InputError(std::string("no array of the luminaire (") + metres(size[0]) + " × " + metres(size[1]) + " m) fits the room (" +
                       room_size + ")" + (settings.fixed_count ? " with " + std::to_string(settings.fixed_count) + " luminaires" : "") +
                       (settings.ceiling_grid > 0 ? " on the " + metres(settings.ceiling_grid) + " m grid" : "") +
                       " with the spacing asked for: --layout free places it freely");
    take_array = true;
    report.why = "--layout array";
  } else if (settings.layout == LayoutChoice::Auto && array) {
    if (!free_met) {
      take_array = array->met || !free_found || array->shortfall < free_layout.shortfall;
      report.why = array->met ? "the free layout does not meet the criteria" : "neither meets the criteria; the array falls less short";
    } else if (array->met && array->fields.size() <= free_layout.lights.size() &&
               array->flux <= free_layout.flux + settings.energy_tolerance * bound.flux + 1e-9) {
      take_array = true;
      report.why = "it costs nothing against the free layout (no more luminaires, flux within the energy tolerance)";
    } else {
      report.why = array->met ? "the array needs more luminaires or flux than the free layout" : "no array meets the criteria";
    }
  } else {
    report.why = settings.layout == LayoutChoice::Free ? "--layout free" : "no array fits the room";
  }
  if (!take_array && !free_found) throw InputError("no layout found");
  Lighting lights;
  if (take_array) {
    report.chosen = "array";
    for (const Vec3& p : array->shape.positions) {
      chosen_places.push_back({p, array->shape.turn});
      chosen_dimming.push_back(array->x);
    }
  } else {
    report.chosen = "free";
    for (size_t j = 0; j < free_layout.lights.size(); ++j) {
      chosen_places.push_back(useful[free_layout.lights[j]]);
      chosen_dimming.push_back(free_layout.dimming[j]);
    }
  }
  report.seconds["program"] = since(t1);

  // 6. The lights found, measured as `hilight render` would.
  const auto t3 = Clock::now();
  for (size_t j = 0; j < chosen_places.size(); ++j) lights.push_back(light_at(chosen_places[j], chosen_dimming[j]));
  report.dimming = chosen_dimming;
  std::vector<double> lux = lux_from_radiance(reference.illuminate(pts.all, lights));
  std::vector<double> maintained(lux.begin(), lux.begin() + long(lux_points));
  for (double& v : maintained) v *= mf;
  report.lux.assign(maintained.begin(), maintained.begin() + long(pts.criteria));
  report.met = true;
  size_t first = 0;
  for (size_t g = 0; g < criteria.grids.size(); ++g) {
    const auto& grid = criteria.grids[g];
    GridFigures f = grid_figures(grid, std::span<const double>(report.lux.data() + first, grid.points.size()));
    double low = f.min;
    for (size_t i = 0; i < pts.between[g].second; ++i) low = std::min(low, maintained[pts.between[g].first + i]);
    report.min_whole.push_back(low);
    report.u0_whole.push_back(f.mean > 0 ? low / f.mean : 0);
    // With a margin: clear of the limits by it, Emin over the whole grid.
    f.met = f.mean >= grid.lux * (1 + margin) * (1 - 1e-3) && report.u0_whole.back() >= grid.u0 * (1 + margin) * (1 - 1e-3);
    report.figures.push_back(f);
    report.met = report.met && f.met;
    first += grid.points.size();
  }
  // Cylindrical illuminance at the eyes' height over the work planes' points, and the modelling.
  report.cylindrical.height = settings.eye_height();
  {
    SurfacePoints cyl;
    for (const Vec3& at : cylinder_places(rays, criteria, room.floor_y, float(report.cylindrical.height)))
      for (const Vec3& n : {kCylinderNormals[0], kCylinderNormals[1], kCylinderNormals[2], kCylinderNormals[3], Vec3(0, 1, 0)}) {
        cyl.positions.push_back(at);
        cyl.normals.push_back(n);
      }
    if (!cyl.positions.empty()) {
      cyl.albedo.assign(cyl.positions.size(), Rgb(1.f));
      const std::vector<double> ev = lux_from_radiance(reference.illuminate(cyl, lights));
      auto& c = report.cylindrical;
      c.points = ev.size() / 5;
      double sum = 0, horizontal = 0;
      c.min = std::numeric_limits<double>::max();
      for (size_t i = 0; i < c.points; ++i) {
        const double ez = mf * 0.25 * (ev[5 * i] + ev[5 * i + 1] + ev[5 * i + 2] + ev[5 * i + 3]);
        sum += ez;
        horizontal += mf * ev[5 * i + 4];
        c.min = std::min(c.min, ez);
      }
      c.mean = sum / double(c.points);
      c.u0 = c.mean > 0 ? c.min / c.mean : 0;
      c.modelling = horizontal > 0 ? sum / horizontal : 0;
    }
    report.cylindrical.wanted = settings.cylindrical_min;
    report.cylindrical.met = !(settings.cylindrical_min > 0) || report.cylindrical.mean >= settings.cylindrical_min * (1 + margin) * (1 - 1e-3);
    report.met = report.met && report.cylindrical.met;
  }
  report.ugr = kNaN;
  for (size_t o = 0; o < observers.size(); ++o) {
    double glare = 0, direct = 0;
    for (const Light& l : lights) {
      const GlareTerms t = glare_terms(rays, l, luminous_area, observers[o]);
      glare += t.glare;
      direct += t.direct_lux;
    }
    const double u = unified_glare_rating(glare, std::max(0.0, lux[pts.eyes_first + o] - direct));
    report.glare.push_back({observers[o], u});
    if (std::isfinite(u) && !(u <= report.ugr)) report.ugr = u;
  }
  if (!ugr_ok(report.ugr)) report.met = false;
  report.flux_lm = 0;
  report.power_w = 0;
  for (double d : chosen_dimming) {
    report.flux_lm += d * rated;
    report.power_w += d * profile.input_watts;
  }
  // Why not met, when the criteria could be.
  if (!report.met && bound.shortfall <= 1e-6) {
    char text[400];
    if (settings.fixed_count && report.fewest_free > settings.fixed_count)
      std::snprintf(text, sizeof(text), "--lights %zu: %zu luminaires fall short of the criteria (the fewest that meet them: %zu)",
                    settings.fixed_count, settings.fixed_count, report.fewest_free);
    else if (settings.fixed_count)
      std::snprintf(text, sizeof(text), "--lights %zu: %zu luminaires fall short of the criteria where they may stand", settings.fixed_count,
                    settings.fixed_count);
    else if (!report.cylindrical.met)
      std::snprintf(text, sizeof(text), "cylindrical illuminance Ēz %.0f lx is below the %g lx asked%s", report.cylindrical.mean,
                    settings.cylindrical_min, margin > 0 ? " (with the margin)" : "");
    else if (ugr_limit > 0 && !ugr_ok(report.ugr))
      std::snprintf(text, sizeof(text), "UGR %.1f is above the limit %.1f%s: a luminaire of lower luminance, or other places", report.ugr,
                    ugr_limit, margin > 0 ? " (with the margin)" : "");
    else if (take_array && settings.layout == LayoutChoice::Array)
      std::snprintf(text, sizeof(text), "no array of the luminaire meets the criteria (the nearest: %s): --layout free",
                    array->shape.describe().c_str());
    else
      std::snprintf(text, sizeof(text), "the criteria are not met when the lights found are measured");
    report.unmet = text;
  }
  report.seconds["measure"] = since(t3);
  report.seconds["total"] = since(t0);
  return lights;
}

} // namespace hilight
