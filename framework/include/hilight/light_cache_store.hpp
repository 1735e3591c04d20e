#pragma once
/// The folder of light caches on disk (`~/.cache/hilight`, --cache-dir): what
/// is in it, clearing it, and a size cap with least-recently-used eviction.
/// A cache file's modification time is its last use: loading touches it.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace hilight {

/// The default folder for cache files: $HILIGHT_CACHE_DIR, else
/// $XDG_CACHE_HOME/hilight, else ~/.cache/hilight.
std::filesystem::path default_cache_dir();

/// Default cap on the folder's size: $HILIGHT_CACHE_MAX_MB megabytes, else 1024.
uint64_t default_cache_cap_bytes();

struct CacheFile {
  std::filesystem::path path;
  uint64_t bytes = 0;
  std::filesystem::file_time_type last_used;
};

/// The light cache files in `dir` (lightcache-*.bin), most recently used first.
std::vector<CacheFile> list_cache(const std::filesystem::path& dir);

/// Removes every light cache file in `dir`; returns what it removed.
std::vector<CacheFile> clear_cache(const std::filesystem::path& dir);

/// Marks `file` as just used (so eviction keeps it longest).
void touch_cache_file(const std::filesystem::path& file);

/// Removes the least recently used files until the folder holds at most
/// `cap_bytes` (never `keep`, the file just written); returns what it removed.
std::vector<CacheFile> evict_cache(const std::filesystem::path& dir, uint64_t cap_bytes, const std::filesystem::path& keep = {});

} // namespace hilight
