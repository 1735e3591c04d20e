#include "hilight/bounces.hpp"

#include "hilight/error.hpp"

#include <charconv>

namespace hilight {

int parse_bounces(std::string_view text, const std::string& owner) {
  if (text == "all") return kAllBounces;
  int n = -1;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (error != std::errc() || end != text.data() + text.size() || n < 0 || n > kMaxBounceCount)
    throw InputError(owner + " must be 'all' or a count from 0 to " + std::to_string(kMaxBounceCount) + " (got '" +
                     std::string(text) + "')");
  return n;
}

std::string bounces_text(int bounces) { return bounces == kAllBounces ? "all" : std::to_string(bounces); }

std::string bounce_model(int bounces) {
  if (bounces == kAllBounces) return "every diffuse bounce";
  if (bounces == 0) return "direct light only";
  if (bounces == 1) return "the first diffuse bounce";
  return std::to_string(bounces) + " diffuse bounces";
}

int bounces_property(const Properties& props, int fallback, const std::string& owner) {
  return parse_bounces(props.get_string("bounces", bounces_text(fallback)), owner);
}

} // namespace hilight
