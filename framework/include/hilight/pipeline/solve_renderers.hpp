#pragma once
/// How every frontend sets up the two renderers of a solve (Solver's
/// `renderer` and `reference`), so the CLI and the painter give the same
/// result for the same input: the renderer's sample streams follow the
/// solve's seed; the reference is the renderer as the user configured it;
/// the fast twin that evaluates thousands of light positions uses cheaper
/// settings where the renderer has them.
#include <cstdint>
#include <string>
#include <vector>

namespace hilight {

/// `settings` (key=value) with the solve's seed added unless one is given.
std::vector<std::string> reference_renderer_settings(std::vector<std::string> settings, uint64_t seed);

/// The fast twin's settings, from the reference's:
/// - embree: `bounce_direct=vertex` (unless the user chose bounce_direct);
/// - ism-vulkan: `vpls=64` (fewer VPLs per light; the reference re-fits).
std::vector<std::string> fast_renderer_settings(const std::string& renderer, std::vector<std::string> reference_settings);

} // namespace hilight
