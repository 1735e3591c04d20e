#include "hilight/light_cache_store.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>

namespace fs = std::filesystem;

namespace hilight {

fs::path default_cache_dir() {
  if (const char* d = std::getenv("HILIGHT_CACHE_DIR"); d && *d) return d;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return fs::path(x) / "hilight";
  if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".cache" / "hilight";
  return fs::temp_directory_path() / "hilight-cache";
}

uint64_t default_cache_cap_bytes() {
  uint64_t megabytes = 1024;
  if (const char* v = std::getenv("HILIGHT_CACHE_MAX_MB"); v && *v) {
    char* end = nullptr;
    const unsigned long long parsed = std::strtoull(v, &end, 10);
    if (end && *end == '\0') megabytes = parsed;
  }
  return megabytes * 1024ull * 1024ull;
}

std::vector<CacheFile> list_cache(const fs::path& dir) {
  std::vector<CacheFile> out;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind("lightcache-", 0) != 0 || it->path().extension() != ".bin") continue;
    std::error_code file_ec;
    CacheFile f{it->path(), uint64_t(it->file_size(file_ec)), it->last_write_time(file_ec)};
    if (!file_ec) out.push_back(std::move(f));
  }
  std::sort(out.begin(), out.end(), [](const CacheFile& a, const CacheFile& b) {
    return a.last_used != b.last_used ? a.last_used > b.last_used : a.path < b.path;
  });
  return out;
}

std::vector<CacheFile> clear_cache(const fs::path& dir) {
  std::vector<CacheFile> removed;
  for (auto& f : list_cache(dir)) {
    std::error_code ec;
    if (fs::remove(f.path, ec)) removed.push_back(std::move(f));
  }
  return removed;
}

void touch_cache_file(const fs::path& file) {
  std::error_code ec;
  fs::last_write_time(file, fs::file_time_type::clock::now(), ec);
}

std::vector<CacheFile> evict_cache(const fs::path& dir, uint64_t cap_bytes, const fs::path& keep) {
  std::vector<CacheFile> files = list_cache(dir), removed;
  uint64_t total = 0;
  for (const auto& f : files) total += f.bytes;
  // Oldest last: walk from the back.
  for (auto it = files.rbegin(); it != files.rend() && total > cap_bytes; ++it) {
    std::error_code ec;
    if (!keep.empty() && fs::equivalent(it->path, keep, ec)) continue;
    if (fs::remove(it->path, ec)) {
      total -= it->bytes;
      removed.push_back(*it);
    }
  }
  return removed;
}

} // namespace hilight
