// The HTML report's plans (html_plans.hpp).
#include "html_plans.hpp"

#include "html_parts.hpp"
#include "hilight/plan_view.hpp"
#include "hilight/scene_origin.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace hilight {

namespace {

/// The lights standing in storey k of `sections`: from its floor to the next
/// floor (the lowest storey also takes lights below its floor).
std::vector<size_t> lights_in(const std::vector<PlanSection>& sections, size_t k, const Lighting& lights) {
  std::vector<size_t> out;
  for (size_t j = 0; j < lights.size(); ++j) {
    const float y = lights[j].position.y;
    if ((k == 0 || y >= sections[k].floor) && (k + 1 == sections.size() || y < sections[k].top)) out.push_back(j);
  }
  return out;
}

/// `image` with its cut pixels grey at `exposure`, and markers over it.
std::string marked_plan(Image image, const std::vector<uint8_t>& cut, float exposure, const std::string& alt,
                        const std::string& markers) {
  for (size_t i = 0; i < cut.size(); ++i)
    if (cut[i]) image.pixels[i] = Rgb(0.35f / exposure);
  // The markers' layer lies over the image, inside its 2 px margin and 1 px border.
  return "<div class=\"planimg\" style=\"position:relative;display:inline-block\">" + png_img(image, exposure, alt) +
         "<svg style=\"position:absolute;left:3px;top:3px\" width=\"" + std::to_string(image.width) + "\" height=\"" +
         std::to_string(image.height) + "\" xmlns=\"http://www.w3.org/2000/svg\" font-size=\"11\">" + markers + "</svg></div>";
}

/// A bar of a round length, a quarter of the plan's width at most, in its lower left corner.
std::string scale_bar(const PlanFrame& frame) {
  const double metres = round_length(0.25 * double(frame.width) * double(frame.pixel));
  const double length = metres / double(frame.pixel), y = double(frame.height) - 10.0;
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << "<g class=\"scalebar\"><rect x=\"4\" y=\"" << y - 13 << "\" width=\"" << length + 12 + 40
    << "\" height=\"20\" fill=\"white\" fill-opacity=\"0.8\"/><line x1=\"10\" y1=\"" << y << "\" x2=\"" << 10 + length << "\" y2=\"" << y
    << "\" stroke=\"black\" stroke-width=\"3\"/><text x=\"" << 14 + length << "\" y=\"" << y + 4 << "\">" << std::setprecision(metres < 1 ? 1 : 0)
    << metres << " m</text></g>";
  return s.str();
}

/// sRGB in [0, 1] back to linear, so that encode_png gives the colour back.
float srgb_decode(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

/// The lux plan in false colour over [0, top]; cut walls grey.
Image false_colour_plan(const Image& lux, const std::vector<uint8_t>& cut, double top) {
  Image out(lux.width, lux.height);
  out.covered = lux.covered;
  for (size_t i = 0; i < lux.pixels.size(); ++i) {
    if (!lux.covered[i]) continue;
    const Rgb c = cut[i] ? Rgb(0.35f) : false_colour(double(lux.pixels[i].r) / top);
    for (int k = 0; k < 3; ++k) out.pixels[i][k] = srgb_decode(c[k]);
  }
  return out;
}

/// The top of the colour scale: a round number over the brightest 2% of what the plan sees.
double scale_top(const Image& lux, const std::vector<uint8_t>& cut) {
  std::vector<float> seen;
  for (size_t i = 0; i < lux.pixels.size(); ++i)
    if (lux.covered[i] && !cut[i]) seen.push_back(lux.pixels[i].r);
  if (seen.empty()) return 1.0;
  const size_t k = std::min(seen.size() - 1, size_t(0.98 * double(seen.size())));
  std::nth_element(seen.begin(), seen.begin() + std::ptrdiff_t(k), seen.end());
  return round_up(std::max(1.0, double(seen[k])));
}

/// Isolines over a lux plan (marching squares between pixel centres, cells
/// with a cut or uncovered corner left out) at round levels, about five
/// between its least lux and the scale's top: SVG paths in the plan's
/// pixels, each labelled with its level.
std::string plan_isolines(const Image& lux, const std::vector<uint8_t>& cut, double top) {
  const int w = lux.width, h = lux.height;
  const auto valid = [&](int x, int y) {
    const size_t i = size_t(y) * size_t(w) + size_t(x);
    return lux.covered[i] && !cut[i];
  };
  const auto value = [&](int x, int y) { return double(lux.pixels[size_t(y) * size_t(w) + size_t(x)].r); };
  double low = top;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (valid(x, y)) low = std::min(low, value(x, y));
  std::ostringstream s;
  s << std::fixed << std::setprecision(1);
  for (const double level : isoline_levels(low, top)) {
    std::ostringstream d;
    d << std::fixed << std::setprecision(1);
    std::pair<double, double> label{-1, -1};
    for (int y = 0; y + 1 < h; ++y)
      for (int x = 0; x + 1 < w; ++x) {
        const int cx[4] = {x, x + 1, x + 1, x}, cy[4] = {y, y, y + 1, y + 1};  // the cell's corners around it
        bool all = true;
        for (int k = 0; k < 4; ++k) all = all && valid(cx[k], cy[k]);
        if (!all) continue;
        std::pair<double, double> cross[4];
        int n = 0;
        for (int k = 0; k < 4; ++k) {
          const int j = (k + 1) % 4;
          const double a = value(cx[k], cy[k]), b = value(cx[j], cy[j]);
          if ((a < level) == (b < level)) continue;
          const double t = (level - a) / (b - a);
          cross[n++] = {double(cx[k]) + 0.5 + t * double(cx[j] - cx[k]), double(cy[k]) + 0.5 + t * double(cy[j] - cy[k])};
        }
        for (int k = 0; k + 1 < n; k += 2) {
          d << "M" << cross[k].first << "," << cross[k].second << "L" << cross[k + 1].first << "," << cross[k + 1].second;
          if (label.first < 0) label = cross[k];
        }
      }
    if (d.str().empty()) continue;
    s << "<path class=\"isoline\" d=\"" << d.str() << "\" stroke=\"black\" stroke-opacity=\"0.6\" stroke-width=\"0.8\" fill=\"none\"/>"
      << "<text x=\"" << label.first + 2 << "\" y=\"" << label.second - 2 << "\" font-size=\"9\">" << std::setprecision(level < 10 ? 1 : 0)
      << level << " lx</text>" << std::setprecision(1);
  }
  return s.str();
}

/// The colour scale under a lux plan: five ticks, each in lx.
std::string colour_scale(double top, int width) {
  const int bar = std::max(120, std::min(width - 40, 360)), steps = 40;
  std::ostringstream s;
  s << "<svg class=\"colour-scale\" width=\"" << bar + 40 << "\" height=\"34\" xmlns=\"http://www.w3.org/2000/svg\" font-size=\"10\">";
  for (int k = 0; k < steps; ++k)
    s << "<rect x=\"" << 10 + k * bar / steps << "\" y=\"2\" width=\"" << bar / steps + 1 << "\" height=\"12\" fill=\""
      << false_colour_css((double(k) + 0.5) / steps) << "\"/>";
  for (int t = 0; t <= 4; ++t) {
    const double value = top * double(t) / 4.0;
    s << "<line x1=\"" << 10 + t * bar / 4 << "\" y1=\"14\" x2=\"" << 10 + t * bar / 4 << "\" y2=\"18\" stroke=\"black\"/><text x=\""
      << 10 + t * bar / 4 - 8 << "\" y=\"29\">" << std::setprecision(value < 10 ? 2 : 0) << std::fixed << value << (t == 4 ? "+" : "")
      << " lx</text>";
  }
  s << "</svg>";
  return s.str();
}

} // namespace

std::string plans_html(const HtmlReport& page, int width) {
  const Scene& scene = *page.scene;
  const RayScene& rays = *page.rays;
  const bool painted = page.criteria == nullptr;
  const std::vector<PlanSection> sections = plan_sections(scene);
  const std::vector<Rgb> albedo = scene.vertex_albedo();
  const std::vector<Rgb> lux = vertex_lux(page.result, albedo);
  const PlanFrame frame(scene.bounds, width);
  const std::string bar = scale_bar(frame);
  std::ostringstream s;
  s << "<h2>Plans</h2><div class=\"views\">\n";
  for (size_t k = 0; k < sections.size(); ++k) {
    const PlanSection& at = sections[k];
    std::vector<uint8_t> cut;
    const Image result = plan_image(rays, frame, at.section, page.result, &cut);
    const Image target = painted ? plan_image(rays, frame, at.section, page.target) : Image();
    const Image lux_plan = plan_image(rays, frame, at.section, lux);
    const double top = scale_top(lux_plan, cut);
    // The result at its own exposure (a storey's light is not another's), the target at the same to compare.
    const float exposure = exposure_for(painted ? target : result);
    std::ostringstream markers, lux_markers;
    markers << std::fixed << std::setprecision(1);
    lux_markers << std::fixed << std::setprecision(1);
    for (size_t j : lights_in(sections, k, page.lights)) {
      const glm::vec2 p = frame.pixel_of(page.lights[j].position);
      const auto floor_lux = lux_on_floor(rays, page.result, albedo, page.lights[j].position, at.floor);
      std::ostringstream label;
      label << j;
      if (floor_lux) label << ": " << std::llround(*floor_lux) << " lx";
      const std::string text = "<text x=\"" + std::to_string(p.x + 8) + "\" y=\"" + std::to_string(p.y - 6) +
                               "\" fill=\"#ffe680\" stroke=\"#000\" stroke-width=\"3\" paint-order=\"stroke\">" + label.str() + "</text>";
      markers << "<circle class=\"light-marker\" data-light=\"" << j << "\" cx=\"" << p.x << "\" cy=\"" << p.y
              << "\" r=\"5\" fill=\"#ffd21f\" stroke=\"#000\" stroke-width=\"1.5\"/>" << text;
      lux_markers << "<circle class=\"lux-marker\" cx=\"" << p.x << "\" cy=\"" << p.y << "\" r=\"5\" fill=\"white\" stroke=\"#000\" "
                  << "stroke-width=\"1.5\"/>" << text;
    }
    const double floor_y = to_world(Vec3(0.f, at.floor, 0.f), scene.frame).y, cut_y = to_world(Vec3(0.f, at.section, 0.f), scene.frame).y;
    s << std::fixed << std::setprecision(2) << "<div class=\"view plan\" id=\"plan-" << k << "\"><h3>Storey " << k + 1 << ": floor at "
      << floor_y << " m, cut at " << cut_y << " m</h3>";
    if (painted) s << marked_plan(target, cut, exposure, "target, plan of storey " + std::to_string(k + 1), bar) << "<br>";
    s << marked_plan(result, cut, exposure, "result, plan of storey " + std::to_string(k + 1), markers.str() + bar) << "<br>"
      << "<div class=\"luxplan\" id=\"luxplan-" << k << "\">"
      << marked_plan(false_colour_plan(lux_plan, cut, top), std::vector<uint8_t>(), 1.f, "lux, plan of storey " + std::to_string(k + 1),
                     plan_isolines(lux_plan, cut, top) + lux_markers.str() + bar)
      << "<br>" << colour_scale(top, frame.width) << "</div></div>\n";
  }
  s << "</div><p class=\"legend\">Each storey seen from above, cut at the height given (1.5 m over its floor, or halfway to the "
       "next floor when that is nearer; north, −Z, up; walls cut through in grey)"
    << (painted ? ": the target, then what the lights give (same exposure)" : ": what the lights give")
    << ", then the illuminance on the surfaces seen from above in false colour (lx, the scale below each; lines: isolines, "
       "each labelled with its lux). Each light is marked "
       "in its storey with its number and the illuminance on the floor straight below it (through furniture); the bar is a "
       "length in metres.</p>\n";
  return s.str();
}

} // namespace hilight
