// The HTML report's plans (html_plans.hpp).
#include "html_plans.hpp"

#include "html_parts.hpp"
#include "hilight/plan_view.hpp"
#include "hilight/scene_origin.hpp"

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

} // namespace

std::string plans_html(const HtmlReport& page, int width) {
  const Scene& scene = *page.scene;
  const RayScene& rays = *page.rays;
  const bool painted = page.criteria == nullptr;
  const std::vector<PlanSection> sections = plan_sections(scene);
  const std::vector<Rgb> albedo = scene.vertex_albedo();
  const PlanFrame frame(scene.bounds, width);
  std::ostringstream s;
  s << "<h2>Plans</h2><div class=\"views\">\n";
  for (size_t k = 0; k < sections.size(); ++k) {
    const PlanSection& at = sections[k];
    std::vector<uint8_t> cut;
    const Image result = plan_image(rays, frame, at.section, page.result, &cut);
    const Image target = painted ? plan_image(rays, frame, at.section, page.target) : Image();
    const float exposure = exposure_for(painted ? target : result);
    std::ostringstream markers;
    markers << std::fixed << std::setprecision(1);
    for (size_t j : lights_in(sections, k, page.lights)) {
      const glm::vec2 p = frame.pixel_of(page.lights[j].position);
      const auto lux = lux_below(rays, page.result, albedo, page.lights[j].position);
      std::ostringstream label;
      label << j;
      if (lux) label << ": " << std::llround(*lux) << " lx";
      markers << "<circle class=\"light-marker\" data-light=\"" << j << "\" cx=\"" << p.x << "\" cy=\"" << p.y
              << "\" r=\"5\" fill=\"#ffd21f\" stroke=\"#000\" stroke-width=\"1.5\"/><text x=\"" << p.x + 8 << "\" y=\"" << p.y - 6
              << "\" fill=\"#ffe680\" stroke=\"#000\" stroke-width=\"3\" paint-order=\"stroke\">" << label.str() << "</text>";
    }
    const double floor_y = to_world(Vec3(0.f, at.floor, 0.f), scene.frame).y, cut_y = to_world(Vec3(0.f, at.section, 0.f), scene.frame).y;
    s << std::fixed << std::setprecision(2) << "<div class=\"view plan\" id=\"plan-" << k << "\"><h3>Storey " << k + 1 << ": floor at "
      << floor_y << ", cut at " << cut_y << "</h3>";
    if (painted) s << marked_plan(target, cut, exposure, "target, plan of storey " + std::to_string(k + 1), "") << "<br>";
    s << marked_plan(result, cut, exposure, "result, plan of storey " + std::to_string(k + 1), markers.str()) << "</div>\n";
  }
  s << "</div><p class=\"legend\">Each storey seen from above, cut at the height given (1.5 m over its floor, or halfway to the "
       "next floor when that is nearer; north, −Z, up; walls cut through in grey)"
    << (painted ? ": the target, then what the lights give (same exposure)" : "")
    << ". Each light is marked in its storey with its number and the lux on the surface straight below it.</p>\n";
  return s.str();
}

} // namespace hilight
