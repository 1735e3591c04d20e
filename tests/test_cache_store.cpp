// The light cache folder: listing, clearing, and the size cap that evicts
// the least recently used files first (never the one just written); and
// `hilight cache list|clear` on it.
#include "hilight/light_cache.hpp"
#include "hilight/light_cache_file.hpp"
#include "hilight/light_cache_store.hpp"
#include "support.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <ostream>
#include <sys/mount.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace hilight;

namespace {
/// A fake cache file of `megabytes`, last used `minutes_ago`.
fs::path fake_cache(const fs::path& dir, const std::string& key, size_t megabytes, int minutes_ago) {
  const fs::path p = dir / ("lightcache-" + key + ".bin");
  test::write_text(p, std::string(megabytes << 20, 'x'));
  fs::last_write_time(p, fs::file_time_type::clock::now() - std::chrono::minutes(minutes_ago));
  return p;
}

/// A cache of no nodes, for saving.
struct EmptyCache final : LightCache {
  std::unique_ptr<LightCacheView> view(const RayScene&, const SampleSet&) const override { return nullptr; }
  size_t node_count() const override { return 0; }
  void write(std::ostream& out) const override { out << "empty"; }
};
} // namespace

TEST_CASE("cache folder: the cap evicts the least recently used files, never the one just written", "[cache]") {
  const auto dir = test::output_dir("cache_store_evict");
  const auto old_file = fake_cache(dir, "0000000000000001", 3, 30);
  const auto middle = fake_cache(dir, "0000000000000002", 3, 20);
  const auto recent = fake_cache(dir, "0000000000000003", 3, 10);
  const auto written = fake_cache(dir, "0000000000000004", 3, 40);  // oldest time, but just written
  test::write_text(dir / "notes.txt", "not a cache file");
  REQUIRE(list_cache(dir).size() == 4);
  CHECK(list_cache(dir).front().path == recent);
  const auto removed = evict_cache(dir, 7u << 20, written);
  CHECK(removed.size() == 2);
  CHECK_FALSE(fs::exists(old_file));
  CHECK_FALSE(fs::exists(middle));
  CHECK(fs::exists(recent));
  CHECK(fs::exists(written));
  CHECK(fs::exists(dir / "notes.txt"));
  // Using a file makes it the last to go.
  touch_cache_file(written);
  CHECK(list_cache(dir).front().path == written);
  CHECK(evict_cache(dir, 4u << 20).front().path == recent);
}

TEST_CASE("hilight cache list and clear", "[cache][cli]") {
  const auto dir = test::output_dir("cache_store_cli");
  fake_cache(dir, "00000000000000aa", 1, 5);
  fake_cache(dir, "00000000000000bb", 2, 1);
  auto list = test::run_hilight({"cache", "list", "--cache-dir", dir.string()});
  CHECK(list.exit_code == 0);
  CHECK_THAT(list.out, Catch::Contains("lightcache-00000000000000bb.bin"));
  CHECK_THAT(list.out, Catch::Contains("3.0 MB  total"));
  CHECK(list.out.find("00000000000000bb") < list.out.find("00000000000000aa"));  // most recently used first
  auto clear = test::run_hilight({"cache", "clear", "--cache-dir", dir.string()});
  CHECK(clear.exit_code == 0);
  CHECK_THAT(clear.out, Catch::Contains("removed 2 light cache files"));
  CHECK(list_cache(dir).empty());
  auto bad = test::run_hilight({"cache", "shred"});
  CHECK(bad.exit_code == 2);
  CHECK(test::line_count(bad.err) == 1);
}

TEST_CASE("hilight solve --cache picks the light cache plugin, and a wrong one is one line and exit 2", "[cache][cli]") {
  const auto dir = test::output_dir("cache_choice_cli");
  const std::string room = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  const auto target = dir / "target.ply";
  REQUIRE(test::run_hilight({"render", room, "--lights", std::string(HILIGHT_SOURCE_DIR) + "/scenes/room-4lights.json", "-o",
                             target.string(), "--max-edge", "0.6"})
              .exit_code == 0);
  auto solve = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"solve", room, "--target", target.string(), "-o", (dir / "lights.json").string(),
                                     "--max-edge", "0.6", "--cache-dir", (dir / "cache").string(), "--report",
                                     (dir / "report.json").string(), "--evaluation-points", "2000"};
    args.insert(args.end(), extra.begin(), extra.end());
    return test::run_hilight(args);
  };
  const auto adaptive = solve({"--cache", "adaptive", "--cache-setting", "growth=1.2"});
  INFO(adaptive.err);
  CHECK(adaptive.exit_code == 0);
  CHECK_THAT(test::read_file(dir / "report.json"), Catch::Contains("\"light_cache\": \"built\""));
  const auto none = solve({"--cache", "none"});
  CHECK(none.exit_code == 0);
  CHECK_THAT(test::read_file(dir / "report.json"), Catch::Contains("\"light_cache\": \"off\""));
  for (const auto& wrong : std::vector<std::vector<std::string>>{{"--cache", "octree"},
                                                                 {"--cache", "grid", "--cache-setting", "cellz=4"},
                                                                 {"--cache", "none", "--cache-setting", "cells=4"},
                                                                 {"--cache", "adaptive", "--cache-setting", "growth=0.5"}}) {
    const auto r = solve(wrong);
    INFO(wrong[1] << " " << (wrong.size() > 2 ? wrong[3] : ""));
    CHECK(r.exit_code == 2);
    CHECK(test::line_count(r.err) == 1);
  }
}

TEST_CASE("cache folder: temporaries of killed writes are listed, cleared, counted and removed when stale", "[cache]") {
  const auto dir = test::output_dir("cache_store_temporaries");
  const auto kept = fake_cache(dir, "0000000000000001", 2, 30);
  // What a kill -9 during a cache write leaves: ".lightcache-KEY.bin.tmpXXXXXX".
  const auto stale = dir / ".lightcache-0000000000000002.bin.tmpAbC123";
  const auto fresh = dir / ".lightcache-0000000000000003.bin.tmpXyZ789";
  test::write_text(stale, std::string(3u << 20, 'x'));
  test::write_text(fresh, std::string(3u << 20, 'x'));
  fs::last_write_time(stale, fs::file_time_type::clock::now() - std::chrono::minutes(30));
  // A folder and a link named like cache files are neither listed nor sized.
  fs::create_directory(dir / "lightcache-00000000000000cc.bin");
  fs::create_symlink("/etc/passwd", dir / "lightcache-00000000000000dd.bin");
  const auto listed = list_cache(dir);
  REQUIRE(listed.size() == 3);
  CHECK(std::count_if(listed.begin(), listed.end(), [](const CacheFile& f) { return f.temporary; }) == 2);
  auto list = test::run_hilight({"cache", "list", "--cache-dir", dir.string()});
  CHECK_THAT(list.out, Catch::Contains(".lightcache-0000000000000002.bin.tmpAbC123"));
  CHECK_THAT(list.out, Catch::Contains("8.0 MB  total"));
  // The cap: the stale temporary goes; the fresh one (maybe still being
  // written) stays but counts, so the cache file goes too.
  const auto removed = evict_cache(dir, 4u << 20);
  CHECK_FALSE(fs::exists(stale));
  CHECK(fs::exists(fresh));
  CHECK_FALSE(fs::exists(kept));
  CHECK(removed.size() == 2);
  // clear: every cache file and temporary, nothing else.
  fake_cache(dir, "0000000000000004", 1, 1);
  auto clear = test::run_hilight({"cache", "clear", "--cache-dir", dir.string()});
  CHECK_THAT(clear.out, Catch::Contains("removed 2 light cache files"));
  CHECK_FALSE(fs::exists(fresh));
  CHECK(fs::is_directory(dir / "lightcache-00000000000000cc.bin"));
  CHECK(fs::is_symlink(dir / "lightcache-00000000000000dd.bin"));
}

TEST_CASE("HILIGHT_CACHE_MAX_MB that is negative, not a number or overflows is one line and exit 2", "[cache][cli]") {
  const auto dir = test::output_dir("cache_store_cap_env");
  for (const std::string value : {"-1", "12abc", "18446744073709551615", "99999999999999999999999"}) {
    INFO(value);
    const auto r = test::run_hilight({"cache", "list", "--cache-dir", dir.string()}, {{"HILIGHT_CACHE_MAX_MB", value}});
    CHECK(r.exit_code == 2);
    CHECK(test::line_count(r.err) == 1);
    CHECK_THAT(r.err, Catch::Contains("HILIGHT_CACHE_MAX_MB"));
  }
  const auto fine = test::run_hilight({"cache", "list", "--cache-dir", dir.string()}, {{"HILIGHT_CACHE_MAX_MB", "17592186044415"}});
  CHECK(fine.exit_code == 0);
}

TEST_CASE("with HOME unset the light caches do not go to a shared folder in /tmp", "[cache][security]") {
  const auto r = test::run_hilight({"cache", "list"}, {{"HOME", ""}, {"XDG_CACHE_HOME", ""}, {"HILIGHT_CACHE_DIR", ""}});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  const std::string shared = (fs::temp_directory_path() / "hilight-cache").string();
  CHECK_THAT(r.out, !Catch::Contains(shared + " "));
  CHECK_THAT(r.out, !Catch::Contains(shared + "\n"));
}

TEST_CASE("a light cache that cannot be saved says why (a read-only folder is not 'missing')", "[cache]") {
  const auto dir = test::output_dir("cache_store_read_only");
  // A read-only file system (root can write anywhere else) or a 0500 folder.
  const fs::path ro = dir / "ro";
  fs::create_directories(ro);
  const bool mounted = ::mount("tmpfs", ro.c_str(), "tmpfs", MS_RDONLY, "size=64k") == 0;
  if (!mounted) fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec);
  if (!mounted && ::geteuid() == 0) {
    std::printf("SKIPPED: root without mount: a read-only folder is writable\n");
    return;
  }
  for (const fs::path& cache : {ro / "lightcache-0000000000000001.bin", ro / "sub" / "lightcache-0000000000000001.bin"}) {
    INFO(cache);
    std::string message;
    try {
      save_light_cache(cache, 1, EmptyCache{});
    } catch (const std::exception& e) {
      message = e.what();
    }
    CHECK_THAT(message, !Catch::Contains("does not exist"));
    CHECK_THAT(message, Catch::Contains(mounted ? "Read-only file system" : "Permission denied"));
  }
  if (mounted) ::umount2(ro.c_str(), MNT_DETACH);
  else fs::permissions(ro, fs::perms::owner_all);
}

TEST_CASE("hilight bench solve --cache-dir removes only the light caches in that folder", "[cache][cli]") {
  const auto dir = test::output_dir("cache_store_bench_dir");
  test::write_text(dir / "notes.txt", "not a cache file");
  fs::create_directories(dir / "project");
  test::write_text(dir / "project" / "model.obj", "v 0 0 0\n");
  fake_cache(dir, "0000000000000001", 1, 5);
  const auto r = test::run_hilight({"bench", "solve", "--scenes", "room", "--optimizers", "varpro", "--max-edge", "1.5", "--repeat", "1",
                                    "--skip-no-cache", "--cache-dir", dir.string()});
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(test::read_file(dir / "notes.txt") == "not a cache file");
  CHECK(test::read_file(dir / "project" / "model.obj") == "v 0 0 0\n");
  CHECK(list_cache(dir).empty());  // its own caches, and the old one, are gone
}
