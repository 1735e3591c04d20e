#pragma once
/// Every output file goes through write_atomically: it appears whole or not
/// at all, and a failed write (a full disk) is an InputError naming the file.
///
/// A regular target (or a new one) is written to a temporary made by mkstemp
/// in the target's folder (O_EXCL, a random name, so a planted symlink is
/// never followed), flushed, checked, fsynced, renamed over the target, and
/// the folder is fsynced. A name that is itself a symlink is replaced, never
/// written through, unless it leads into /dev. A character device
/// (`/dev/null`), a FIFO or socket of this user's, and an open file named
/// through /proc (`/dev/stdout`, `/dev/fd/3`, even when it is a regular
/// file) are written in place and never replaced; a block device, a folder
/// and another user's FIFO are refused.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>

namespace hilight {

/// InputError naming `path` unless it can be written: a device or FIFO that
/// is writable, or a name whose folder exists and is writable and which is
/// not a folder. Cheap: callers use it to fail before any work.
void check_writable(const std::filesystem::path& path);

/// Calls write(out) and puts the bytes at `path` as described above. On any
/// exception or write failure the temporary is removed and nothing appears
/// under `path`; a failed write becomes an InputError naming `path` and the
/// system's reason ("No space left on device").
void write_atomically(const std::filesystem::path& path, const std::function<void(std::ostream& out)>& write);

/// The same for bytes already in memory.
void write_atomically(const std::filesystem::path& path, std::string_view bytes);

} // namespace hilight
