#include "hilight/pipeline/solve_renderers.hpp"

#include <algorithm>

namespace hilight {

namespace {

bool has_setting(const std::vector<std::string>& settings, const std::string& key) {
  return std::any_of(settings.begin(), settings.end(), [&](const std::string& kv) { return kv.rfind(key + "=", 0) == 0; });
}

} // namespace

std::vector<std::string> reference_renderer_settings(std::vector<std::string> settings, uint64_t seed) {
  // Renderer seeds are signed 64-bit settings: fold the solve's seed into range.
  if (!has_setting(settings, "seed")) settings.push_back("seed=" + std::to_string(seed & 0x7FFFFFFFFFFFFFFFull));
  return settings;
}

std::vector<std::string> fast_renderer_settings(const std::string& renderer, std::vector<std::string> settings) {
  if (renderer == "embree" && !has_setting(settings, "bounce_direct")) settings.push_back("bounce_direct=vertex");
  // Hot patches cost the vertex mode 1.6x per light even with one shadow ray
  // for all of them (and a cold start 1.6x); the fast twin's fireflies are
  // the reference polish's to remove, so it gathers alone.
  if (renderer == "embree" && !has_setting(settings, "hot_spots")) settings.push_back("hot_spots=off");
  if (renderer == "ism-vulkan") {
    std::erase_if(settings, [](const std::string& kv) { return kv.rfind("vpls=", 0) == 0; });
    settings.push_back("vpls=64");
  }
  return settings;
}

} // namespace hilight
