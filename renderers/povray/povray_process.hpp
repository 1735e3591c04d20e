#pragma once
/// Running the real `povray` program: a child process in a private temporary
/// folder, with a time limit, its own error text kept for messages.
#include <filesystem>
#include <string>
#include <vector>

namespace hilight::povray {

/// The povray executable on PATH, or "" if there is none.
std::string find_povray();

/// A private folder, removed with its contents when this object goes.
class TempFolder {
public:
  TempFolder();
  ~TempFolder();
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  const std::filesystem::path& path() const { return m_path; }

private:
  std::filesystem::path m_path;
};

/// Runs povray with `args` in `folder`; throws std::runtime_error carrying
/// POV-Ray's own error lines when it fails or exceeds `timeout_seconds`.
void run_povray(const std::string& executable, const std::vector<std::string>& args, const std::filesystem::path& folder,
                double timeout_seconds);

} // namespace hilight::povray
