// Plans (plan_view.hpp, issue 20): the storeys of a real building, its plan
// cut through the walls, the lux readout under a light, and the solve's HTML
// report with a plan of each storey and one marker per light.
#include "hilight/io/html_report.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/plan_view.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "hilight/surface_points.hpp"
#include "random_lights.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <random>

using namespace hilight;

namespace {

std::shared_ptr<const Scene> house() {
  return std::make_shared<const Scene>(load_scene(builders::testmodels_dir() / "IFC/AC14-FZK-Haus.ifc"));
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// The storey of `sections` a light at height y stands in.
size_t storey_of(const std::vector<PlanSection>& sections, float y) {
  size_t k = 0;
  while (k + 1 < sections.size() && y >= sections[k].top) ++k;
  return k;
}

} // namespace

TEST_CASE("plan readout: the lux below a light over a floor is 683 I / h squared", "[plan]") {
  const auto scene = test::finish(builders::plane(5.f, Rgb(0.6f, 0.7f, 0.8f)), 0.1f);
  const auto rays = RayScene::shared(scene);
  Light light;
  light.position = Vec3(0.3f, 2.f, -0.2f);
  light.intensity = Rgb(4.f);
  auto renderer = test::make_renderer("embree", scene, {"bounces=0"});
  const std::vector<Rgb> radiance = renderer->illuminate(SurfacePoints::from_vertices(*scene), Lighting{light});
  const std::vector<Rgb> albedo = scene->vertex_albedo();
  const auto lux = lux_below(*rays, radiance, albedo, light.position);
  REQUIRE(lux);
  CHECK(*lux == Approx(683.0 * 4.0 / (2.0 * 2.0)).epsilon(0.01));  // the nearest vertex is within 0.07 of straight below
  // Nothing below, or no result yet: no readout.
  CHECK_FALSE(lux_below(*rays, radiance, albedo, Vec3(0.f, -1.f, 0.f)));
  CHECK_FALSE(lux_below(*rays, {}, albedo, light.position));
}

TEST_CASE("plan readout: the lux on the floor below a light, not on a plate 2 cm under it (issue 36)", "[plan]") {
  Scene raw = builders::plane(5.f, Rgb(0.6f, 0.7f, 0.8f));
  // A 10 cm plate 2 cm under the first light (its own fitting, a shelf), facing up.
  builders::add_quad(raw, Vec3(-0.05f, 1.98f, 0.05f), Vec3(0.05f, 1.98f, 0.05f), Vec3(0.05f, 1.98f, -0.05f), Vec3(-0.05f, 1.98f, -0.05f),
                     Rgb(0.5f), "plate");
  const auto scene = test::finish(std::move(raw), 0.1f);
  const auto rays = RayScene::shared(scene);
  const Lighting lights{Light::point(Vec3(0.f, 2.f, 0.f), Rgb(4.f)), Light::point(Vec3(2.5f, 2.f, 0.3f), Rgb(4.f))};
  auto renderer = test::make_renderer("embree", scene, {"bounces=0"});
  const std::vector<Rgb> radiance = renderer->illuminate(SurfacePoints::from_vertices(*scene), lights);
  const std::vector<Rgb> albedo = scene->vertex_albedo();
  const std::vector<PlanSection> sections = plan_sections(*scene);
  REQUIRE(sections.size() == 1);
  CHECK(storey_floor(sections, lights[0].position) == Approx(0.f).margin(0.1f));
  // The old readout: the plate, 683 · 8 / 0.02² lx from both lights at once.
  const auto on_plate = lux_below(*rays, radiance, albedo, lights[0].position);
  REQUIRE(on_plate);
  CHECK(*on_plate > 1e6);
  // The floor under the plate is in its shadow: the second light alone reaches it, from 2.5 m aside.
  const auto under_plate = lux_on_floor(*rays, radiance, albedo, lights[0].position, 0.f);
  REQUIRE(under_plate);
  const double aside = std::hypot(2.5, 0.3), distance = std::hypot(aside, 2.0);
  CHECK(*under_plate == Approx(683.0 * 4.0 * (2.0 / distance) / (distance * distance)).epsilon(0.03));
  // Nothing over the floor under the second light: 683 I / h², the first light's cone under its plate (68° wide) aside.
  const auto open_floor = lux_on_floor(*rays, radiance, albedo, lights[1].position, 0.f);
  REQUIRE(open_floor);
  CHECK(*open_floor == Approx(683.0 * 4.0 / 4.0).epsilon(0.03));
  // No floor near the storey's height: no readout.
  CHECK_FALSE(lux_on_floor(*rays, radiance, albedo, lights[1].position, 1.f));
  CHECK_FALSE(lux_on_floor(*rays, {}, albedo, lights[1].position, 0.f));
}

TEST_CASE("plans of the IFC house: its two storeys, the walls cut through, the floor under every ceiling lamp seen", "[plan]") {
  const auto scene = house();
  const auto rays = RayScene::shared(scene);
  const std::vector<PlanSection> sections = plan_sections(*scene);
  REQUIRE(sections.size() == 2);
  CHECK(sections[1].floor - sections[0].floor > 2.5f);
  for (const PlanSection& s : sections) {
    CHECK(s.section - s.floor > 1.f);
    CHECK(s.section - s.floor <= 1.5f + 1e-4f);
  }
  const PlanFrame frame(scene->bounds, 300);
  const std::vector<Rgb> ones(scene->positions.size(), Rgb(1.f));
  std::vector<Image> plans;
  std::vector<std::vector<uint8_t>> cuts(sections.size());
  for (size_t k = 0; k < sections.size(); ++k) {
    plans.push_back(plan_image(*rays, frame, sections[k].section, ones, &cuts[k]));
    const double pixels = double(plans[k].pixels.size());
    const double cut = double(std::count(cuts[k].begin(), cuts[k].end(), 1)) / pixels;
    const double covered = double(std::count(plans[k].covered.begin(), plans[k].covered.end(), 1)) / pixels;
    INFO("storey " << k << ": cut " << cut << ", covered " << covered);
    CHECK(cut > 0.01);  // walls
    CHECK(cut < 0.3);
    CHECK(covered > 0.3);
  }
  // Seeded lamps under the house's ceilings: the floor straight below each
  // is seen in its storey's plan, not a wall.
  std::mt19937_64 rng(20);
  for (const Light& lamp : test::random_ceiling_lamps(*rays, rng, 8)) {
    const size_t k = storey_of(sections, lamp.position.y);
    const glm::vec2 p = frame.pixel_of(lamp.position);
    const size_t i = size_t(p.y) * size_t(frame.width) + size_t(p.x);
    INFO("lamp at " << lamp.position.x << ", " << lamp.position.y << ", " << lamp.position.z << " in storey " << k);
    REQUIRE(i < plans[k].pixels.size());
    CHECK(plans[k].covered[i]);
    CHECK_FALSE(cuts[k][i]);
  }
}

TEST_CASE("the HTML report's plans of the IFC house mark each light once, in its storey, with the lux on its floor, and map the lux",
          "[plan][report]") {
  const auto scene = house();
  const auto rays = RayScene::shared(scene);
  std::mt19937_64 rng(21);
  const Lighting lights = test::random_ceiling_lamps(*rays, rng, 5);
  auto renderer = test::make_renderer("embree", scene, {"bounces=0"});
  HtmlReport page;
  page.scene = scene.get();
  page.rays = rays.get();
  page.title = "plans";
  page.result = renderer->illuminate(SurfacePoints::from_vertices(*scene), lights);
  page.target = page.result;
  page.target_weight.assign(scene->positions.size(), 1.f);
  page.lights = lights;
  page.report.seconds["total"] = 0.0;
  const auto dir = test::output_dir("plan_report");
  write_html_report(dir / "plans.html", page, 360);
  const std::string html = test::read_file(dir / "plans.html");
  const std::vector<PlanSection> sections = plan_sections(*scene);
  REQUIRE(count(html, "class=\"view plan\"") == sections.size());
  CHECK(count(html, "class=\"light-marker\"") == lights.size());
  const std::vector<Rgb> albedo = scene->vertex_albedo();
  for (size_t j = 0; j < lights.size(); ++j) {
    INFO("light " << j);
    const std::string marker = "data-light=\"" + std::to_string(j) + "\"";
    REQUIRE(count(html, marker) == 1);
    // In its own storey's plan: after that plan's start, before the next one's.
    const size_t k = storey_of(sections, lights[j].position.y), at = html.find(marker);
    CHECK(at > html.find("id=\"plan-" + std::to_string(k) + "\""));
    CHECK(at < html.find("id=\"plan-" + std::to_string(k + 1) + "\""));
    const auto lux = lux_on_floor(*rays, page.result, albedo, lights[j].position, sections[k].floor);
    REQUIRE(lux);
    CHECK(*lux > 1.0);
    // On the result's plan and on the lux map: the same label.
    CHECK(count(html, ">" + std::to_string(j) + ": " + std::to_string(std::llround(*lux)) + " lx<") == 2);
  }
  // Each storey: a lux map with its colour scale (every tick in lx) and scale bars (in m) on its plans.
  CHECK(count(html, "class=\"luxplan\"") == sections.size());
  CHECK(count(html, "class=\"colour-scale\"") == sections.size());
  CHECK(count(html, "class=\"scalebar\"") == 3 * sections.size());  // target, result and lux plans
  CHECK(count(html, " lx</text>") >= 5 * sections.size());
  // Isolines on each storey's lux map (issue 34), in its div, each labelled in lx.
  for (size_t k = 0; k < sections.size(); ++k) {
    INFO("storey " << k);
    const size_t from = html.find("id=\"luxplan-" + std::to_string(k) + "\""), to = html.find("</div></div>", from);
    REQUIRE(from != std::string::npos);
    const std::string map = html.substr(from, to - from);
    CHECK(count(map, "class=\"isoline\"") >= 2);
    CHECK(count(map, "class=\"isoline\"") <= 12);
  }
  CHECK(count(html, " m</text></g>") == 3 * sections.size());
  CHECK(count(html, " m, cut at ") == sections.size());
  if (test::skip_without_chromium()) return;
  const test::BrowserPage browser = test::open_in_chromium(dir / "plans.html");
  INFO(browser.log.substr(0, 2000));
  CHECK(test::page_is_clean(browser));
}
