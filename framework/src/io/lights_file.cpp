#include "hilight/io/lights_file.hpp"

#include "hilight/io/gltf.hpp"
#include "hilight/io/lights_json.hpp"

namespace hilight {

Lighting read_lights_file(const std::filesystem::path& path, Units units, const SceneFrame* frame) {
  return is_gltf_path(path) ? read_gltf_lights(path, frame) : lights_from_units(read_lights_json(path, frame), units);
}

void write_lights_file(const std::filesystem::path& path, const Lighting& lights, Units units, const std::string& length_unit) {
  write_lights_json(path, lights_to_units(lights, units), length_unit);
}

void write_lights_file(const std::filesystem::path& path, const Lighting& lights, Units units, const SceneFrame& frame) {
  write_lights_json(path, lights_to_units(lights, units), frame.unit, &frame);
}

} // namespace hilight
