// Small input files read whole (io/text_file.hpp).
#include "hilight/io/text_file.hpp"

#include "hilight/error.hpp"

#include <fstream>
#include <sstream>

namespace hilight {

std::string read_text_file(const std::filesystem::path& path, const std::string& kind, uintmax_t max_bytes) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path.string(), "no such file");
  if (std::filesystem::is_directory(path, ec)) throw InputError(path.string(), "is a folder, not a " + kind + " file");
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path.string(), "not a regular file");
  if (std::filesystem::file_size(path, ec) > max_bytes)
    throw InputError(path.string(), "larger than " + std::to_string(max_bytes >> 20) + " MB: not a " + kind + " file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "cannot open the " + kind + " file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

} // namespace hilight
