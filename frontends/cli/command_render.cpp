// hilight render SCENE --lights L.json -o OUT[.ply|.png|.exr]
#include "cli_common.hpp"
#include "hilight/scene_origin.hpp"
#include "commands.hpp"
#include "hilight/shadow_refinement.hpp"
#include "hilight/default_view.hpp"
#include "hilight/error.hpp"
#include "hilight/io/image_io.hpp"
#include "hilight/io/gltf.hpp"
#include "hilight/io/lights_file.hpp"
#include "hilight/io/ply.hpp"
#include "progress_display.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace hilight::cli {

namespace fs = std::filesystem;

namespace {

/// -o OUT: by extension; without one, OUT.ply and OUT.png.
std::vector<fs::path> expand_outputs(const std::vector<std::string>& outputs) {
  std::vector<fs::path> out;
  for (const auto& o : outputs) {
    fs::path p(o);
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    if (ext.empty()) {
      out.push_back(fs::path(o + ".ply"));
      out.push_back(fs::path(o + ".png"));
    } else if (ext == ".ply" || ext == ".png" || ext == ".exr") {
      out.push_back(p);
    } else {
      throw InputError(o, "unknown output type '" + ext + "' (use .ply, .png or .exr, or no extension for .ply + .png)");
    }
  }
  return out;
}

} // namespace

int run_render(const std::vector<std::string>& args, Registry& registry) {
  CommandProgress progress;  // first: the summary's time is the whole command's
  CLI::App app("Light a scene with lights: a picture (.png, .exr) and/or the light at every vertex (.ply).\n"
               "  hilight render SCENE --lights lights.json -o out        (out.ply and out.png)",
               "render");
  std::string scene_path, lights_path, camera_text;
  std::vector<std::string> outputs;
  float exposure = 0.f;
  int width = 960, height = 720;
  // Off by default: a refined mesh depends on the lights, so two renders of
  // one scene would no longer add up vertex by vertex (superposition).
  std::string refine_text = "0";
  RendererOptions ropts;
  app.add_option("scene", scene_path, "the scene: any format assimp reads (OBJ, glTF, FBX, IFC, ...)")->required();
  app.add_option("--lights", lights_path, "the lights: hilight's .json, or a .gltf/.glb's lights; default: a glTF scene's own lights");
  app.add_option("-o,--output", outputs, "what to write: OUT.png, OUT.exr, OUT.ply, or OUT for OUT.ply and OUT.png (repeatable)")->required();
  SceneLoadOptions scene_options;
  add_scene_options(app, scene_options, kAdvanced);
  app.add_option("--camera", camera_text, "where the picture is taken from: eye_x,eye_y,eye_z,target_x,target_y,target_z,fov_deg (default: inside the "
                 "largest lit room of a building or closed box, at eye height; else from outside)");
  app.add_option("--width", width, "image width in pixels")->check(CLI::Range(1, 16384))->capture_default_str();
  app.add_option("--height", height, "image height in pixels")->check(CLI::Range(1, 16384))->capture_default_str();
  app.add_option("--refine-shadows", refine_text,
                 "split triangles at shadow and spot edges for .ply outputs, up to this many vertices in all "
                 "(auto: 4x the scene's; 0: off, the default)")
      ->check([](const std::string& text) -> std::string {
        if (text == "auto") return "";
        long long n = -1;
        try {
          size_t used = 0;
          n = std::stoll(text, &used);
          if (used != text.size()) n = -1;
        } catch (const std::exception&) {
        }
        return n >= 0 && n <= 50000000 ? "" : "must be auto or a vertex count from 0 to 50000000";
      })
      ->capture_default_str()
      ->group(kAdvanced);
  std::string units_name = "radiometric";
  app.add_option("--units", units_name,
                 "radiometric: W/sr, and W/(sr m2) in .ply/.exr; photometric: candela and cd/m2 (x683). A lights file that "
                 "states its intensity_unit is read in it")
      ->check(CLI::IsMember({"radiometric", "photometric"}))
      ->capture_default_str();
  app.add_option("--exposure", exposure, "PNG exposure multiplier (default: automatic)")->check(FiniteNonNegative);
  ropts.add_to(app, kAdvanced);
  progress.add_to(app);
  if (auto code = parse_arguments(app, args)) return *code;

  // Everything that can be checked cheaply is checked before any work.
  std::vector<fs::path> paths = expand_outputs(outputs);
  for (const auto& p : paths) check_writable(p);
  if (lights_path.empty() && !is_gltf_path(scene_path))
    throw InputError("render: --lights is required (only a glTF scene carries its own lights)");
  const Units units = parse_units(units_name);
  Lighting lights = read_lights_file(lights_path.empty() ? scene_path : lights_path, units);
  std::optional<Camera> camera;
  if (!camera_text.empty()) camera = Camera::parse(camera_text);
  registry.renderer_unavailable_reason(ropts.name);  // unknown renderer fails here, before loading

  progress.start();
  std::optional<ProgressStage> stage;
  stage.emplace("loading the scene");
  auto scene = std::make_shared<const Scene>(load_scene(scene_path, scene_options));
  stage.reset();
  // Where the scene was moved, and within the renderers' reach (scene_origin.hpp).
  lights = lights_from_file(lights_path.empty() ? scene_path : lights_path, units, *scene);
  if (camera) {
    camera->eye = to_local(camera->eye, scene->frame);
    camera->target = to_local(camera->target, scene->frame);
  }
  const bool any_ply = std::any_of(paths.begin(), paths.end(), [](const fs::path& p) { return p.extension() == ".ply"; });
  const long long refine_budget = refine_text == "auto" ? 4 * (long long)scene->positions.size() : std::stoll(refine_text);
  if (any_ply && refine_budget > (long long)scene->positions.size()) {
    stage.emplace("refining shadow edges");
    // The direct light alone decides where shadow and spot edges run.
    RendererOptions direct = ropts;
    direct.bounces = "0";
    ShadowRefinementSettings refine;
    refine.vertex_budget = size_t(refine_budget);
    const size_t before = scene->positions.size();
    auto refined = refine_shadow_edges(scene, [&](const std::shared_ptr<const Scene>& s) {
      return direct.create(registry, s)->illuminate(SurfacePoints::from_vertices(*s), lights);
    }, refine);
    scene = refined.scene;
    stage.reset();
    std::fprintf(stderr, "refined shadow edges: %zu -> %zu vertices in %d passes\n", before, scene->positions.size(),
                 refined.passes);
  }
  stage.emplace("preparing the renderer");
  auto renderer = ropts.create(registry, scene);
  stage.reset();
  const bool any_picture = std::any_of(paths.begin(), paths.end(), [](const fs::path& p) { return p.extension() != ".ply"; });
  if (any_picture && !camera) {
    // No --camera: inside the largest lit room of a building or box, else from outside (default_view.hpp).
    stage.emplace("choosing the view");
    camera = default_view(*RayScene::shared(scene), lights, float(width) / float(height));
    stage.reset();
  }

  for (const auto& path : paths) {
    stage.emplace("rendering " + path.filename().string());
    if (path.extension() == ".ply") {
      std::vector<Rgb> radiance = renderer->illuminate(SurfacePoints::from_vertices(*scene), lights);
      write_illuminated_ply(path, *scene, radiance_to_units(std::move(radiance), units));
    } else {
      Image image = renderer->render_image(*camera, lights, width, height);
      if (path.extension() == ".exr") image.pixels = radiance_to_units(std::move(image.pixels), units);  // PNG: exposed for display
      write_image(path, image, exposure);
    }
    stage.reset();  // the bar's line is cleared before the line below
    std::fprintf(stderr, "wrote %s\n", path.c_str());
  }
  std::fprintf(stderr, "rendered %zu vertices, %zu lights with %s (bounces %s) in %s\n", scene->positions.size(),
               lights.size(), ropts.name.c_str(), ropts.bounces.c_str(), progress.time_summary().c_str());
  return 0;
}

} // namespace hilight::cli
