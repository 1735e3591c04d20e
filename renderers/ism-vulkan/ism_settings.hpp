#pragma once
/// The ism-vulkan renderer's parameters (documented in docs/ism-vulkan.md and
/// ism_plugin.cpp, where they are read and checked).
#include "vulkan_context.hpp"

#include <cstdint>
#include <string>

namespace hilight::ism {

struct IsmSettings {
  int bounces = 1;                 ///< 0: direct light only; 1: plus the first bounce from VPLs; N or kAllBounces: more (bounce_transport.hpp)
  uint32_t shadow_size = 512;      ///< cube ID map face resolution (texels)
  uint32_t vpls = 256;             ///< virtual point lights per light
  uint32_t ism_size = 32;          ///< imperfect shadow map resolution per VPL (power of two)
  uint32_t points_per_vpl = 4096;  ///< scene point samples splatted into each VPL's ISM
  uint32_t ism_points = 262144;    ///< point samples of the scene in all (each VPL takes a random subset)
  float ism_bias = 0.04f;          ///< ISM depth bias, relative to the distance
  float vpl_clamp = 0.05f;         ///< VPL distances below this fraction of the diagonal are clamped
  uint32_t bounce_points = 2048;   ///< surface samples carrying bounces 2.. (at most 32767)
  uint32_t bounce_map = 16;        ///< their and the shaded points' hemisphere maps, texels a side (power of two)
  uint32_t chunk_mb = 192;         ///< device memory per batch of lights in one submission
  uint64_t memory_mb = 0;          ///< the renderer's own device-memory limit (0: 3/4 of the largest heap)
  uint32_t workgroup = 64;         ///< compute work-group width
  uint64_t seed = 1;               ///< VPL spiral rotation and ISM point pool
  DeviceOptions device;

  std::string key() const;
};

} // namespace hilight::ism
