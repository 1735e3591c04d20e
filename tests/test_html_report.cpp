// `hilight solve --report-html` (issue 14): a self-contained page, opened in
// a real headless browser (Debian's chromium): every embedded image decodes,
// the console stays clean, and the page holds what it promises.
#include "support.hpp"

#include <catch2/catch.hpp>

namespace {

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

} // namespace

TEST_CASE("the solve's HTML report renders in a headless browser with its images, plot and lights", "[report][cli]") {
  const auto dir = test::output_dir("html_report");
  const std::string room = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  REQUIRE(test::run_hilight({"render", room, "--lights", std::string(HILIGHT_SOURCE_DIR) + "/scenes/room-4lights.json", "-o",
                             (dir / "target.ply").string(), "--max-edge", "0.5"}).exit_code == 0);
  const auto r = test::run_hilight({"solve", room, "--target", (dir / "target.ply").string(), "-o", (dir / "lights.json").string(),
                                    "--max-edge", "0.5", "--report-html", (dir / "report.html").string(), "--cache-dir",
                                    (dir / "cache").string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const std::string html = test::read_file(dir / "report.html");
  // Target, result, difference from three views; the room's plan: target, result, lux in false colour.
  CHECK(count(html, "<img ") == 12);
  CHECK(count(html, "src=\"data:image/png;base64,") == 12);
  CHECK(count(html, "class=\"view plan\"") == 1);
  CHECK(count(html, "class=\"light-marker\"") == count(test::read_file(dir / "lights.json"), "\"position\""));  // one a light
  CHECK(count(html, "<svg id=\"cuts\"") == 1);
  CHECK(count(html, "class=\"chosen\"") == 1);
  CHECK(count(html, "<tr><td>") >= 4 + 3);  // four lights, and timings
  CHECK(html.find("http") == html.find("http://www.w3.org/2000/svg"));  // nothing fetched from elsewhere

  if (test::skip_without_chromium()) return;
  const test::BrowserPage page = test::open_in_chromium(dir / "report.html");
  INFO(page.log.substr(0, 2000));
  CHECK(test::page_is_clean(page));
}
