// The HTML report's lux grids (html_lux_maps.hpp).
#include "html_lux_maps.hpp"

#include "html_parts.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

namespace hilight {

namespace {

/// Isolines (marching squares) over the cells of a regular grid of points
/// (a work plane's), at round levels between its least and largest lux:
/// SVG paths labelled with their level. Nothing for irregular grids (walls).
std::string isolines(const CriterionGrid& grid, const double* lux, const Bounds& box, double scale) {
  if (grid.kind == CriterionGrid::Kind::Walls || grid.points.size() < 4) return "";
  // The cells: the smallest steps between points in x and in z.
  float cx = std::numeric_limits<float>::max(), cz = cx;
  for (size_t i = 1; i < grid.points.size(); ++i) {
    const float dx = std::abs(grid.points[i].x - grid.points[i - 1].x), dz = std::abs(grid.points[i].z - grid.points[i - 1].z);
    if (dx > 1e-4f) cx = std::min(cx, dx);
    if (dz > 1e-4f) cz = std::min(cz, dz);
  }
  if (cx == std::numeric_limits<float>::max() || cz == std::numeric_limits<float>::max()) return "";
  const Vec3 o = grid.points.front();
  std::map<std::pair<long, long>, size_t> at;
  for (size_t i = 0; i < grid.points.size(); ++i)
    at[{std::lround((grid.points[i].x - o.x) / cx), std::lround((grid.points[i].z - o.z) / cz)}] = i;
  double low = lux[0], high = lux[0];
  for (size_t i = 0; i < grid.points.size(); ++i) low = std::min(low, lux[i]), high = std::max(high, lux[i]);
  std::ostringstream s;
  s << std::fixed << std::setprecision(1);
  for (const double level : isoline_levels(low, high)) {
    std::ostringstream d;
    d << std::fixed << std::setprecision(1);
    std::pair<double, double> label{-1, -1};
    for (const auto& cell : at) {
      const std::pair<long, long> key = cell.first;  // (not a structured binding: clang 14 cannot capture those)
      const size_t i00 = cell.second;
      const auto find = [&](long dx, long dz) {
        const auto it = at.find({key.first + dx, key.second + dz});
        return it == at.end() ? size_t(-1) : it->second;
      };
      const size_t i10 = find(1, 0), i01 = find(0, 1), i11 = find(1, 1);
      if (i10 == size_t(-1) || i01 == size_t(-1) || i11 == size_t(-1)) continue;
      // The square's corners counter-clockwise, and where the level crosses each side.
      const size_t c[4] = {i00, i10, i11, i01};
      std::vector<std::pair<double, double>> cross;
      for (int k = 0; k < 4; ++k) {
        const size_t a = c[k], b = c[(k + 1) % 4];
        if ((lux[a] < level) == (lux[b] < level)) continue;
        const double t = (level - lux[a]) / (lux[b] - lux[a]);
        const double x = double(grid.points[a].x + float(t) * (grid.points[b].x - grid.points[a].x) - box.lo.x) * scale;
        const double y = double(grid.points[a].z + float(t) * (grid.points[b].z - grid.points[a].z) - box.lo.z) * scale;
        cross.push_back({x, y});
      }
      for (size_t k = 0; k + 1 < cross.size(); k += 2) {
        d << "M" << cross[k].first << "," << cross[k].second << "L" << cross[k + 1].first << "," << cross[k + 1].second;
        if (label.first < 0) label = cross[k];
      }
    }
    if (d.str().empty()) continue;
    s << "<path class=\"isoline\" d=\"" << d.str() << "\" stroke=\"black\" stroke-width=\"0.8\" fill=\"none\"/>"
      << "<text x=\"" << label.first + 2 << "\" y=\"" << label.second - 2 << "\">" << std::setprecision(0) << level << " lx" << std::setprecision(1)
      << "</text>";
  }
  return s.str();
}

std::string grid_map(const CriterionGrid& grid, const double* lux, const Lighting& lights, size_t index) {
  Bounds box;
  for (const Vec3& p : grid.points) box.extend(p);
  const float half = 0.5f * float(grid.spacing > 0 ? grid.spacing : 0.1);
  box.lo -= Vec3(half);
  box.hi += Vec3(half);
  const double width = 420.0, scale = width / std::max(1e-6, double(std::max(box.extent().x, box.extent().z)));
  const double w = double(box.extent().x) * scale, h = double(box.extent().z) * scale;
  double top = 1.5 * grid.lux;
  for (size_t i = 0; i < grid.points.size(); ++i) top = std::max(top, lux[i]);
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << "<svg class=\"luxmap\" id=\"luxmap-" << index << "\" width=\"" << w + 20 << "\" height=\""
    << h + 34 << "\" xmlns=\"http://www.w3.org/2000/svg\" font-size=\"9\"><g transform=\"translate(10,10)\">";
  for (size_t i = 0; i < grid.points.size(); ++i) {
    const double x = double(grid.points[i].x - box.lo.x) * scale, y = double(grid.points[i].z - box.lo.z) * scale;
    const double side = 2.0 * half * scale;
    s << "<rect x=\"" << x - 0.5 * side << "\" y=\"" << y - 0.5 * side << "\" width=\"" << side << "\" height=\"" << side
      << "\" fill=\"" << false_colour_css(lux[i] / top) << "\"><title>" << std::setprecision(0) << lux[i] << " lx</title></rect>"
      << std::setprecision(1);
  }
  s << isolines(grid, lux, box, scale);
  for (const Light& l : lights) {
    if (l.position.x < box.lo.x || l.position.x > box.hi.x || l.position.z < box.lo.z || l.position.z > box.hi.z) continue;
    const double x = double(l.position.x - box.lo.x) * scale, y = double(l.position.z - box.lo.z) * scale;
    s << "<circle class=\"luminaire\" cx=\"" << x << "\" cy=\"" << y << "\" r=\"4\" fill=\"white\" stroke=\"black\"/>";
  }
  // A scale bar: the round length nearest a quarter of the map.
  const double bar = round_length(0.25 * double(std::max(box.extent().x, box.extent().z)));
  s << "<g class=\"scalebar\"><line x1=\"0\" y1=\"" << h + 6 << "\" x2=\"" << bar * scale << "\" y2=\"" << h + 6
    << "\" stroke=\"black\" stroke-width=\"2\"/><text x=\"" << bar * scale + 4 << "\" y=\"" << h + 9 << "\">" << std::setprecision(bar < 1 ? 1 : 0)
    << bar << " m</text></g>" << std::setprecision(1);
  s << "</g></svg>";
  // The colour scale.
  s << "<svg width=\"" << 260 << "\" height=\"30\" xmlns=\"http://www.w3.org/2000/svg\" font-size=\"10\">";
  for (int k = 0; k < 20; ++k)
    s << "<rect x=\"" << 10 + k * 12 << "\" y=\"2\" width=\"12\" height=\"12\" fill=\"" << false_colour_css(double(k) / 19.0) << "\"/>";
  s << std::setprecision(0) << "<text x=\"10\" y=\"26\">0 lx</text><text x=\"200\" y=\"26\">" << top << " lx</text></svg>";
  return s.str();
}

} // namespace

std::string lux_maps_html(const IlluminanceCriteria& criteria, const DesignReport& design, const Lighting& lights) {
  std::ostringstream html;
  html << "<h2>Illuminance</h2><table id=\"grids\"><tr><th>grid</th><th>points</th><th>Ē (lx)</th><th>wanted</th><th>Emin (lx)</th>"
          "<th>U0</th><th>wanted</th><th>met</th></tr>\n";
  for (size_t g = 0; g < criteria.grids.size() && g < design.figures.size(); ++g) {
    const auto& c = criteria.grids[g];
    const auto& f = design.figures[g];
    html << std::fixed << std::setprecision(0) << "<tr><td>" << c.name << "</td><td>" << c.points.size() << "</td><td>" << f.mean
         << "</td><td>≥ " << c.lux << "</td><td>" << f.min << "</td><td>" << std::setprecision(2) << f.u0 << "</td><td>≥ " << c.u0
         << "</td><td>" << (f.met ? "yes" : "<b>no</b>") << "</td></tr>\n";
  }
  html << "</table>\n" << std::setprecision(0) << "<p>Maintained illuminance: the new installation × the maintenance factor "
       << std::setprecision(2) << design.maintenance_factor << std::setprecision(0);
  if (design.margin > 0) html << "; every criterion " << 100 * design.margin << "% clear of its limit, Emin also between the points";
  html << ".</p><p>Total flux " << design.flux_lm << " lm (the least any layout of these places could have: " << design.least_flux_lm
       << " lm)";
  if (design.power_w > 0) {
    html << ", " << design.power_w << " W";
    if (design.room.floor_area > 0)
      html << std::setprecision(2) << ", " << design.power_w / design.room.floor_area << " W/m² over " << std::setprecision(1)
           << design.room.floor_area << " m²" << std::setprecision(0);
  }
  html << ".</p>\n<table id=\"layouts\"><tr><th>layout</th><th>luminaires</th><th>flux (lm)</th><th>W</th><th>met</th><th></th></tr>\n";
  for (const auto& [kind, summary] : {std::pair<const char*, const LayoutSummary*>{"array", &design.array}, {"free", &design.free}}) {
    if (!summary->found) continue;
    html << "<tr><td>" << kind << "</td><td>" << summary->count << "</td><td>" << summary->flux_lm << "</td><td>" << summary->power_w
         << "</td><td>" << (summary->met ? "yes" : "no") << "</td><td>" << summary->shape << (design.chosen == kind ? " (kept)" : "")
         << "</td></tr>\n";
  }
  html << "</table><p>Kept: " << design.chosen << ", " << design.why << ".</p>\n";
  if (!design.glare.empty()) {
    html << "<table id=\"ugr\"><tr><th>UGR observer (eyes 1.2 m)</th><th>UGR</th></tr>\n" << std::fixed << std::setprecision(1);
    for (const auto& g : design.glare)
      if (std::isfinite(g.ugr)) html << "<tr><td>" << g.observer.name << "</td><td>" << g.ugr << "</td></tr>\n";
      else html << "<tr><td>" << g.observer.name << "</td><td>&lt; 10</td></tr>\n";
    html << "</table>\n" << std::setprecision(0);
  }
  html << "<div class=\"views\">";
  size_t first = 0;
  for (size_t g = 0; g < criteria.grids.size(); ++g) {
    const auto& c = criteria.grids[g];
    if (c.kind != CriterionGrid::Kind::Walls && first + c.points.size() <= design.lux.size())
      html << "<div class=\"view\"><h3>" << c.name << ", seen from above</h3>" << grid_map(c, design.lux.data() + first, lights, g)
           << "</div>\n";
    first += c.points.size();
  }
  html << "</div><p class=\"legend\">Each square a calculation point, coloured by its illuminance; lines: isolines (lx); "
          "circles: the luminaires; the bar: a length in metres. Walls are in the table only.</p>\n";
  return html.str();
}

} // namespace hilight
