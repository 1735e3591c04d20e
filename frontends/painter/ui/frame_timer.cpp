#include "ui/frame_timer.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace hilight::painter::ui {

namespace {

double percentile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  size_t k = std::min(values.size() - 1, size_t(q * double(values.size() - 1) + 0.5));
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
  return values[k];
}

nlohmann::json summary(const std::map<std::string, std::vector<double>>& series) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [name, values] : series) {
    out[name] = {{"count", values.size()},
                 {"median_ms", median(values)},
                 {"p90_ms", percentile(values, 0.9)},
                 {"max_ms", values.empty() ? 0.0 : *std::max_element(values.begin(), values.end())}};
  }
  return out;
}

} // namespace

double median(std::vector<double> values) { return percentile(std::move(values), 0.5); }

std::string FrameTimer::to_json() const {
  return nlohmann::json{{"frames", summary(m_frames)}, {"latency", summary(m_latency)}}.dump(2) + "\n";
}

} // namespace hilight::painter::ui
