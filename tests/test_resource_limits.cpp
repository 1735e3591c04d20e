// Resource limits (issue 15): a tessellation that would exceed --max-vertices
// fails before it takes the memory, in one line naming the limit.
#include "support.hpp"

#include <catch2/catch.hpp>

namespace {
const std::string kRoom = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
}

TEST_CASE("a tessellation beyond --max-vertices fails early, naming the limit", "[cli][limits][bad-input]") {
  const auto fine = test::run_hilight({"info", kRoom, "--max-vertices", "20000"});
  INFO(fine.err);
  CHECK(fine.exit_code == 0);  // the default tessellation: 11,614 vertices
  const auto tight = test::run_hilight({"info", kRoom, "--max-vertices", "1000"});
  CHECK(tight.exit_code == 2);
  CHECK(test::line_count(tight.err) == 1);
  CHECK(tight.err.find("--max-vertices 1000") != std::string::npos);
  CHECK(tight.err.find(kRoom) != std::string::npos);
  // About 10^10 vertices asked for under the default limit: refused at once, in little memory.
  const auto dir = test::output_dir("limits");
  const auto huge = test::run_hilight({"render", kRoom, "--lights", std::string(HILIGHT_SOURCE_DIR) + "/scenes/room-4lights.json",
                                       "--max-edge", "0.0005", "-o", (dir / "out.ply").string()});
  CHECK(huge.exit_code == 2);
  CHECK(huge.err.find("--max-vertices 10000000") != std::string::npos);
  CHECK(huge.max_rss_kb < 300 * 1024);
  CHECK_FALSE(std::filesystem::exists(dir / "out.ply"));
}
