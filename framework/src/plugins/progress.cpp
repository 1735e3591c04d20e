#include "hilight/progress.hpp"

#include <algorithm>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace hilight {

namespace {

using Clock = std::chrono::steady_clock;

/// A part's name is shown once it has run this long, and its fraction as
/// the work's (under a parent of unknown size) once it has run kMeasureAfter:
/// the many short renderer calls inside a solve's stage would make the line
/// flicker between their fractions; a long one (a light cache, a large
/// render) is measured.
constexpr double kShowAfter = 0.5, kMeasureAfter = 2.0;

double seconds_since(Clock::time_point t, Clock::time_point now) { return std::chrono::duration<double>(now - t).count(); }

thread_local ProgressStage* t_innermost = nullptr;

} // namespace

struct ProgressHub {
  std::mutex state;                        ///< guards `open` and the stages' parents
  std::vector<ProgressStage*> open;        ///< in the order they were opened
  std::atomic<ProgressReporter*> reporter{nullptr};
  std::mutex calls;                        ///< one reporter call at a time
  std::mutex ticker_mutex;
  std::condition_variable ticker_wake;
  bool stop = false;                       ///< guarded by ticker_mutex
  std::thread ticker;

  static ProgressHub& get() {
    static ProgressHub hub;
    return hub;
  }

  ProgressUpdate snapshot(Clock::time_point now) {
    std::lock_guard lock(state);
    ProgressUpdate out;
    auto root = std::find_if(open.begin(), open.end(), [](const ProgressStage* s) { return !s->m_parent; });
    if (root == open.end()) return out;
    // The chain from the oldest outermost stage to its most recent part.
    std::vector<ProgressStage*> chain{*root};
    for (;;) {
      ProgressStage* child = nullptr;
      for (auto it = open.rbegin(); it != open.rend(); ++it)
        if ((*it)->m_parent == chain.back()) {
          child = *it;
          break;
        }
      if (!child) break;
      chain.push_back(child);
    }
    const size_t n = chain.size();
    std::vector<double> f(n, -1.0);
    for (size_t k = n; k-- > 0;) {
      const ProgressStage& s = *chain[k];
      const double total = s.m_total.load(std::memory_order_relaxed), done = s.m_done.load(std::memory_order_relaxed);
      const bool child_shown = k + 1 < n && seconds_since(chain[k + 1]->m_start, now) >= kMeasureAfter;
      const double part = k + 1 < n && f[k + 1] >= 0 ? std::min(f[k + 1], 1.0) * chain[k + 1]->m_parent_units : 0.0;
      if (total > 0)
        f[k] = std::clamp((done + part) / total, 0.0, 1.0);
      else if (child_shown && k + 1 < n)
        f[k] = f[k + 1];
    }
    // Names: the outermost's, then each part's that has run a while, unless
    // unnamed (a call whose purpose is its caller's stage) or the same again.
    for (size_t k = 0; k < n; ++k) {
      const std::string& name = chain[k]->m_name;
      if (name.empty() || (k > 0 && seconds_since(chain[k]->m_start, now) < kShowAfter)) continue;
      if (out.stages.empty() || out.stages.back() != name) out.stages.push_back(name);
    }
    out.elapsed = seconds_since(chain[0]->m_start, now);
    // The time left of the outermost stage that has a measure.
    for (size_t k = 0; k < n; ++k) {
      if (f[k] < 0) continue;
      out.fraction = f[k];
      const double t = seconds_since(chain[k]->m_start, now);
      if (f[k] >= 1.0)
        out.seconds_left = 0;
      else if (f[k] >= 0.01 && t >= 1.0)
        out.seconds_left = t * (1.0 - f[k]) / f[k];
      break;
    }
    return out;
  }

  void tick_until_stopped(double interval) {
    const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(interval));
    std::unique_lock lock(ticker_mutex);
    while (!ticker_wake.wait_for(lock, period, [&] { return stop; })) {
      std::lock_guard call(calls);
      ProgressReporter* r = reporter.load();
      if (!r) continue;
      const ProgressUpdate now = snapshot(Clock::now());
      if (!now.stages.empty()) r->update(now);
    }
  }

  void install(ProgressReporter* r, double interval) {
    if (ticker.joinable()) {
      {
        std::lock_guard lock(ticker_mutex);
        stop = true;
      }
      ticker_wake.notify_all();
      ticker.join();
    }
    {
      std::lock_guard call(calls);
      reporter.store(r);
    }
    if (!r) return;
    stop = false;
    ticker = std::thread([this, interval] { tick_until_stopped(std::max(interval, 0.005)); });
  }
};

void set_progress_reporter(ProgressReporter* reporter, double interval_seconds) {
  ProgressHub::get().install(reporter, interval_seconds);
}

ProgressReporting::ProgressReporting(ProgressReporter* reporter, double interval_seconds) {
  if (!reporter) return;
  set_progress_reporter(reporter, interval_seconds);
  m_installed = true;
}

ProgressReporting::~ProgressReporting() {
  if (m_installed) set_progress_reporter(nullptr);
}

ProgressUpdate progress_now() { return ProgressHub::get().snapshot(Clock::now()); }

ProgressStage::ProgressStage(std::string name, double total, double parent_units) : m_name(std::move(name)) {
  ProgressHub& hub = ProgressHub::get();
  if (!hub.reporter.load(std::memory_order_relaxed)) return;
  m_total.store(total, std::memory_order_relaxed);
  m_parent_units = parent_units;
  m_start = Clock::now();
  std::lock_guard lock(hub.state);
  m_active = true;
  m_previous = t_innermost;
  // On a thread with no stage of its own (a worker of a parallel solve), a
  // part of the work that is going on: the oldest outermost stage's.
  m_parent = m_previous;
  if (!m_parent) {
    auto root = std::find_if(hub.open.begin(), hub.open.end(), [](const ProgressStage* s) { return !s->m_parent; });
    if (root != hub.open.end()) m_parent = *root;
  }
  m_depth = m_parent ? m_parent->m_depth + 1 : 0;
  hub.open.push_back(this);
  t_innermost = this;
}

ProgressStage::~ProgressStage() {
  if (!m_active) return;
  ProgressHub& hub = ProgressHub::get();
  bool idle;
  {
    std::lock_guard lock(hub.state);
    hub.open.erase(std::remove(hub.open.begin(), hub.open.end(), this), hub.open.end());
    // A part still open (closed out of order) belongs to this one's parent now.
    for (ProgressStage* s : hub.open)
      if (s->m_parent == this) s->m_parent = m_parent;
    if (t_innermost == this) t_innermost = m_previous;
    idle = hub.open.empty();
  }
  const double seconds = seconds_since(m_start, Clock::now());
  std::lock_guard call(hub.calls);
  if (ProgressReporter* r = hub.reporter.load()) {
    r->stage_ended(m_name, m_depth, seconds);
    if (idle) r->idle();
  }
}

ProgressStage* ProgressStage::current() { return t_innermost; }

void ProgressStage::rename(std::string name) {
  std::lock_guard lock(ProgressHub::get().state);  // also inactive: two threads may rename at once
  m_name = std::move(name);
}

} // namespace hilight
