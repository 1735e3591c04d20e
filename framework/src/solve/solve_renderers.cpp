#include "hilight/solve/solve_renderers.hpp"

#include <algorithm>

namespace hilight {

namespace {

bool has_setting(const std::vector<std::string>& settings, const std::string& key) {
  return std::any_of(settings.begin(), settings.end(), [&](const std::string& kv) { return setting_key(kv) == key; });
}

} // namespace

std::string setting_key(const std::string& assignment) { return assignment.substr(0, assignment.find('=')); }

std::vector<std::string> reference_renderer_settings(std::vector<std::string> settings, uint64_t seed) {
  // Renderer seeds are signed 64-bit settings: fold the solve's seed into range.
  if (!has_setting(settings, "seed")) settings.push_back("seed=" + std::to_string(seed & 0x7FFFFFFFFFFFFFFFull));
  return settings;
}

std::vector<std::string> with_defaults(std::vector<std::string> settings, const std::vector<std::string>& defaults) {
  const std::vector<std::string> chosen = settings;
  for (const auto& kv : defaults)
    if (!has_setting(chosen, setting_key(kv))) settings.push_back(kv);
  return settings;
}

std::vector<std::string> fast_renderer_settings(const RendererTraits& traits, std::vector<std::string> reference_settings) {
  return with_defaults(std::move(reference_settings), traits.fast_twin);
}

} // namespace hilight
