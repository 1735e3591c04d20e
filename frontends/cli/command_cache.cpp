// hilight cache list|clear: the light caches kept on disk between solves.
#include "cli_common.hpp"
#include "commands.hpp"
#include "hilight/light_cache.hpp"
#include "hilight/light_cache_store.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>

namespace hilight::cli {

namespace {

double megabytes(uint64_t bytes) { return double(bytes) / (1024.0 * 1024.0); }

std::string when(std::filesystem::file_time_type t) {
  const auto system = std::chrono::time_point_cast<std::chrono::system_clock::duration>(
      t - std::filesystem::file_time_type::clock::now() + std::chrono::system_clock::now());
  const std::time_t c = std::chrono::system_clock::to_time_t(system);
  char buf[32];
  std::strftime(buf, sizeof(buf), "%Y-%m-%d %H:%M", std::localtime(&c));
  return buf;
}

} // namespace

int run_cache(const std::vector<std::string>& args) {
  CLI::App app("List or clear the light caches kept between solves", "cache");
  app.require_subcommand(1);
  std::string dir;
  app.add_option("--cache-dir", dir, "the cache folder (default: ~/.cache/hilight, or $HILIGHT_CACHE_DIR)");
  auto* list = app.add_subcommand("list", "each cache file (and unfinished writes), most recently used first, and the total against the cap");
  auto* clear = app.add_subcommand("clear", "remove every light cache file and unfinished write, nothing else");
  list->fallthrough();  // --cache-dir may follow the subcommand
  clear->fallthrough();
  if (auto code = parse_arguments(app, args)) return *code;
  const std::filesystem::path folder = dir.empty() ? default_cache_dir() : std::filesystem::path(dir);

  if (list->parsed()) {
    uint64_t total = 0;
    for (const auto& f : list_cache(folder)) {
      std::printf("%10.1f MB  %s  %s%s\n", megabytes(f.bytes), when(f.last_used).c_str(), f.path.filename().c_str(),
                  f.temporary ? "  (an unfinished write; removed by clear, or when 10 minutes old)" : "");
      total += f.bytes;
    }
    std::printf("%10.1f MB  total in %s (cap %.0f MB, $HILIGHT_CACHE_MAX_MB; least recently used go first)\n", megabytes(total),
                folder.c_str(), megabytes(default_cache_cap_bytes()));
  }
  if (clear->parsed()) {
    uint64_t total = 0;
    const auto removed = clear_cache(folder);
    for (const auto& f : removed) total += f.bytes;
    std::printf("removed %zu light cache file%s (%.1f MB) from %s\n", removed.size(), removed.size() == 1 ? "" : "s",
                megabytes(total), folder.c_str());
  }
  return 0;
}

} // namespace hilight::cli
