#pragma once
/// The folder of light caches on disk (`~/.cache/hilight`, --cache-dir): what
/// is in it, clearing it, and a size cap with least-recently-used eviction.
/// A cache file's modification time is its last use: loading touches it.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace hilight {

/// The default folder for cache files: $HILIGHT_CACHE_DIR, else
/// $XDG_CACHE_HOME/hilight, else ~/.cache/hilight ($HOME, or the home the
/// user database names). Without a home, a 0700 folder of this user's in the
/// system's temporary directory; empty (no caching, with a note on stderr)
/// when that cannot be made safely.
std::filesystem::path default_cache_dir();

/// Default cap on the folder's size: $HILIGHT_CACHE_MAX_MB megabytes, else
/// 1024. InputError when the variable is not a whole number of megabytes.
uint64_t default_cache_cap_bytes();

struct CacheFile {
  std::filesystem::path path;
  uint64_t bytes = 0;
  std::filesystem::file_time_type last_used;
  bool temporary = false;  ///< a write's temporary (.lightcache-*.tmp*), left by a kill when old
};

/// The light cache files in `dir` (lightcache-*.bin, regular files only) and
/// the temporaries of their writes, most recently used first.
std::vector<CacheFile> list_cache(const std::filesystem::path& dir);

/// Removes every light cache file and temporary in `dir`; returns what it removed.
std::vector<CacheFile> clear_cache(const std::filesystem::path& dir);

/// Marks `file` as just used (so eviction keeps it longest).
void touch_cache_file(const std::filesystem::path& file);

/// Removes temporaries older than 10 minutes (left by killed writes), then the
/// least recently used files until the folder holds at most `cap_bytes`
/// (never `keep`, the file just written, nor a temporary still being
/// written, which counts); returns what it removed.
std::vector<CacheFile> evict_cache(const std::filesystem::path& dir, uint64_t cap_bytes, const std::filesystem::path& keep = {});

} // namespace hilight
