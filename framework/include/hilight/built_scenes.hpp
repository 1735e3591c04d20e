#pragma once
/// The scenes of issue 10 built in code (a building, a corridor, a product, a
/// stage), with the zones where a seeded random light configuration of that
/// kind of scene stands: the recovery tests, `hilight bench solve` and the
/// painter's tests share them. Metres, +Y up; raw meshes (finish_scene()).
#include "hilight/lighting.hpp"
#include "hilight/ray_scene.hpp"
#include "hilight/scene.hpp"

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace hilight::builders {

struct BuiltScene {
  std::string name;
  Scene scene;
  /// Where random lights of this scene stand (one box a room; boxes around
  /// the product; the stage's rig). A light is drawn in a random zone.
  std::vector<Bounds> zones;
  /// Spots aim at points in here (the stage's platform); none: point lights.
  std::optional<Bounds> aim;
  /// Lights stand far from what they light (a product): intensities grow
  /// with the squared distance to the scene's centre, so each one counts.
  bool far_lights = false;
};

/// Two storeys of four rooms each (12 x 8 m, 2.8 m rooms): thick walls,
/// doors between the rooms of a storey, a window in each room, a stair
/// through an opening in the upper floor, a table and a cabinet per room.
BuiltScene two_storey_building();
/// An L-shaped corridor (legs 10 m and 10 m, 2 m wide, 2.6 m high) with a
/// bench in each leg.
BuiltScene l_corridor();
/// A product (a body, a neck, a sphere) on a turntable, in open space: the
/// zones lie outside its bounds, where a key, a fill and a rim light stand.
BuiltScene product_on_turntable();
/// A stage (a platform, a back wall, side flats, props, no ceiling): spots
/// hang in the rig above and in front, aimed at the platform.
BuiltScene stage();

struct RandomLightRules {
  size_t min_count = 1, max_count = 8;
  float min_intensity = 1.f, max_intensity = 4.f;  ///< at 1 m; scaled by the zone's distance for open scenes
  float min_apart = 0.1f;                          ///< share of the diagonal between two lights
  float clearance = 0.02f;                         ///< share of the diagonal from every surface
};

/// A seeded random configuration: 1–8 lights (rules) in random zones, random
/// colours, some zones left dark; spots aimed into `aim` with random cutoffs
/// where the scene has one. `rays`: over the finished scene. Positions are
/// free: in its light bounds (the open ones for far lights), out of solids,
/// clear of surfaces.
Lighting random_lights(const BuiltScene& built, const RayScene& rays, std::mt19937_64& rng, const RandomLightRules& rules);

} // namespace hilight::builders
