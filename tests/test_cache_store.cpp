// The light cache folder: listing, clearing, and the size cap that evicts
// the least recently used files first (never the one just written); and
// `hilight cache list|clear` on it.
#include "hilight/light_cache_store.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <chrono>

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
