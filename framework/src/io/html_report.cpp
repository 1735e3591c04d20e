// The solve's HTML report (io/html_report.hpp). Views: three of the default
// views (default_view.hpp): inside the largest lit room, or around the scene.
#include "hilight/io/html_report.hpp"

#include "html_lux_maps.hpp"
#include "html_parts.hpp"
#include "html_plans.hpp"
#include "hilight/scene_origin.hpp"

#include "hilight/camera.hpp"
#include "hilight/default_view.hpp"
#include "hilight/io/atomic_file.hpp"
#include "hilight/io/image_io.hpp"
#include "hilight/units.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <tbb/parallel_for.h>

namespace hilight {

namespace {

/// Red where the result is brighter than the target, blue where darker.
Image difference_image(const Image& result, const Image& target, float exposure) {
  Image out(result.width, result.height);
  for (size_t i = 0; i < out.pixels.size(); ++i) {
    out.covered[i] = result.covered[i];
    const float d = (0.2126f * (result.pixels[i].r - target.pixels[i].r) + 0.7152f * (result.pixels[i].g - target.pixels[i].g) +
                     0.0722f * (result.pixels[i].b - target.pixels[i].b)) * exposure * 4.f;
    out.pixels[i] = d > 0 ? Rgb(std::min(d, 1.f), 0.f, 0.f) : Rgb(0.f, 0.f, std::min(-d, 1.f));
  }
  return out;
}

std::string dbar_plot(const SolveReport& r, size_t chosen_points) {
  if (r.cuts.empty()) {
    // The spot search's answer replaces the point lights' hierarchy: say so, not that the lights were given.
    const bool spots_won = std::any_of(r.stages.begin(), r.stages.end(), [](const StageRecord& s) { return s.name == "spot search" && s.kept; });
    return spots_won ? "<p>No light-count walk: spotlights replaced the point lights (the spot search's answer has no hierarchy).</p>"
                     : "<p>No hierarchy (the lights were given).</p>";
  }
  double top = 0;
  size_t most = 1;
  for (const auto& c : r.cuts) {
    top = std::max({top, c.dbar_initial, c.refined ? c.dbar_refined : 0.0});
    most = std::max(most, c.lights);
  }
  top = std::max(top, 1e-6);
  const int w = 420, h = 220, left = 50, bottom = 30;
  auto x = [&](size_t n) { return left + double(n - 1) / double(std::max<size_t>(most - 1, 1)) * (w - left - 20); };
  auto y = [&](double d) { return h - bottom - d / top * (h - bottom - 20); };
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << "<svg id=\"cuts\" width=\"" << w << "\" height=\"" << h
    << "\" xmlns=\"http://www.w3.org/2000/svg\" font-size=\"11\">"
    << "<line x1=\"" << left << "\" y1=\"" << h - bottom << "\" x2=\"" << w - 10 << "\" y2=\"" << h - bottom << "\" stroke=\"#444\"/>"
    << "<line x1=\"" << left << "\" y1=\"10\" x2=\"" << left << "\" y2=\"" << h - bottom << "\" stroke=\"#444\"/>"
    << "<text x=\"" << w / 2 << "\" y=\"" << h - 5 << "\">point lights in the cut</text>"
    << "<text x=\"4\" y=\"14\">D̄ " << 100 * top << "%</text><text x=\"30\" y=\"" << h - bottom << "\">0</text>";
  std::string initial, refined;
  for (const auto& c : r.cuts) {
    initial += std::to_string(x(c.lights)) + "," + std::to_string(y(c.dbar_initial)) + " ";
    if (c.refined) refined += std::to_string(x(c.lights)) + "," + std::to_string(y(c.dbar_refined)) + " ";
    s << "<text x=\"" << x(c.lights) - 3 << "\" y=\"" << h - bottom + 13 << "\">" << c.lights << "</text>";
  }
  s << "<polyline fill=\"none\" stroke=\"#999\" points=\"" << initial << "\"/>";
  if (!refined.empty()) s << "<polyline fill=\"none\" stroke=\"#06c\" stroke-width=\"2\" points=\"" << refined << "\"/>";
  for (const auto& c : r.cuts) {
    if (c.lights != chosen_points) continue;
    s << "<circle class=\"chosen\" cx=\"" << x(c.lights) << "\" cy=\"" << y(c.refined ? c.dbar_refined : c.dbar_initial)
      << "\" r=\"6\" fill=\"none\" stroke=\"#c00\" stroke-width=\"2\"/>";
    break;
  }
  s << "</svg><p class=\"legend\">grey: D̄ of each cut at the samples with intensities re-fitted; blue: after refinement; "
    << "red circle: the count chosen (" << chosen_points << " point lights, eq. 9).</p>";
  return s.str();
}

} // namespace

Image vertex_value_image(const Scene& scene, const RayScene& rays, const Camera& camera, const std::vector<Rgb>& values,
                         int width, int height) {
  Image image(width, height);
  const Camera::Basis basis = camera.basis();
  const float aspect = float(width) / float(height);
  tbb::parallel_for(0, height, [&](int py) {
    for (int px = 0; px < width; ++px) {
      const float sx = (2.f * (float(px) + 0.5f) / float(width) - 1.f) * basis.tan_half_fov * aspect;
      const float sy = (1.f - 2.f * (float(py) + 0.5f) / float(height)) * basis.tan_half_fov;
      const Vec3 dir = glm::normalize(basis.forward + sx * basis.right + sy * basis.up);
      const Hit hit = rays.intersect(camera.eye, dir);
      if (!hit.valid()) continue;
      const auto& tri = scene.triangles[hit.triangle];
      const size_t i = size_t(py) * size_t(width) + size_t(px);
      image.pixels[i] = (1.f - hit.u - hit.v) * values[tri[0]] + hit.u * values[tri[1]] + hit.v * values[tri[2]];
      image.covered[i] = 1;
    }
  });
  return image;
}

void write_html_report(const std::filesystem::path& path, const HtmlReport& page, int width) {
  const int height = width * 3 / 4;
  const Scene& scene = *page.scene;
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>hilight: " << html_escape(page.title)
       << "</title>\n<style>body{font-family:sans-serif;margin:1.5em;max-width:1600px}td,th{padding:2px 8px;text-align:right}"
          "th{background:#eee}table{border-collapse:collapse}img{margin:2px;border:1px solid #ccc}.views{display:flex;flex-wrap:wrap}"
          ".view{margin-right:1em}.legend{color:#555;font-size:90%}</style></head><body>\n";
  html << "<h1>hilight solve</h1><p>" << html_escape(page.title) << "</p>\n";
  if (page.criteria)
    html << std::setprecision(4) << "<p id=\"summary\"><b>" << page.lights.size() << " luminaires</b>, criteria "
         << (page.design.met ? "met" : "<b>not met</b>") << ", " << page.report.seconds.at("total") << " s.</p>\n";
  else
    html << std::setprecision(4) << "<p id=\"summary\"><b>" << page.lights.size() << " lights</b>, D̄ <b>" << 100.0 * page.report.dbar
         << "%</b> over " << page.report.dbar_points << " of " << page.report.target_points << " target points, "
         << page.report.seconds.at("total") << " s.</p>\n";
  // Views: one exposure for target and result, so they compare.
  const bool painted = page.criteria == nullptr;  // criteria have no painted target to show
  html << (painted ? "<h2>Target, result, difference</h2>" : "<h2>Result</h2>") << "<div class=\"views\">\n";
  int view_number = 0;
  for (const Camera& cam : default_views(*page.rays, page.lights, float(width) / float(height), 3)) {
    ++view_number;
    const Image target = vertex_value_image(scene, *page.rays, cam, painted ? page.target : page.result, width, height);
    const Image result = vertex_value_image(scene, *page.rays, cam, page.result, width, height);
    const float exposure = exposure_for(target);
    html << "<div class=\"view\"><h3>View " << view_number << "</h3>";
    if (painted) html << png_img(target, exposure, "target, view " + std::to_string(view_number)) << "<br>";
    html << png_img(result, exposure, "result, view " + std::to_string(view_number));
    if (painted) html << "<br>" << png_img(difference_image(result, target, exposure), 1.f, "difference, view " + std::to_string(view_number));
    html << "</div>\n";
  }
  if (painted) {
    html << "</div><p class=\"legend\">Rows: the target, what the lights give (same exposure), their difference (red: "
            "brighter than wanted, blue: darker; 4× the exposure).</p>\n";
    const size_t points = size_t(std::count_if(page.lights.begin(), page.lights.end(), [](const Light& l) { return l.type != LightType::Spot; }));
    html << "<h2>D̄ against the light count</h2>" << dbar_plot(page.report, points) << "\n";
  } else {
    html << "</div>\n" << lux_maps_html(*page.criteria, page.design, page.lights);
  }
  html << plans_html(page, width);
  const bool photometric = page.units == "photometric";
  const bool luminaires = std::any_of(page.lights.begin(), page.lights.end(), [](const Light& l) { return bool(l.profile); });
  html << "<h2>Lights</h2><table id=\"lights\"><tr><th>#</th><th>type</th><th>x</th><th>y</th><th>z</th><th>intensity "
       << (photometric ? "(cd)" : "(W/sr)") << "</th><th>flux (lm)</th>"
       << (luminaires ? "<th>product</th><th>aim</th><th>dimming (%)</th><th>W</th>" : "") << "</tr>\n";
  for (size_t j = 0; j < page.lights.size(); ++j) {
    const Light& l = page.lights[j];
    const Rgb shown = photometric ? l.intensity * float(kLumensPerWatt) : l.intensity;
    const glm::dvec3 at = to_world(l.position, scene.frame);  // where it stands in the file's coordinates (scene_origin.hpp)
    html << "<tr><td>" << j << "</td><td>" << to_string(l.type) << "</td><td>" << at.x << "</td><td>" << at.y
         << "</td><td>" << at.z << "</td><td>" << shown.r << ", " << shown.g << ", " << shown.b << "</td><td>"
         << luminous_flux(l) << "</td>";
    if (luminaires && l.profile) {
      const double d = luminaire_dimming(l);
      html << "<td>" << html_escape(l.profile->product.empty() ? std::filesystem::path(l.profile_path).filename().string() : l.profile->product) << "</td><td>"
           << l.direction.x << ", " << l.direction.y << ", " << l.direction.z << "</td><td>" << 100.0 * d << "</td><td>"
           << d * l.profile->input_watts << "</td>";
    }
    html << "</tr>\n";
  }
  html << "</table>\n<h2>Timings</h2><table id=\"timings\"><tr><th>stage</th><th>seconds</th></tr>\n";
  for (const auto& [stage, seconds] : page.report.seconds) html << "<tr><td>" << html_escape(stage) << "</td><td>" << seconds << "</td></tr>\n";
  html << "</table>\n<p class=\"legend\">Written by hilight. D̄ = ‖Ψ − I‖ / ‖Ψ‖ over the target points, measured with the "
          "reference renderer.</p>\n";
  // Checked by the tests in a headless browser: every embedded image decoded.
  html << "<script>document.body.dataset.imagesOk = [...document.images].every(i => i.complete && i.naturalWidth > 0);</script>\n";
  html << "</body></html>\n";
  const std::string text = html.str();
  write_atomically(path, text);
}

} // namespace hilight
