#include "hilight/io/lights_file.hpp"

#include "hilight/io/gltf.hpp"
#include "hilight/io/lights_json.hpp"

namespace hilight {

Lighting read_lights_file(const std::filesystem::path& path) {
  return is_gltf_path(path) ? read_gltf_lights(path) : read_lights_json(path);
}

} // namespace hilight
