#include "hilight/io/atomic_file.hpp"

#include "hilight/error.hpp"

#include <cstring>
#include <fstream>
#include <unistd.h>

namespace hilight {

namespace fs = std::filesystem;

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
