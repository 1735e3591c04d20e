#pragma once
// The illuminance design's parts (solve/illuminance_design.hpp): the places
// tried, the points rendered, a place's field, the linear program's rows
// and a layout. Internal to the design's steps (design_steps.hpp).
#include "hilight/error.hpp"
#include "hilight/solve/illuminance_design.hpp"
#include "hilight/solve/linear_program.hpp"
#include "hilight/units.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <optional>
#include <set>
#include <string>
#include <unordered_set>
#include <vector>

namespace hilight::design {

using Clock = std::chrono::steady_clock;

inline double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// A luminaire asked for by count is never dimmed below this (a dark one is no luminaire).
constexpr double kLeastDimming = 0.1;

inline std::string metres(double v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f", v);
  return text;
}

struct Place {
  Vec3 position;
  float turn = 0.f;                 ///< degrees from the template, about its aim
  glm::ivec4 cell{-1, -1, -1, -1};  ///< lattice x, layer, z, spin index (arrays: none)
  Vec3 aim{0.f};                    ///< a tilted aim (unit; zero: the luminaire's own)
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
std::vector<Vec3> cylinder_places(const RayScene& rays, const IlluminanceCriteria& criteria, float floor_y, float height);
inline const Vec3 kCylinderNormals[4] = {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)};

/// A grid's points between its calculation points, where its illuminance
/// may dip: a work plane's halfway between its points and on its cells'
/// corners (those the plane reaches from its point unobstructed, out of
/// solids); a wall or ceiling grid's halfway between neighbours on the same
/// surface.
void add_between(const RayScene& rays, const CriterionGrid& g, SurfacePoints& out);

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

/// A place's column of the program's rows.
std::vector<double> program_column(const IlluminanceCriteria& criteria, const Points& pts, double margin, const Field& f);
/// The program's bounds b.
std::vector<double> program_bounds(const IlluminanceCriteria& criteria, const Points& pts, double margin, double cylindrical_min);

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
double layout_ugr(const std::vector<const Field*>& fields, const std::vector<double>& x, size_t observers);

/// The mount height over the criteria's area: where the LightSpace puts a
/// luminaire over its points (the median), or the top of the space.
std::vector<float> candidate_layers(const LightSpace& space, float plane, float step);

} // namespace hilight::design
