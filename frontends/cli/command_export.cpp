// hilight export SCENE --lights L -o scene.pov|scene.gltf|scene.glb: a
// self-contained POV-Ray scene that renders what hilight shows
// (docs/povray.md), or a glTF with the scene's meshes and the lights as
// KHR_lights_punctual (docs/interchange.md) for Blender, game engines and
// other glTF tools.
#include "cli_common.hpp"
#include "hilight/scene_origin.hpp"
#include "commands.hpp"
#include "hilight/error.hpp"
#include "hilight/io/atomic_file.hpp"
#include "hilight/io/gltf.hpp"
#include "hilight/io/lights_file.hpp"
#include "hilight/io/pov_export.hpp"

#include <cstdio>
#include <fstream>

namespace hilight::cli {

int run_export(const std::vector<std::string>& args, Registry& registry) {
  CLI::App app("Write the scene and its lights for another tool: POV-Ray 3.7 (.pov, following hilight's rendering model) or glTF 2.0 (.gltf/.glb)", "export");
  std::string scene_path, lights_path, output, camera_text;
  std::string bounces = "all";
  int width = 960, height = 720;
  bool vertex_colours = false;
  app.add_option("scene", scene_path, "scene file (any format assimp reads)")->required();
  app.add_option("--lights", lights_path, "lights: hilight JSON, or a glTF's KHR_lights_punctual (.gltf/.glb)")->required();
  app.add_option("-o,--output", output, "the .pov, .gltf or .glb file to write")->required();
  app.add_option("--bounces", bounces, "diffuse bounces: all, 0 (direct only), 1, or a count (POV-Ray radiosity recursion up to 20; glTF --vertex-colours)")
      ->check(BounceCount)
      ->capture_default_str();
  app.add_option("--camera", camera_text, "eye_x,eye_y,eye_z,target_x,target_y,target_z,fov_deg (.pov; default frames the scene)");
  app.add_option("--width", width, "image width the camera is set up for (.pov)")->check(CLI::Range(1, 16384))->capture_default_str();
  app.add_option("--height", height, "image height the camera is set up for (.pov)")->check(CLI::Range(1, 16384))->capture_default_str();
  SceneLoadOptions scene_options;
  add_scene_options(app, scene_options);
  std::string units_name = "radiometric";
  app.add_option("--units", units_name, "a lights JSON's intensities: radiometric (W/sr) or photometric (candela)")
      ->check(CLI::IsMember({"radiometric", "photometric"}))
      ->capture_default_str();
  app.add_flag("--vertex-colours", vertex_colours, "glTF: the lights' illumination per vertex as COLOR_0 (the default renderer)");
  if (auto code = parse_arguments(app, args)) return *code;

  const bool gltf = is_gltf_path(output);
  const std::string ext = std::filesystem::path(output).extension().string();
  if (!gltf && ext != ".pov") throw InputError(output, "the output must end in .pov, .gltf or .glb");
  if (vertex_colours && !gltf) throw InputError("--vertex-colours needs a .gltf or .glb output, not " + output);
  check_writable(output);
  const Units units = parse_units(units_name);
  read_lights_file(lights_path, units);  // fails before the scene loads
  std::optional<Camera> camera;
  if (!camera_text.empty()) camera = Camera::parse(camera_text);
  auto scene = std::make_shared<const Scene>(load_scene(scene_path, scene_options));
  // In the scene's coordinates (scene_origin.hpp): the glTF puts them back in the world; a
  // .pov file stays in the scene's own, camera and lights with it.
  const Lighting lights = lights_from_file(lights_path, units, *scene);
  if (camera) {
    camera->eye = to_local(camera->eye, scene->frame);
    camera->target = to_local(camera->target, scene->frame);
  }
  if (gltf) {
    GltfExport contents;
    contents.scene = scene.get();
    contents.lights = lights;
    if (vertex_colours) {
      auto renderer = registry.create_renderer(PluginDefaults::renderer, Properties::from_assignments({"bounces=" + bounces}));
      renderer->set_scene(scene);
      contents.result = renderer->illuminate(SurfacePoints::from_vertices(*scene), lights);
    }
    write_gltf(output, contents);
    std::fprintf(stderr, "wrote %s (%zu vertices, %zu lights)\n", output.c_str(), scene->positions.size(), lights.size());
    return 0;
  }
  PovSettings settings;
  settings.bounces = parse_bounces(bounces, "--bounces");
  if (settings.bounces > kPovMaxBounces)
    throw InputError("--bounces: a POV-Ray scene carries at most " + std::to_string(kPovMaxBounces) + " bounces (say all)");
  write_atomically(output, [&](std::ostream& out) {
    write_pov_scene(out, *scene, lights, settings);
    write_pov_camera(out, camera ? *camera : Camera::framing(scene->bounds, float(width) / float(height)), width, height);
  });
  std::fprintf(stderr, "wrote %s (render: povray +W%d +H%d +FE %s)\n", output.c_str(), width, height, output.c_str());
  return 0;
}

} // namespace hilight::cli
