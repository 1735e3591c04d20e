// Light cache files read as untrusted input (issue 35): the checksum is no
// secret, so a forged file with a good checksum but sizes that wrap, a NaN
// origin, a huge block scale or values out of range is refused (rebuilt with
// a warning), never crashes a solve or changes its answer. A FIFO at the
// file's name does not hang the solve.
#include "hilight/hash.hpp"
#include "hilight/light_cache.hpp"
#include "hilight/light_cache_file.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <cmath>
#include <cstring>
#include <future>
#include <sys/stat.h>
#include <thread>

namespace fs = std::filesystem;
using namespace hilight;

namespace {

// The file's header (light_cache_file.cpp): magic 8, format 4, reserved 4,
// key 8, payload size 8, checksum 8. The grid cache's payload begins with
// its counts (2 × 8), origin (3 × 4), spacing (3 × 4) and dims (3 × 4).
constexpr size_t kHeader = 40, kChecksumAt = 32, kPayloadSizeAt = 24;
constexpr size_t kCountsAt = kHeader, kOriginAt = kHeader + 16, kDimsAt = kHeader + 40, kSlotsAt = kHeader + 52;

struct GridRig {
  std::shared_ptr<const Scene> scene = test::finish(builders::furnished_room(), 0.5f);
  std::shared_ptr<const RayScene> rays = std::make_shared<const RayScene>(*scene);
  std::unique_ptr<Renderer> renderer = test::make_renderer("embree", scene, {"bounce_samples=16", "bounce_direct=vertex"});
  std::unique_ptr<LightCacheBuilder> builder = test::registry().create_cache("grid", Properties::from_assignments({"cells=4"}));
  uint64_t key = light_cache_key(*scene, renderer->settings_key(), builder->settings_key(), scene->light_bounds());
  std::string bytes;  ///< a good file

  explicit GridRig(const fs::path& dir) {
    const auto cache = builder->build({*scene, *rays, *renderer, scene->light_bounds()});
    save_light_cache(dir / "good.bin", key, *cache);
    bytes = test::read_file(dir / "good.bin");
  }
  /// Loads `contents` (its checksum and size made right first, as a forger would).
  LoadedCache load_forged(const fs::path& dir, std::string contents) const {
    const uint64_t payload = contents.size() - kHeader;
    std::memcpy(&contents[kPayloadSizeAt], &payload, 8);
    const uint64_t sum = hash_words(kFnvOffset, contents.data() + kHeader, payload);
    std::memcpy(&contents[kChecksumAt], &sum, 8);
    test::write_text(dir / "forged.bin", contents);
    return load_light_cache(dir / "forged.bin", key, *builder, scene->positions.size());
  }
  /// Offset of the first node's first block (after the slots).
  size_t first_block() const {
    uint64_t slots = 0;
    std::memcpy(&slots, &bytes[kCountsAt], 8);
    return kSlotsAt + 4 * slots;
  }
};

template <class T>
void put(std::string& s, size_t at, const T& value) {
  std::memcpy(&s[at], &value, sizeof(T));
}

} // namespace

TEST_CASE("a forged light cache with a good checksum is refused, never read", "[cache][security]") {
  const auto dir = test::output_dir("cache_crafted");
  const GridRig rig(dir);
  REQUIRE(rig.load_forged(dir, rig.bytes).cache);  // the forging itself keeps a good file good

  SECTION("sizes whose product wraps to 0") {
    std::string f = rig.bytes.substr(0, kSlotsAt);
    put(f, kCountsAt, uint64_t(0));
    put(f, kCountsAt + 8, uint64_t(0));
    const int32_t dims[3] = {1 << 30, 1 << 30, 16};  // 2^64: 0 in 64 bits
    std::memcpy(&f[kDimsAt], dims, sizeof(dims));
    CHECK_FALSE(rig.load_forged(dir, f).cache);
  }
  SECTION("a NaN origin") {
    std::string f = rig.bytes;
    put(f, kOriginAt, std::nanf(""));
    CHECK_FALSE(rig.load_forged(dir, f).cache);
  }
  SECTION("a block scale of 3e38") {
    std::string f = rig.bytes;
    put(f, rig.first_block(), 3e38f);
    CHECK_FALSE(rig.load_forged(dir, f).cache);
  }
  SECTION("a value above its block's scale (an infinity)") {
    std::string f = rig.bytes;
    // Find a block with values: scale, sizes (runs, halves), runs, halves.
    size_t at = rig.first_block();
    uint64_t sizes[2] = {0, 0};
    for (;;) {
      std::memcpy(sizes, &f[at + 4], 16);
      if (sizes[1] > 0) break;
      at += 4 + 16 + 4 * sizes[0] + 2 * sizes[1];
      REQUIRE(at < f.size());
    }
    put(f, at + 4 + 16 + 4 * sizes[0], uint16_t(0x7C00));
    CHECK_FALSE(rig.load_forged(dir, f).cache);
  }
  SECTION("a node count the file is far too short for") {
    std::string f = rig.bytes;
    uint64_t counts[2];
    std::memcpy(counts, &f[kCountsAt], 16);
    counts[1] = counts[0];
    std::memcpy(&f[kCountsAt], counts, 16);
    for (size_t s = 0; s < counts[0]; ++s) put(f, kSlotsAt + 4 * s, uint32_t(s));
    const auto loaded = rig.load_forged(dir, f);
    CHECK_FALSE(loaded.cache);
    CHECK_FALSE(loaded.damage.empty());
  }
}

TEST_CASE("a FIFO at the light cache's name neither hangs the load nor takes the save", "[cache][security]") {
  const auto dir = test::output_dir("cache_fifo");
  const GridRig rig(dir);
  const auto fifo = dir / "lightcache-fifo.bin";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // On a thread of its own: were it to hang, the test fails instead of hanging.
  auto done = std::make_shared<std::promise<std::string>>();
  auto result = done->get_future();
  std::thread([done, fifo, &rig] { done->set_value(load_light_cache(fifo, rig.key, *rig.builder, rig.scene->positions.size()).damage); })
      .detach();
  REQUIRE(result.wait_for(std::chrono::seconds(20)) == std::future_status::ready);
  CHECK_THAT(result.get(), Catch::Contains("not a regular file"));
  const auto cache = rig.builder->build({*rig.scene, *rig.rays, *rig.renderer, rig.scene->light_bounds()});
  CHECK_THROWS_WITH(save_light_cache(fifo, rig.key, *cache), Catch::Contains("not a regular file"));
  struct stat st {};
  CHECK((::lstat(fifo.c_str(), &st) == 0 && S_ISFIFO(st.st_mode)));
}

TEST_CASE("hilight solve with a FIFO at its cache file's name warns and finishes", "[cache][cli][security]") {
  const auto dir = test::output_dir("cache_fifo_cli");
  const std::string room = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  const auto target = dir / "target.ply";
  REQUIRE(test::run_hilight({"render", room, "--lights", std::string(HILIGHT_SOURCE_DIR) + "/scenes/room-4lights.json", "-o",
                             target.string(), "--max-edge", "0.6"})
              .exit_code == 0);
  const std::vector<std::string> solve = {"solve", room, "--target", target.string(), "-o", (dir / "lights.json").string(), "--max-edge",
                                          "0.6", "--cache-dir", (dir / "cache").string(), "--evaluation-points", "2000"};
  REQUIRE(test::run_hilight(solve).exit_code == 0);
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir / "cache")) files.push_back(e.path());
  REQUIRE(files.size() == 1);
  fs::remove(files[0]);
  REQUIRE(::mkfifo(files[0].c_str(), 0600) == 0);
  // Killed after 120 s were it to hang (exit 128 + 9).
  const auto r = test::run_hilight_interrupted(solve, 120.0, SIGKILL);
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("not a regular file"));
  struct stat st {};
  CHECK((::lstat(files[0].c_str(), &st) == 0 && S_ISFIFO(st.st_mode)));
}
