#include "povray_process.hpp"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace hilight::povray {

namespace fs = std::filesystem;

std::string find_povray() {
  const char* path = std::getenv("PATH");
  std::stringstream ss(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(ss, dir, ':')) {
    if (dir.empty()) continue;
    fs::path candidate = fs::path(dir) / "povray";
    if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return {};
}

TempFolder::TempFolder() {
  std::string pattern = (fs::temp_directory_path() / "hilight-povray-XXXXXX").string();
  std::vector<char> buf(pattern.begin(), pattern.end());
  buf.push_back('\0');
  if (!::mkdtemp(buf.data())) throw std::runtime_error(std::string("povray: cannot create a temporary folder: ") + std::strerror(errno));
  m_path = buf.data();
}

TempFolder::~TempFolder() {
  std::error_code ec;
  fs::remove_all(m_path, ec);
}

namespace {

/// The lines of POV-Ray's output that explain a failure.
std::string error_lines(const fs::path& log) {
  std::ifstream in(log);
  std::string line, out;
  while (std::getline(in, line))
    if (line.find("rror") != std::string::npos || line.find("Parse") != std::string::npos || line.find("line") != std::string::npos)
      out += (out.empty() ? "" : " | ") + line;
  if (out.empty()) {
    in.clear();
    in.seekg(0);
    std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    out = all.size() > 400 ? all.substr(all.size() - 400) : all;
  }
  return out;
}

} // namespace

void run_povray(const std::string& executable, const std::vector<std::string>& args, const fs::path& folder,
                double timeout_seconds) {
  const fs::path log = folder / "povray.log";
  pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(std::string("povray: fork failed: ") + std::strerror(errno));
  if (pid == 0) {
    if (::chdir(folder.c_str()) != 0) ::_exit(126);
    int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    int null_in = ::open("/dev/null", O_RDONLY);
    if (fd >= 0) {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
    }
    if (null_in >= 0) ::dup2(null_in, 0);
    ::setpgid(0, 0);  // its own group, so a timeout kills everything it started
    std::vector<std::string> argv_s = {executable};
    argv_s.insert(argv_s.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv_s) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(executable.c_str(), argv.data());
    ::_exit(127);
  }
  auto start = std::chrono::steady_clock::now();
  int status = 0;
  for (;;) {
    pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (r < 0 && errno != EINTR) throw std::runtime_error("povray: waitpid failed");
    double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed > timeout_seconds) {
      ::kill(-pid, SIGKILL);
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      throw std::runtime_error("povray: no result after " + std::to_string(int(timeout_seconds)) + " s (time limit; raise it with --set timeout=S)");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::string why = WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status)) : "killed by signal " + std::to_string(WTERMSIG(status));
    throw std::runtime_error("povray failed (" + why + "): " + error_lines(log));
  }
}

} // namespace hilight::povray
