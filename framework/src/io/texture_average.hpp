#pragma once
// The average colour of a material's base-colour texture, so textured scenes
// get a sensible albedo (one colour per material; texture lookups per point
// are not modelled). Private to scene_io.cpp.
#include "hilight/math.hpp"

#include <filesystem>
#include <optional>
#include <string>

struct aiScene;
struct aiMaterial;

namespace hilight {

/// Linear average of the material's base-colour (or diffuse) texture: sRGB
/// texels decoded to linear, weighted by alpha. nullopt when the material
/// has no texture; `problem` is set when it has one that cannot be read.
/// A texture outside the scene's folder is not read (issue 35): `problem`
/// says so.
std::optional<Rgb> average_texture(const aiScene& scene, const aiMaterial& material, const std::filesystem::path& scene_folder,
                                   std::string& problem);

} // namespace hilight
