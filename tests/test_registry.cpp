// The plugin registry: real modules load, refused modules say why, names are
// unique, and options nobody reads are errors.
#include "hilight/error.hpp"
#include "hilight/plugin.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

using namespace hilight;

TEST_CASE("the build's modules load: the embree renderer and the cli frontend", "[plugins]") {
  Registry& reg = test::registry();
  const ModuleRecord* embree = reg.find("renderer", "embree");
  REQUIRE(embree);
  CHECK(embree->loaded);
  CHECK(embree->problem.empty());
  CHECK_FALSE(embree->version.empty());
  CHECK(reg.find("frontend", "cli"));
  CHECK(reg.frontend_for("render") != nullptr);
  CHECK(reg.frontend_for("no-such-command") == nullptr);
  CHECK(reg.renderer_unavailable_reason("embree").empty());
}

TEST_CASE("renderers declare whether their direct light is cheap enough to settle fine-tune", "[plugins]") {
  // The solve settles fine-tune's answer with hundreds of direct renders
  // only where the renderer says they take milliseconds (command_solve.cpp).
  Registry& reg = test::registry();
  CHECK(reg.renderer_traits("embree").cheap_direct);
  for (const char* other : {"povray", "ism-vulkan"})
    if (reg.find("renderer", other)) CHECK_FALSE(reg.renderer_traits(other).cheap_direct);
}

TEST_CASE("a module built against another ABI version is refused with a clear message", "[plugins][abi]") {
  Registry reg;
  const ModuleRecord& rec = reg.load_module(std::string(HILIGHT_TEST_PLUGIN_DIR) + "/hilight-renderer-wrong-abi.so");
  CHECK_FALSE(rec.loaded);
  CHECK_THAT(rec.problem, Catch::Contains("ABI version " + std::to_string(HILIGHT_ABI_VERSION + 1)));
  CHECK_THAT(rec.problem, Catch::Contains("rebuild"));
  CHECK(reg.find("renderer", "wrong-abi") == nullptr);
  CHECK_THROWS_WITH(reg.create_renderer("wrong-abi", {}), Catch::Contains("ABI version"));
}

TEST_CASE("a module built by another compiler or standard library is refused", "[plugins][abi]") {
  Registry reg;
  const ModuleRecord& rec = reg.load_module(std::string(HILIGHT_TEST_PLUGIN_DIR) + "/hilight-renderer-wrong-key.so");
  CHECK_FALSE(rec.loaded);
  CHECK_THAT(rec.problem, Catch::Contains("othercc-99"));
  CHECK_THAT(rec.problem, Catch::Contains(HILIGHT_BUILD_KEY));
}

TEST_CASE("a file that is not a hilight module is reported, not loaded", "[plugins]") {
  Registry reg;
  auto dir = test::output_dir("registry_not_a_module");
  test::write_text(dir / "hilight-renderer-garbage.so", "this is not an ELF file");
  const ModuleRecord& rec = reg.load_module(dir / "hilight-renderer-garbage.so");
  CHECK_FALSE(rec.loaded);
  CHECK_THAT(rec.problem, Catch::Contains("cannot load"));
}

TEST_CASE("a second module with the same kind and name is refused as a duplicate", "[plugins]") {
  Registry reg;
  std::string path = std::string(HILIGHT_PLUGIN_DIR) + "/hilight-renderer-embree.so";
  CHECK(reg.load_module(path).loaded);
  const ModuleRecord& second = reg.load_module(path);
  CHECK_FALSE(second.loaded);
  CHECK_THAT(second.problem, Catch::Contains("duplicate"));
  CHECK(reg.names("renderer") == std::vector<std::string>{"embree"});
}

TEST_CASE("unknown renderers and unread options are input errors", "[plugins]") {
  Registry& reg = test::registry();
  CHECK_THROWS_AS(reg.create_renderer("nosuch", {}), InputError);
  CHECK_THROWS_WITH(reg.create_renderer("nosuch", {}), Catch::Contains("available: embree"));
  CHECK_THROWS_WITH(reg.create_renderer("embree", Properties::from_assignments({"bounce_sampels=4"})),
                    Catch::Contains("unknown option 'bounce_sampels'"));
  // Two bounces are a valid count now (every bounce, issue 32); what is not a count is refused.
  CHECK_NOTHROW(reg.create_renderer("embree", Properties::from_assignments({"bounces=2"})));
  CHECK_THROWS_WITH(reg.create_renderer("embree", Properties::from_assignments({"bounces=1001"})), Catch::Contains("bounces"));
  CHECK_THROWS_WITH(reg.create_renderer("embree", Properties::from_assignments({"bounces=most"})), Catch::Contains("bounces"));
  CHECK_THROWS_AS(Properties::from_assignments({"novalue"}), InputError);
}
