// ism-vulkan through the real launcher: requests the device cannot serve
// fail with one clear line and exit 2; a clean run under the validation
// layer reports nothing, not even objects left alive at shutdown.
#include "support.hpp"

#include <catch2/catch.hpp>

namespace {

const std::string kRoom = HILIGHT_SOURCE_DIR "/scenes/room.obj";
const std::string kRoomLights = HILIGHT_SOURCE_DIR "/scenes/room-4lights.json";

} // namespace

TEST_CASE("ism-vulkan: a scene too large for the memory budget fails with one clear line", "[ism][bad-input]") {
  if (test::skip_without_renderer("ism-vulkan")) return;
  auto dir = test::output_dir("ism_memory_limit");
  const auto out = dir / "out.ply";
  auto r = test::run_hilight({"render", kRoom, "--lights", kRoomLights, "--renderer", "ism-vulkan", "--set", "memory_mb=1", "-o",
                              out.string()});
  INFO(r.err);
  CHECK(r.exit_code == 2);
  CHECK(test::line_count(r.err) == 1);
  CHECK(r.err.find("ism-vulkan") != std::string::npos);
  CHECK(r.err.find("memory") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(out));
}

TEST_CASE("ism-vulkan: unknown device and bad settings are refused by name", "[ism][bad-input]") {
  if (test::skip_without_renderer("ism-vulkan")) return;
  auto dir = test::output_dir("ism_bad_settings");
  for (const char* setting : {"device=7", "ism_size=30", "vpls=0", "no_such_key=1"}) {
    auto r = test::run_hilight({"render", kRoom, "--lights", kRoomLights, "--renderer", "ism-vulkan", "--set", setting, "-o",
                                (dir / "out.ply").string()});
    INFO(setting << ": " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(test::line_count(r.err) == 1);
  }
}

TEST_CASE("ism-vulkan: a render and an image under the validation layer report no errors and leave nothing alive",
          "[ism][validation]") {
  if (test::skip_without_renderer("ism-vulkan")) return;
  auto dir = test::output_dir("ism_clean_run");
  // Every bounce: the bounce points' maps and their series run too (few
  // points: this is about the Vulkan calls, not the light).
  auto r = test::run_hilight({"render", kRoom, "--lights", kRoomLights, "--renderer", "ism-vulkan", "--set", "validation=true",
                              "--bounces", "all", "--set", "bounce_points=256", "--width", "160", "--height", "120", "-o", (dir / "out.ply").string(), "-o",
                              (dir / "out.png").string()});
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.err.find("Vulkan validation") == std::string::npos);
  CHECK(std::filesystem::exists(dir / "out.png"));
}
