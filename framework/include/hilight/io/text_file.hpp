#pragma once
/// A small input file read whole, after the checks every reader of a
/// user's file needs: not a folder, not a device (/dev/zero would never
/// end), not larger than `max_bytes`. InputError naming the file otherwise
/// ("no such file", "larger than 64 MB: not a <kind> file", ...).
#include <cstdint>
#include <filesystem>
#include <string>

namespace hilight {

std::string read_text_file(const std::filesystem::path& path, const std::string& kind, uintmax_t max_bytes = uintmax_t(64) << 20);

} // namespace hilight
