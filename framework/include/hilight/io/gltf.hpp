#pragma once
/// glTF 2.0 in and out (through libtinygltf): the scene's meshes, lights as
/// KHR_lights_punctual, per-vertex illumination as COLOR_0 / COLOR_1.
///
/// Units: a light's intensity is W/sr per channel here; glTF wants candela.
/// The intensity is split as the spec asks, colour × scalar, with the colour's
/// largest channel 1, and the scalar in candela is 683 × W/sr (683 lm/W:
/// cd = W·683/(4π) for a point light of W watts, Blender's importer's rule).
/// Spotlights: outerConeAngle = cutoff, innerConeAngle = cutoff − falloff
/// (glTF's soft edge is t² in the cosine, ours smoothstep: docs/interchange.md).
/// Lights point down their node's −Z and stand at its translation.
#include "hilight/lighting.hpp"
#include "hilight/scene.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace hilight {

/// Candela per W/sr (luminous efficacy at 555 nm).
constexpr double kCandelaPerWattPerSr = 683.0;

/// True for .gltf and .glb (any case).
bool is_gltf_path(const std::filesystem::path& path);

struct GltfExport {
  const Scene* scene = nullptr;   ///< its meshes (nullptr: the lights only)
  Lighting lights;  ///< in the scene's local coordinates: written where they stand in the world (scene.origin)
  /// Per scene vertex (empty: not written): COLOR_0 = what the lights give,
  /// COLOR_1 = the target, alpha its weight (0: no target point there).
  std::vector<Rgb> result, target;
  std::vector<float> target_weight;
  /// Written as the glTF scene's extras.hilight (e.g. "lights", "dbar").
  std::map<std::string, double> figures;
};

/// Writes .glb (binary) or .gltf (buffers embedded) atomically.
void write_gltf(const std::filesystem::path& path, const GltfExport& contents);

/// The KHR_lights_punctual lights of the file's default scene, in world
/// space (node transforms applied). InputError naming the file for what is
/// not a light hilight has (directional lights) or a broken file. With
/// `frame`, moved into that scene's frame in double precision (scene_origin.hpp).
Lighting read_gltf_lights(const std::filesystem::path& path, const SceneFrame* frame = nullptr);

/// Points with colours from a glTF: every vertex of every mesh primitive with
/// COLOR_0 (or `attribute`), in world space.
struct GltfColours {
  std::vector<Vec3> positions, normals;  ///< normals empty when a primitive has none
  std::vector<Rgb> values;               ///< linear RGB (× the file's colour scale, when hilight wrote it)
  std::vector<float> weights;            ///< a _WEIGHT attribute, else the alpha channel, else 1
};
GltfColours read_gltf_colours(const std::filesystem::path& path, const std::string& attribute = "COLOR_0");

} // namespace hilight
