#pragma once
/// Seeded random light configurations for the tests (never hand-placed):
/// ceiling lamps a given drop below whatever ceiling is above a random free
/// point, and free-standing lights with a clearance from every surface.
#include "hilight/lighting.hpp"
#include "hilight/ray_scene.hpp"

#include <cstdint>
#include <random>

namespace test {

struct LampRules {
  float min_drop = 0.15f, max_drop = 0.40f;  ///< below the ceiling (scene units: metres)
  float min_room_height = 2.0f;              ///< floor to ceiling, so it is a room, not a gap in a wall
  float min_intensity = 1.f, max_intensity = 4.f;
  bool coloured = true;                      ///< random tint per light
};

/// `count` point lights hanging below ceilings, each inside the scene's light
/// space and out of solids. REQUIREs that they can be placed.
hilight::Lighting random_ceiling_lamps(const hilight::RayScene& rays, std::mt19937_64& rng, size_t count,
                                       const LampRules& rules = {});

/// `count` point lights anywhere in the light space, at least `clearance`
/// (fraction of the diagonal) from every surface and out of solids.
hilight::Lighting random_free_lights(const hilight::RayScene& rays, std::mt19937_64& rng, size_t count,
                                     float clearance = 0.05f, const LampRules& rules = {});

} // namespace test
