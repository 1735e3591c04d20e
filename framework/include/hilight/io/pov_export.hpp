#pragma once
/// POV-Ray 3.7 scenes that follow hilight's rendering model exactly
/// (docs/povray.md): mesh2 geometry with normals, Lambertian finishes,
/// inverse-square point and spot lights, no ambient, no specular, optional
/// radiosity limited to the first bounce.
#include "hilight/camera.hpp"
#include "hilight/lighting.hpp"
#include "hilight/scene.hpp"

#include <ostream>
#include <string>

namespace hilight {

/// POV-Ray's radiosity recursion_limit goes up to 20: "all bounces" there.
constexpr int kPovMaxBounces = 20;

struct PovSettings {
  int bounces = 1;               ///< 0: direct only; N: radiosity with recursion_limit N; kAllBounces: kPovMaxBounces
  int radiosity_count = 800;     ///< rays per radiosity sample
  double error_bound = 0.15;     ///< radiosity error_bound (lower = more samples)
  double pretrace_end = 0.005;   ///< radiosity pretrace_end (lower = denser samples)
  /// Both sides of each surface lit at once (POV-Ray's double_illuminate), as
  /// a user's export wants. Baking turns it off and bakes each side on its own.
  bool double_illuminate = true;
};

/// fade_distance used for inverse-square lights: far below any distance in
/// the scene, so POV-Ray's 2/(1+(d/fd)²) is 2fd²/d² to within (fd/d)².
float pov_fade_distance(const Scene& scene);

/// Global settings, the mesh and the lights (no camera).
void write_pov_scene(std::ostream& out, const Scene& scene, const Lighting& lights, const PovSettings& settings);
/// A perspective camera showing what hilight's Camera shows (right-handed:
/// POV-Ray is left-handed, so the right vector is mirrored).
void write_pov_camera(std::ostream& out, const Camera& camera, int width, int height);

} // namespace hilight
