#pragma once
/// What every `hilight bench` figure is made of: medians of timed runs and
/// the process's peak memory.
#include <algorithm>
#include <chrono>
#include <sys/resource.h>
#include <vector>

namespace hilight::bench {

/// The median (the upper one of an even count); 0 for none.
inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

/// Seconds `f` takes.
template <class F>
double seconds_of(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The process's peak resident memory so far, in MB (getrusage).
inline double peak_rss_mb() {
  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;
}

} // namespace hilight::bench
