#include "hilight/io/atomic_file.hpp"

#include "hilight/error.hpp"

#include <atomic>
#include <csignal>
#include <cstring>
#include <fstream>
#include <mutex>
#include <unistd.h>

namespace hilight {

namespace fs = std::filesystem;

namespace {

// Ctrl-C (or a TERM or HUP) while a file is being written must not leave its
// temporary behind: the paths in flight are kept where a signal handler can
// reach them without allocating, and the handler removes them, then dies of
// the signal as the default would.
constexpr size_t kSlots = 32, kPathBytes = 4096;
struct TempSlot {
  std::atomic<int> state{0};  ///< 0 free, 1 taken (path being copied), 2 holds a path
  char path[kPathBytes] = {};
};
TempSlot g_temps[kSlots];

extern "C" void remove_temps_and_reraise(int sig) {
  for (auto& slot : g_temps)
    if (slot.state.load() == 2) ::unlink(slot.path);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

/// Installs the handler for signals still at their default (a frontend's own stays).
void install_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction old {};
      if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;
      struct sigaction sa {};
      sa.sa_handler = remove_temps_and_reraise;
      sigemptyset(&sa.sa_mask);
      ::sigaction(sig, &sa, nullptr);
    }
  });
}

/// Holds a temporary's path in a slot while it exists.
class TempGuard {
public:
  explicit TempGuard(const fs::path& temp) {
    install_handlers();
    const std::string p = fs::absolute(temp).string();
    if (p.size() >= kPathBytes) return;  // too long to note: removed on errors, not on signals
    for (size_t i = 0; i < kSlots; ++i) {
      int expected = 0;
      if (g_temps[i].state.compare_exchange_strong(expected, 1)) {
        // Published only once whole: a signal meanwhile removes nothing.
        std::memset(g_temps[i].path, 0, kPathBytes);
        std::memcpy(g_temps[i].path, p.c_str(), p.size());
        g_temps[i].state.store(2);
        m_slot = int(i);
        return;
      }
    }
  }
  ~TempGuard() {
    if (m_slot >= 0) g_temps[m_slot].state.store(0);
  }
  TempGuard(const TempGuard&) = delete;
  TempGuard& operator=(const TempGuard&) = delete;

private:
  int m_slot = -1;
};

} // namespace

void check_writable(const fs::path& path) {
  fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(path.string(), "cannot write: folder " + dir.string() + " does not exist");
  if (fs::is_directory(path, ec)) throw InputError(path.string(), "cannot write: it is a folder");
  if (::access(dir.c_str(), W_OK) != 0) throw InputError(path.string(), "cannot write: folder " + dir.string() + " is not writable");
}

void write_atomically(const fs::path& path, const std::function<void(const fs::path& temp)>& write) {
  check_writable(path);
  fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  // Same folder as the target so the rename is atomic; pid keeps parallel runs apart.
  std::string temp_name = ".";  // built by appending: GCC 12 misreports chained + (-Wrestrict)
  temp_name.append(path.filename().string()).append(".tmp").append(std::to_string(::getpid())).append(path.extension().string());
  fs::path temp = dir / temp_name;
  const TempGuard guard(temp);
  {
    std::ofstream probe(temp, std::ios::binary);
    if (!probe) throw InputError(path.string(), std::string("cannot write: ") + std::strerror(errno));
  }
  try {
    write(temp);
    fs::rename(temp, path);
  } catch (const fs::filesystem_error& e) {
    fs::remove(temp, ec);
    throw InputError(path.string(), std::string("cannot write: ") + e.code().message());
  } catch (...) {
    fs::remove(temp, ec);
    throw;
  }
}

} // namespace hilight
