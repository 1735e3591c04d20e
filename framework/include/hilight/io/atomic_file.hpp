#pragma once
/// Output files appear whole or not at all: written to a temporary name
/// beside the target, renamed on success, removed on failure.
#include <filesystem>
#include <functional>

namespace hilight {

/// InputError naming `path` unless it can be created: its folder exists and
/// is writable, and it is not itself a folder. Cheap: callers use it to fail
/// before any work.
void check_writable(const std::filesystem::path& path);

/// Calls write(temp_path), then renames temp_path to `path`. On any exception
/// the temporary is removed and the exception continues (an unwritable folder
/// becomes an InputError naming `path`).
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path& temp)>& write);

} // namespace hilight
