#pragma once
/// How every frontend sets up the two renderers of a solve (Solver's
/// `renderer` and `reference`), so the CLI and the painter give the same
/// result for the same input: the renderer's sample streams follow the
/// solve's seed; the reference is the renderer as the user configured it;
/// the fast twin that evaluates thousands of light positions takes the
/// cheaper settings its plugin declares (RendererTraits::fast_twin).
#include "hilight/registry.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace hilight {

/// `settings` (key=value) with the solve's seed added unless one is given.
std::vector<std::string> reference_renderer_settings(std::vector<std::string> settings, uint64_t seed);

/// The key of a `key=value` setting.
std::string setting_key(const std::string& assignment);

/// `settings` with each of `defaults` (key=value) added whose key they do not set.
std::vector<std::string> with_defaults(std::vector<std::string> settings, const std::vector<std::string>& defaults);

/// The fast twin's settings, from the reference's: the renderer's declared
/// fast-twin settings added where the user did not choose.
std::vector<std::string> fast_renderer_settings(const RendererTraits& traits, std::vector<std::string> reference_settings);

} // namespace hilight
