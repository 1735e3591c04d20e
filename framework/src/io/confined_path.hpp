#pragma once
// Files that an input names (an OBJ's mtllib, glTF buffers and images,
// textures) must lie in the input's folder or below it (issue 35): a `../`
// or absolute reference would otherwise read, and echo in errors, files the
// input has no business with. Symlinks are followed before the check, so a
// link in the folder that leads out of it is refused as well.
#include <filesystem>
#include <system_error>

namespace hilight {

/// True when `file` (absolute, or relative to the working folder, as the
/// readers build it from the input's folder) resolves to a place inside
/// `folder` (the input's folder; empty: the working folder).
inline bool inside_folder(const std::filesystem::path& folder, const std::filesystem::path& file) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path base = fs::weakly_canonical(fs::absolute(folder.empty() ? fs::path(".") : folder, ec), ec);
  if (ec) return false;
  const fs::path target = fs::weakly_canonical(fs::absolute(file, ec), ec);
  if (ec) return false;
  auto b = base.begin(), t = target.begin();
  for (; b != base.end(); ++b, ++t) {
    if (b->empty() && std::next(b) == base.end()) break;  // a trailing separator
    if (t == target.end() || *b != *t) return false;
  }
  return true;
}

/// `file` as the input named it, relative to its `folder` where it can be
/// ("../secret.bin"), for the refusal.
inline std::string named_from(const std::filesystem::path& folder, const std::filesystem::path& file) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path base = fs::absolute(folder.empty() ? fs::path(".") : folder, ec).lexically_normal();
  const fs::path relative = fs::absolute(file, ec).lexically_normal().lexically_relative(base);
  return relative.empty() ? file.string() : relative.string();
}

} // namespace hilight
