#pragma once
/// A lights file by its extension: a hilight lights JSON, or a glTF
/// (.gltf/.glb) whose KHR_lights_punctual lights are read (io/gltf.hpp).
#include "hilight/lighting.hpp"

#include <filesystem>

namespace hilight {

Lighting read_lights_file(const std::filesystem::path& path);

} // namespace hilight
