#pragma once
/// How many diffuse bounces a render carries (docs/rendering-model.md,
/// "Illumination"): 0 is direct light only, 1 the paper's first bounce, N
/// exactly N, and "all" every bounce, iterated to convergence.
#include "hilight/properties.hpp"

#include <string>
#include <string_view>

namespace hilight {

/// "all": every bounce, to the renderer's stated tolerance.
constexpr int kAllBounces = -1;
/// The most bounces a number may ask for (beyond it, say "all").
constexpr int kMaxBounceCount = 1000;

/// "all" -> kAllBounces, "0".."1000" -> the count; otherwise InputError
/// naming `owner` (e.g. "--bounces" or "renderer embree: bounces").
int parse_bounces(std::string_view text, const std::string& owner);
/// The inverse: "all" or the count.
std::string bounces_text(int bounces);
/// In words, for reports: "every diffuse bounce", "the first diffuse bounce",
/// "direct light only" or "N diffuse bounces".
std::string bounce_model(int bounces);
/// The "bounces" property of a renderer (`fallback` when unset).
int bounces_property(const Properties& props, int fallback, const std::string& owner);

} // namespace hilight
