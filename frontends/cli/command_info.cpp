// hilight info SCENE: size, bounds and tessellation of a scene.
#include "cli_common.hpp"
#include "commands.hpp"
#include "hilight/light_bounds.hpp"
#include "hilight/regions.hpp"
#include "hilight/scene_origin.hpp"
#include "progress_display.hpp"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace hilight::cli {

int run_info(const std::vector<std::string>& args) {
  CommandProgress progress;
  CLI::App app("Print a scene's size, bounds, tessellation and rooms (the regions --place region:K names)", "info");
  std::string scene_path;
  bool as_json = false;
  app.add_option("scene", scene_path, "scene file (any format assimp reads)")->required();
  SceneLoadOptions scene_options;
  add_scene_options(app, scene_options, kAdvanced);
  app.add_flag("--json", as_json, "print JSON instead of text");
  progress.add_to(app);
  if (auto code = parse_arguments(app, args)) return *code;
  progress.start();

  std::optional<ProgressStage> stage(std::in_place, "loading the scene");
  Scene scene = load_scene(scene_path, scene_options);
  stage.reset();  // the bar's line is cleared before the lines below
  // Positions said in the world's coordinates (the scene may have been moved home: scene_origin.hpp).
  const auto world = [&](const Vec3& v) { return to_world(v, scene.frame); };
  const Bounds& b = scene.bounds;
  const glm::dvec3 lo = world(b.lo), hi = world(b.hi), o = scene.frame.origin;
  const double metres = double(scene.diagonal());  // hilight computes in metres
  if (as_json) {
    nlohmann::json j = {{"file", scene_path},
                        {"triangles_input", scene.input_triangle_count},
                        {"vertices_input", scene.input_vertex_count},
                        {"triangles", scene.triangles.size()},
                        {"vertices", scene.positions.size()},
                        {"materials", scene.materials.size()},
                        {"bounds_min", {lo.x, lo.y, lo.z}},
                        {"bounds_max", {hi.x, hi.y, hi.z}},
                        {"origin", {o.x, o.y, o.z}},
                        {"unit", scene.frame.unit},
                        {"size_m", metres},
                        {"diagonal", scene.diagonal()},
                        {"max_edge", scene.max_edge}};
    std::printf("%s\n", j.dump(2).c_str());
    return 0;
  }
  std::printf("scene      %s\n", scene_path.c_str());
  std::printf("triangles  %zu (input %zu)\n", scene.triangles.size(), scene.input_triangle_count);
  std::printf("vertices   %zu (input %zu)\n", scene.positions.size(), scene.input_vertex_count);
  std::printf("materials  %zu\n", scene.materials.size());
  std::printf("bounds     [%.9g, %.9g, %.9g] .. [%.9g, %.9g, %.9g]\n", lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
  std::printf("unit       %s (%g m); %.4g m across\n", scene.frame.unit.c_str(), scene.frame.scale, metres);
  if (o != glm::dvec3(0.0))
    std::printf("origin     [%.9g, %.9g, %.9g] (far from the world's origin: computed relative to this)\n", o.x, o.y, o.z);
  std::printf("diagonal   %g\n", scene.diagonal());
  const auto print_box = [&](const char* label, const Bounds& box, const char* tail) {
    const glm::dvec3 a = world(box.lo), c = world(box.hi);
    std::printf("%s[%.9g, %.9g, %.9g] .. [%.9g, %.9g, %.9g]%s", label, a.x, a.y, a.z, c.x, c.y, c.z, tail);
  };
  print_box("lights in  ", scene.light_bounds(), "\n");
  const auto open = side_openness(scene);
  std::printf("open sides -x %.2f +x %.2f -y %.2f +y %.2f -z %.2f +z %.2f (lights may go beyond a side from %.2f)\n", open[0], open[1], open[2],
              open[3], open[4], open[5], kOpenSide);
  // Where a solve looks when the lights inside explain the target poorly
  // (docs/solve.md, "Lit from outside"): only beyond open sides.
  if (std::none_of(open.begin(), open.end(), [](float side) { return side >= kOpenSide; }))
    std::printf("open space none (closed on every side: a target is never solved as lit from outside)\n");
  else print_box("open space ", open_light_bounds(scene), " (where a target lit from outside is solved)\n");
  std::printf("max edge   %g\n", scene.max_edge);
  // The connected parts of free space: what --place region:K / not-region:K name.
  stage.emplace("finding the rooms");
  const RayScene rays(scene);
  const Regions regions(rays);
  stage.reset();
  std::printf("regions    %zu (connected free space; --place region:K, not-region:K)\n", regions.list().size());
  for (const auto& r : regions.list()) {
    if (r.id >= 20) {
      std::printf("  ... %zu more\n", regions.list().size() - 20);
      break;
    }
    std::printf("  %-3d ", r.id);
    print_box("", r.box, "");
    std::printf(", volume %g\n", r.volume);
  }
  return 0;
}

} // namespace hilight::cli
