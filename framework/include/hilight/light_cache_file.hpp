#pragma once
/// Light cache files: a header (magic, format, key, size) and a checksum
/// around what the cache plugin writes, so that a file of another scene,
/// renderer or cache setting is never read, and a truncated or damaged one is
/// detected and rebuilt rather than read as garbage.
#include "hilight/light_cache.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace hilight {

/// The key of a cache: the scene's geometry and materials, the renderer's
/// settings, the cache plugin's settings key (LightCacheBuilder::settings_key), and the box lights stand in.
uint64_t light_cache_key(const Scene& scene, const std::string& renderer_key, const std::string& cache_settings_key,
                         const Bounds& bounds);

/// Writes atomically (a half-written file never appears under `file`).
void save_light_cache(const std::filesystem::path& file, uint64_t key, const LightCache& cache);

struct LoadedCache {
  std::unique_ptr<LightCache> cache;  ///< null when absent, of another key, or damaged
  std::string damage;                 ///< why a file with this key was not usable ("" otherwise)
};

/// Reads `file` when it exists and holds this key, checking its checksum.
LoadedCache load_light_cache(const std::filesystem::path& file, uint64_t key, const LightCacheBuilder& builder,
                             size_t vertex_count);

} // namespace hilight
