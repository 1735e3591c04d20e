#pragma once
/// Progress of long work (issue 36). The library says what it is doing and
/// how far along it is; a frontend shows it: the CLI a bar with the time
/// left on a terminal, or lines with --progress (frontends/common/progress_display.hpp);
/// the painter can show the same in its window.
///
/// Library code opens a ProgressStage around a piece of long work and
/// advances it from any thread. Stages nest per thread: one opened while
/// another is open on the same thread is a part of it; one opened on a
/// thread with none open (a worker of a parallel solve) is a part of the
/// oldest outermost stage. A part with a known
/// size fills `parent_units` of its parent's units as it goes (the parent
/// advances past them itself when the part is done); under a parent of
/// unknown size, a part's own fraction is the work's once it has run two
/// seconds (short calls inside a long stage do not make the line flicker).
///
/// Without a reporter (set_progress_reporter / ProgressReporting) stages
/// cost an atomic load and nothing is recorded. With one, a thread of this
/// facility calls the reporter at a fixed interval while work is open: the
/// rate is bounded however often the work advances, the reporter is never
/// called concurrently, and elapsed time goes on being shown while a stage
/// with no measure of its own runs.
#include <atomic>
#include <chrono>
#include <string>
#include <vector>

namespace hilight {

/// What is being done now, as a reporter is told it.
struct ProgressUpdate {
  std::vector<std::string> stages;  ///< the open stages worth showing, outermost first
  double fraction = -1;             ///< 0-1 of the measured work; negative: not known
  double elapsed = 0;               ///< seconds since the outermost stage began
  double seconds_left = -1;         ///< estimate from the fraction; negative: not known yet
};

class ProgressReporter {
public:
  virtual ~ProgressReporter() = default;
  /// Called every interval while a stage is open (from the facility's own
  /// thread; never concurrently with the other calls).
  virtual void update(const ProgressUpdate& now) = 0;
  /// A stage ended after `seconds` (`depth` 0: an outermost one).
  virtual void stage_ended(const std::string& /*name*/, size_t /*depth*/, double /*seconds*/) {}
  /// The last open stage ended: nothing is going on (a bar clears its line).
  virtual void idle() {}
};

/// Installs `reporter` for the process (nullptr: none) with a thread that
/// calls its update() every `interval_seconds` while stages are open.
/// Removing it stops the thread and waits for a call in progress.
void set_progress_reporter(ProgressReporter* reporter, double interval_seconds = 0.1);

/// set_progress_reporter for a scope: the reporter is removed when it ends
/// (also when an exception passes).
class ProgressReporting {
public:
  explicit ProgressReporting(ProgressReporter* reporter, double interval_seconds = 0.1);
  ~ProgressReporting();
  ProgressReporting(const ProgressReporting&) = delete;
  ProgressReporting& operator=(const ProgressReporting&) = delete;

private:
  bool m_installed = false;
};

/// The state the reporter would be told now (also without a reporter's
/// thread: a frontend may poll). Empty stages when nothing is open.
ProgressUpdate progress_now();

/// One piece of long work; see the file's comment.
class ProgressStage {
public:
  /// `total`: units of work the stage will be advanced by (0: not known).
  /// `parent_units`: how many of the enclosing stage's units this one is.
  explicit ProgressStage(std::string name, double total = 0, double parent_units = 1);
  ~ProgressStage();
  ProgressStage(const ProgressStage&) = delete;
  ProgressStage& operator=(const ProgressStage&) = delete;

  /// `units` more are done (any thread).
  void advance(double units = 1) {
    if (m_active) m_done.fetch_add(units, std::memory_order_relaxed);
  }
  /// What it is doing now, for a stage whose steps are not stages of their
  /// own (a Solver's, said from whichever thread reaches them; any thread).
  void rename(std::string name);
  /// The innermost stage open on this thread (nullptr: none, or no
  /// reporter): what code that was not handed a stage advances. Capture it
  /// before a parallel loop: worker threads have their own.
  static ProgressStage* current();

private:
  friend struct ProgressHub;
  friend ProgressUpdate progress_now();
  bool m_active = false;  ///< registered with a reporter
  std::string m_name;
  std::atomic<double> m_total{0}, m_done{0};
  double m_parent_units = 1;
  ProgressStage* m_parent = nullptr;    ///< what it is a part of; guarded by the hub's mutex after construction
  ProgressStage* m_previous = nullptr;  ///< the innermost stage of its thread before it (restored when it ends)
  std::chrono::steady_clock::time_point m_start;
  size_t m_depth = 0;
};

} // namespace hilight
