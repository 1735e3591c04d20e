#include "hilight/light_cache_store.hpp"

#include "hilight/error.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <pwd.h>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace hilight {

namespace {

/// A temporary older than this is left by a killed write (a write takes seconds).
constexpr auto kStaleTemporary = std::chrono::minutes(10);

/// The home folder from the user database, when HOME is not set.
fs::path home_from_passwd() {
  const struct passwd* pw = ::getpwuid(::getuid());
  return pw && pw->pw_dir && pw->pw_dir[0] == '/' ? fs::path(pw->pw_dir) : fs::path();
}

/// A folder in the system's temporary directory that only this user can
/// use: made 0700, or already there as a real folder (not a link) of this
/// user's with no access for others. Empty when neither.
fs::path private_temp_folder() {
  const fs::path dir = fs::temp_directory_path() / ("hilight-cache-" + std::to_string(::getuid()));
  if (::mkdir(dir.c_str(), 0700) != 0 && errno != EEXIST) return {};
  struct stat st {};
  if (::lstat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != ::getuid() || (st.st_mode & 077) != 0) return {};
  return dir;
}

bool is_cache_name(const std::string& name) {
  return name.rfind("lightcache-", 0) == 0 && name.size() > 4 && name.compare(name.size() - 4, 4, ".bin") == 0;
}

/// What write_atomically leaves of a cache file a kill interrupted: ".lightcache-….bin.tmpXXXXXX".
bool is_temporary_name(const std::string& name) {
  return name.rfind(".lightcache-", 0) == 0 && name.find(".tmp") != std::string::npos;
}

} // namespace

fs::path default_cache_dir() {
  if (const char* d = std::getenv("HILIGHT_CACHE_DIR"); d && *d) return d;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return fs::path(x) / "hilight";
  if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".cache" / "hilight";
  if (const fs::path home = home_from_passwd(); !home.empty()) return home / ".cache" / "hilight";
  // Never a shared, predictable folder others could plant caches in.
  static const fs::path fallback = [] {
    fs::path dir = private_temp_folder();
    if (dir.empty()) std::fprintf(stderr, "hilight: note: no private folder for light caches (HOME is not set); caching is off\n");
    return dir;
  }();
  return fallback;
}

uint64_t default_cache_cap_bytes() {
  const char* v = std::getenv("HILIGHT_CACHE_MAX_MB");
  if (!v || !*v) return 1024ull << 20;
  // Digits only (strtoull would take "-1" as a huge number), and no overflow in bytes.
  constexpr uint64_t kMaxMegabytes = UINT64_MAX >> 20;
  uint64_t megabytes = 0;
  for (const char* c = v; *c; ++c) {
    if (*c < '0' || *c > '9' || megabytes > (kMaxMegabytes - uint64_t(*c - '0')) / 10)
      throw InputError("HILIGHT_CACHE_MAX_MB=" + std::string(v), "not a size in megabytes (a whole number from 0 to " +
                                                                    std::to_string(kMaxMegabytes) + ")");
    megabytes = megabytes * 10 + uint64_t(*c - '0');
  }
  return megabytes << 20;
}

std::vector<CacheFile> list_cache(const fs::path& dir) {
  std::vector<CacheFile> out;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    const bool temporary = is_temporary_name(name);
    if (!temporary && !is_cache_name(name)) continue;
    // Regular files only: a folder or link named like a cache is not one (nor its size).
    std::error_code file_ec;
    if (!it->is_regular_file(file_ec) || it->is_symlink(file_ec)) continue;
    CacheFile f{it->path(), uint64_t(it->file_size(file_ec)), it->last_write_time(file_ec), temporary};
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
  const auto stale = fs::file_time_type::clock::now() - kStaleTemporary;
  // Temporaries of killed writes go first; one still being written counts but stays.
  for (auto it = files.begin(); it != files.end();) {
    std::error_code ec;
    if (it->temporary && it->last_used < stale && fs::remove(it->path, ec)) {
      removed.push_back(*it);
      it = files.erase(it);
    } else {
      total += it->bytes;
      ++it;
    }
  }
  // Oldest last: walk from the back.
  for (auto it = files.rbegin(); it != files.rend() && total > cap_bytes; ++it) {
    std::error_code ec;
    if (it->temporary || (!keep.empty() && fs::equivalent(it->path, keep, ec))) continue;
    if (fs::remove(it->path, ec)) {
      total -= it->bytes;
      removed.push_back(*it);
    }
  }
  return removed;
}

} // namespace hilight
