#pragma once
/// How a command shows its progress (hilight/progress.hpp) and says its
/// time: on a terminal a bar with the percentage and the time left, on a
/// pipe nothing unless --progress asks for lines; the summary's time is the
/// whole command's, with its slow parts named.
#include "hilight/progress.hpp"

#include <CLI/CLI.hpp>
#include <chrono>
#include <memory>
#include <optional>
#include <string>

namespace hilight::cli {

/// "12 s", "3 min 05 s", "1 h 02 min".
std::string format_duration(double seconds);

/// For code a command's CommandProgress is not handed to: the running
/// one's time_summary(), or `seconds` as "1.23 s" when none runs.
std::string command_time_summary(double seconds);
/// Stops the running command's display (before its summary is printed).
void stop_command_progress();

class CommandProgress {
public:
  /// The command's clock starts here: construct it first thing.
  CommandProgress();
  ~CommandProgress();
  CommandProgress(const CommandProgress&) = delete;
  CommandProgress& operator=(const CommandProgress&) = delete;

  /// --progress and --no-progress.
  void add_to(CLI::App& app);
  /// After parsing: a bar on a terminal, lines with --progress, nothing
  /// with --no-progress or `quiet`. The stages' times are kept for
  /// time_summary() in every case but `quiet`.
  void start(bool quiet = false);
  /// Stops showing (the bar's line is cleared); also done by the destructor.
  void stop();

  /// Seconds since construction.
  double seconds() const;
  /// The command's time and its slow parts, e.g. "23.1 s (writing the HTML
  /// report 14.0 s, solving 6.2 s)": the outermost stages that took at
  /// least a tenth of it and half a second, largest first, at most three.
  std::string time_summary() const;

private:
  class Display;
  std::chrono::steady_clock::time_point m_start;
  bool m_lines = false, m_off = false;
  std::unique_ptr<Display> m_display;
  std::optional<ProgressReporting> m_reporting;
};

} // namespace hilight::cli
