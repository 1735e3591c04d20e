// hilight export SCENE --lights L.json -o scene.pov: a self-contained POV-Ray
// scene that renders what hilight shows (docs/povray.md).
#include "cli_common.hpp"
#include "commands.hpp"
#include "hilight/error.hpp"
#include "hilight/io/atomic_file.hpp"
#include "hilight/io/lights_json.hpp"
#include "hilight/io/pov_export.hpp"

#include <cstdio>
#include <fstream>

namespace hilight::cli {

int run_export(const std::vector<std::string>& args, Registry&) {
  CLI::App app("Write a POV-Ray 3.7 scene that follows hilight's rendering model", "export");
  std::string scene_path, lights_path, output, camera_text;
  float max_edge = 0.f;
  int bounces = 1, width = 960, height = 720;
  app.add_option("scene", scene_path, "scene file (any format assimp reads)")->required();
  app.add_option("--lights", lights_path, "lights JSON file")->required();
  app.add_option("-o,--output", output, "the .pov file to write")->required();
  app.add_option("--bounces", bounces, "0 = direct only, 1 = radiosity for the first bounce")->check(CLI::IsMember({0, 1}))->capture_default_str();
  app.add_option("--camera", camera_text, "eye_x,eye_y,eye_z,target_x,target_y,target_z,fov_deg (default frames the scene)");
  app.add_option("--width", width, "image width the camera is set up for")->check(CLI::Range(1, 16384))->capture_default_str();
  app.add_option("--height", height, "image height the camera is set up for")->check(CLI::Range(1, 16384))->capture_default_str();
  app.add_option("--max-edge", max_edge, "longest edge after tessellation (default: diagonal/40)")->check(FiniteNonNegative);
  if (auto code = parse_arguments(app, args)) return *code;

  check_writable(output);
  Lighting lights = read_lights_json(lights_path);
  std::optional<Camera> camera;
  if (!camera_text.empty()) camera = Camera::parse(camera_text);
  Scene scene = load_scene(scene_path, {max_edge});
  PovSettings settings;
  settings.bounces = bounces;
  write_atomically(output, [&](const std::filesystem::path& temp) {
    std::ofstream out(temp);
    write_pov_scene(out, scene, lights, settings);
    write_pov_camera(out, camera ? *camera : Camera::framing(scene.bounds, float(width) / float(height)), width, height);
    if (!out) throw InputError(output, "write failed");
  });
  std::fprintf(stderr, "wrote %s (render: povray +W%d +H%d +FE %s)\n", output.c_str(), width, height, output.c_str());
  return 0;
}

} // namespace hilight::cli
