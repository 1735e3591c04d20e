// hilight export SCENE --lights L -o scene.pov|scene.gltf|scene.glb: a
// self-contained POV-Ray scene that renders what hilight shows
// (docs/povray.md), or a glTF with the scene's meshes and the lights as
// KHR_lights_punctual (docs/interchange.md) for Blender, game engines and
// other glTF tools.
#include "cli_common.hpp"
#include "hilight/scene_origin.hpp"
#include "commands.hpp"
#include "hilight/default_view.hpp"
#include "hilight/error.hpp"
#include "hilight/io/atomic_file.hpp"
#include "hilight/io/gltf.hpp"
#include "hilight/io/lights_file.hpp"
#include "hilight/io/pov_export.hpp"
#include "progress_display.hpp"

#include <cstdio>
#include <fstream>

namespace hilight::cli {

int run_export(const std::vector<std::string>& args, Registry& registry) {
  CommandProgress progress;  // first: the summary's time is the whole command's
  CLI::App app("Write the scene and its lights for another tool: glTF 2.0 (.gltf/.glb: Blender, game engines) or POV-Ray 3.7 "
               "(.pov, following hilight's rendering model).\n"
               "  hilight export SCENE --lights lights.json -o scene.glb",
               "export");
  std::string scene_path, lights_path, output, camera_text;
  std::string bounces = "all";
  int width = 960, height = 720;
  bool vertex_colours = false;
  app.add_option("scene", scene_path, "the scene: any format assimp reads (OBJ, glTF, FBX, IFC, ...)")->required();
  app.add_option("--lights", lights_path, "the lights: hilight's .json, or a .gltf/.glb's lights")->required();
  app.add_option("-o,--output", output, "what to write: a .gltf, .glb or .pov file")->required();
  app.add_option("--bounces", bounces, "diffuse bounces: all, 0 (direct only), 1, or a count (POV-Ray radiosity recursion up to 20; glTF --vertex-colours)")
      ->check(BounceCount)
      ->capture_default_str();
  SceneLoadOptions scene_options;
  add_scene_options(app, scene_options, kAdvanced);
  std::string units_name = "radiometric";
  app.add_option("--units", units_name,
                 "a lights .json's intensities when it does not state its intensity_unit: radiometric (W/sr) or photometric (candela)")
      ->check(CLI::IsMember({"radiometric", "photometric"}))
      ->capture_default_str();
  app.add_flag("--vertex-colours", vertex_colours, "glTF: the lights' illumination per vertex as COLOR_0 (the default renderer)");
  app.add_option("--camera", camera_text, ".pov: where the picture is taken from: eye_x,eye_y,eye_z,target_x,target_y,target_z,fov_deg")
      ->group(kAdvanced);
  app.add_option("--width", width, ".pov: image width the camera is set up for")->check(CLI::Range(1, 16384))->capture_default_str()->group(kAdvanced);
  app.add_option("--height", height, ".pov: image height the camera is set up for")->check(CLI::Range(1, 16384))->capture_default_str()->group(kAdvanced);
  progress.add_to(app);
  if (auto code = parse_arguments(app, args)) return *code;

  const bool gltf = is_gltf_path(output);
  const std::string ext = std::filesystem::path(output).extension().string();
  if (!gltf && ext != ".pov") throw InputError(output, "unknown output type '" + ext + "' (use .gltf or .glb for glTF, .pov for POV-Ray)");
  if (vertex_colours && !gltf) throw InputError("--vertex-colours needs a .gltf or .glb output, not " + output);
  check_writable(output);
  const Units units = parse_units(units_name);
  read_lights_file(lights_path, units);  // fails before the scene loads
  std::optional<Camera> camera;
  if (!camera_text.empty()) camera = Camera::parse(camera_text);
  progress.start();
  std::optional<ProgressStage> stage(std::in_place, "loading the scene");
  auto scene = std::make_shared<const Scene>(load_scene(scene_path, scene_options));
  // In the scene's coordinates (scene_origin.hpp): the glTF puts them back in the world; a
  // .pov file stays in the scene's own, camera and lights with it.
  const Lighting lights = lights_from_file(lights_path, units, *scene);
  if (camera) {
    camera->eye = to_local(camera->eye, scene->frame);
    camera->target = to_local(camera->target, scene->frame);
  }
  stage.emplace("writing " + std::filesystem::path(output).filename().string());
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
    stage.reset();  // the bar's line is cleared before the line below
    std::fprintf(stderr, "wrote %s (%zu vertices, %zu lights) in %s\n", output.c_str(), scene->positions.size(), lights.size(),
                 progress.time_summary().c_str());
    return 0;
  }
  PovSettings settings;
  settings.bounces = parse_bounces(bounces, "--bounces");
  if (settings.bounces > kPovMaxBounces)
    throw InputError("--bounces: a POV-Ray scene carries at most " + std::to_string(kPovMaxBounces) + " bounces (say all)");
  // No --camera: the view `hilight render` takes (default_view.hpp).
  if (!camera) camera = default_view(RayScene(*scene), lights, float(width) / float(height));
  write_atomically(output, [&](std::ostream& out) {
    write_pov_scene(out, *scene, lights, settings);
    write_pov_camera(out, *camera, width, height);
  });
  stage.reset();
  std::fprintf(stderr, "wrote %s in %s (render: povray +W%d +H%d +FE %s)\n", output.c_str(), progress.time_summary().c_str(), width,
               height, output.c_str());
  return 0;
}

} // namespace hilight::cli
