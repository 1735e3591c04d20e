#include "hilight/io/lights_file.hpp"

#include "hilight/io/gltf.hpp"
#include "hilight/io/lights_json.hpp"

namespace hilight {

namespace {
const char* intensity_unit(Units units) { return units == Units::Photometric ? "cd" : "W/sr"; }
} // namespace

Lighting read_lights_file(const std::filesystem::path& path, Units units, const SceneFrame* frame) {
  if (is_gltf_path(path)) return read_gltf_lights(path, frame);
  std::string stated;
  Lighting lights = read_lights_json(path, frame, &stated);
  // The file's own word wins; --units only speaks for a file that is silent.
  const Units in = stated.empty() ? units : stated == "cd" ? Units::Photometric : Units::Radiometric;
  return lights_from_units(std::move(lights), in);
}

void write_lights_file(const std::filesystem::path& path, const Lighting& lights, Units units, const std::string& length_unit) {
  write_lights_json(path, lights_to_units(lights, units), length_unit, nullptr, intensity_unit(units));
}

void write_lights_file(const std::filesystem::path& path, const Lighting& lights, Units units, const SceneFrame& frame) {
  write_lights_json(path, lights_to_units(lights, units), frame.unit, &frame, intensity_unit(units));
}

} // namespace hilight
