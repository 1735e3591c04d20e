#include "hilight/io/atomic_file.hpp"

#include "hilight/error.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <mutex>
#include <streambuf>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

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

/// A stream buffer over a file descriptor that keeps the first write error
/// (std::ofstream forgets errno, and so the reason).
class FdBuf : public std::streambuf {
public:
  explicit FdBuf(int fd) : m_fd(fd), m_buf(kBytes) { setp(m_buf.data(), m_buf.data() + kBytes); }
  int error() const { return m_error; }

protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    if (n < std::streamsize(kBytes)) return std::streambuf::xsputn(s, n);
    return drain() && write_all(s, size_t(n)) ? n : 0;  // large blocks skip the buffer
  }

private:
  bool drain() {
    const bool ok = write_all(pbase(), size_t(pptr() - pbase()));
    setp(m_buf.data(), m_buf.data() + kBytes);
    return ok;
  }
  bool write_all(const char* p, size_t n) {
    while (n > 0 && m_error == 0) {
      const ssize_t w = ::write(m_fd, p, n);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) m_error = w < 0 ? errno : EIO;
      else p += w, n -= size_t(w);
    }
    return m_error == 0;
  }
  static constexpr size_t kBytes = size_t(1) << 16;
  int m_fd;
  int m_error = 0;
  std::vector<char> m_buf;
};

fs::path folder_of(const fs::path& path) { return path.has_parent_path() ? path.parent_path() : fs::path("."); }

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

/// A process's open file named through /proc (/dev/stdout, /dev/fd/N,
/// /proc/self/fd/N): written in place whatever it is, since a redirected
/// stdout may be a regular file, and /dev must never get one.
bool names_open_file(const fs::path& path) {
  std::error_code ec;
  const fs::path dir = fs::canonical(folder_of(path), ec);
  if (!ec && starts_with(dir.string() + "/", "/proc/")) return true;
  const fs::path target = fs::read_symlink(path, ec);
  return !ec && starts_with(target.string(), "/proc/");
}

/// True when `path` is written in place: an open file named through /proc,
/// a character device, or a FIFO or socket of this user's. A link is
/// followed only into /dev: one planted elsewhere (to someone's FIFO) is
/// replaced, never written through. Throws for what is never written: a
/// folder, a block device, another user's FIFO or socket.
bool written_in_place(const fs::path& path) {
  const bool open_file = names_open_file(path);
  struct stat st {};
  if (!open_file) {
    if (::lstat(path.c_str(), &st) != 0) return false;  // a new file
    std::error_code ec;
    if (S_ISLNK(st.st_mode) && !starts_with(fs::canonical(path, ec).string(), "/dev/")) return false;
  }
  if (::stat(path.c_str(), &st) != 0) return open_file;  // open fails with the reason
  if (S_ISDIR(st.st_mode)) throw InputError(path.string(), "cannot write: it is a folder");
  if (S_ISBLK(st.st_mode)) throw InputError(path.string(), "cannot write: it is a block device");
  if ((S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode)) && st.st_uid != ::geteuid() && !open_file)
    throw InputError(path.string(), "cannot write: it is a FIFO or socket of another user's");
  return open_file || S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode);
}

/// The permissions a new file gets: 0666 less the umask, read without
/// changing it (umask() would race with other threads creating files).
mode_t new_file_mode() {
  static const mode_t mode = [] {
    mode_t mask = 022;
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
      if (line.rfind("Umask:", 0) == 0) mask = mode_t(std::strtoul(line.c_str() + 6, nullptr, 8));
    return mode_t(0666 & ~mask);
  }();
  return mode;
}

[[noreturn]] void fail(const fs::path& path, int err) {
  throw InputError(path.string(), std::string("cannot write: ") + std::strerror(err));
}

/// Runs the writer on `fd`; returns 0 or the first errno. The writer's own
/// exception passes, unless the write failed first (its complaint is then
/// about the broken stream, and the errno says why).
int run_writer(int fd, const std::function<void(std::ostream&)>& write) {
  FdBuf buf(fd);
  std::ostream out(&buf);
  try {
    write(out);
  } catch (...) {
    if (buf.error() == 0) throw;
    return buf.error();
  }
  out.flush();
  if (buf.error()) return buf.error();
  return out ? 0 : EIO;
}

void write_in_place(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  // No O_CREAT: a device that is not there is not made; O_APPEND keeps what
  // was already written to a redirected stdout.
  const int fd = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC | O_APPEND);
  if (fd < 0) fail(path, errno);
  int err = 0;
  try {
    err = run_writer(fd, write);
  } catch (...) {
    ::close(fd);
    throw;
  }
  // Devices and pipes cannot be synced (EINVAL); a redirected file can.
  if (err == 0 && ::fsync(fd) != 0 && errno != EINVAL && errno != EROFS && errno != ENOTSUP) err = errno;
  if (::close(fd) != 0 && err == 0 && errno != EINTR) err = errno;
  if (err) fail(path, err);
}

void sync_folder(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);  // best effort: the rename is done; some file systems refuse
  ::close(fd);
}

void write_replacing(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  const fs::path dir = folder_of(path);
  // A random name made with O_EXCL: nothing planted at it is followed.
  std::string name = path.filename().string();
  if (name.size() > 200) name.resize(200);  // room for the affixes within NAME_MAX
  std::string temp = (dir / ("." + name + ".tmpXXXXXX")).string();
  install_handlers();
  const int fd = ::mkostemp(temp.data(), O_CLOEXEC);
  if (fd < 0) {
    const int err = errno;
    check_writable(path);  // a clearer reason when there is one
    fail(path, err);
  }
  const TempGuard guard(temp);
  // An existing file keeps its permissions; a new one gets the umask's.
  struct stat old {};
  const bool replaces_file = ::lstat(path.c_str(), &old) == 0 && S_ISREG(old.st_mode);
  ::fchmod(fd, replaces_file ? (old.st_mode & 07777) : new_file_mode());
  int err = 0;
  try {
    err = run_writer(fd, write);
  } catch (...) {
    ::close(fd);
    ::unlink(temp.c_str());
    throw;
  }
  // Synced before the rename: a power loss leaves the old file or the new, never an empty one.
  if (err == 0 && ::fsync(fd) != 0) err = errno;
  if (::close(fd) != 0 && err == 0 && errno != EINTR) err = errno;
  if (err == 0 && ::rename(temp.c_str(), path.c_str()) != 0) err = errno;
  if (err) {
    ::unlink(temp.c_str());
    fail(path, err);
  }
  sync_folder(dir);
}

} // namespace

void check_writable(const fs::path& path) {
  if (written_in_place(path)) {
    if (::access(path.c_str(), W_OK) != 0) fail(path, errno);
    return;
  }
  const fs::path dir = folder_of(path);
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(path.string(), "cannot write: folder " + dir.string() + " does not exist");
  if (::access(dir.c_str(), W_OK) != 0)
    throw InputError(path.string(), "cannot write: folder " + dir.string() + " is not writable (" + std::strerror(errno) + ")");
}

void write_atomically(const fs::path& path, const std::function<void(std::ostream& out)>& write) {
  check_writable(path);
  if (written_in_place(path)) write_in_place(path, write);
  else write_replacing(path, write);
}

void write_atomically(const fs::path& path, std::string_view bytes) {
  write_atomically(path, [&](std::ostream& out) { out.write(bytes.data(), std::streamsize(bytes.size())); });
}

} // namespace hilight
