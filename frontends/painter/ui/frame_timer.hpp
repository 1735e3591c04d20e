#pragma once
/// Frame and latency figures for `--timings`: frame times split by what the
/// frame was doing (camera move, brush stroke, idle), and stroke-release →
/// fine-tuned-lights latencies.
#include <map>
#include <string>
#include <vector>

namespace hilight::painter::ui {

class FrameTimer {
public:
  /// One frame's duration in milliseconds, under `activity` ("camera", "stroke", "idle").
  void add_frame(const std::string& activity, double ms) { m_frames[activity].push_back(ms); }
  /// One latency sample in milliseconds under `name` (e.g. "stroke_to_fine_tune").
  void add_latency(const std::string& name, double ms) { m_latency[name].push_back(ms); }

  /// {"frames": {"camera": {"count":..,"median_ms":..,"p90_ms":..,"max_ms":..}, ...}, "latency": {...}}
  std::string to_json() const;

private:
  std::map<std::string, std::vector<double>> m_frames, m_latency;
};

double median(std::vector<double> values);

} // namespace hilight::painter::ui
