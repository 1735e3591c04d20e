// hilight info SCENE: size, bounds and tessellation of a scene.
#include "cli_common.hpp"
#include "commands.hpp"
#include "ifc_spaces.hpp"
#include "solve_options.hpp"
#include "hilight/error.hpp"
#include "hilight/light_bounds.hpp"
#include "hilight/regions.hpp"
#include "hilight/room_split.hpp"
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
  // The rooms an IFC names (IfcSpace) and whether the scene is a building (the ceiling default).
  IfcRooms ifc;
  try {
    ifc = read_ifc_rooms(scene_path, scene);
  } catch (const InputError& e) {  // assimp read it: the rest of the summary stands
    std::fprintf(stderr, "hilight: warning: no room names: %s\n", e.what());
  }
  const std::string building = building_kind(scene, ifc_has_storeys(scene_path));
  const auto room_box = [&](const auto& r) {  // a NamedRoom or a RoomSplit::Room
    const glm::dvec3 a = world(r.box.lo), c = world(r.box.hi);
    return nlohmann::json{{"min", {a.x, a.y, a.z}}, {"max", {c.x, c.y, c.z}}};
  };
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
                        {"max_edge", scene.max_edge},
                        {"building", building},
                        {"storeys", ifc.storeys}};
    nlohmann::json rooms = nlohmann::json::array();
    for (const auto& r : ifc.rooms)
      rooms.push_back({{"name", r.name}, {"number", r.number}, {"storey", r.storey}, {"box", room_box(r)}});
    if (ifc.rooms.empty()) {  // no names in the file: free space split at doors, as the text lists them
      const RayScene rays(scene);
      const RoomSplit split(rays);  // named: list() refers into it
      for (const auto& r : split.list())
        rooms.push_back({{"name", "room" + std::to_string(r.number)}, {"box", room_box(r)}, {"volume", r.volume}});
    }
    j["rooms"] = rooms;
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
  if (!building.empty()) std::printf("building   %s: lights on the ceiling by default (--place anywhere lifts it)\n", building.c_str());
  if (!ifc.storeys.empty()) {
    std::printf("storeys    %zu:", ifc.storeys.size());
    for (const auto& s : ifc.storeys) std::printf(" '%s'", s.c_str());
    std::printf("\n");
  }
  if (!ifc.rooms.empty()) {
    std::printf("rooms      %zu named (IfcSpace; --place region:NAME, or a storey's name for all its rooms)\n", ifc.rooms.size());
    // Padded by characters, not bytes ('Küche').
    const auto padded = [](const std::string& text, size_t width) {
      const size_t chars = size_t(std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
      return text + std::string(chars < width ? width - chars : 0, ' ');
    };
    for (const auto& r : ifc.rooms) {
      std::printf("  %s %s %s ", padded(r.name, 14).c_str(), padded(r.number, 4).c_str(), padded(r.storey, 18).c_str());
      print_box("", r.box, "\n");
    }
  }
  // The connected parts of free space: what --place region:K / not-region:K name.
  stage.emplace("finding the rooms");
  const RayScene rays(scene);
  const Regions regions(rays);
  stage.reset();
  if (ifc.rooms.empty()) {  // no names in the file: free space split at doors
    stage.emplace("splitting the rooms at doors");
    const RoomSplit split(rays);
    stage.reset();
    std::printf("rooms      %zu (free space split at doors; --place region:room1 ...)\n", split.list().size());
    for (const auto& r : split.list()) {
      if (r.number > 40) {
        std::printf("  ... %zu more\n", split.list().size() - 40);
        break;
      }
      std::printf("  room%-3d ", r.number);
      print_box("", r.box, "");
      std::printf(", volume %g\n", r.volume);
    }
  }
  std::printf("regions    %zu (connected free space; --place region:K, not-region:K)\n", regions.list().size());
  for (const auto& r : regions.list()) {
    if (r.id >= 20) {
      std::printf("  ... %zu more\n", regions.list().size() - 20);
      break;
    }
    std::printf("  %-3d ", r.id);
    print_box("", r.box, "");
    std::printf(", volume %g%s\n", r.volume,
                building.empty() || offered_as_room(r) ? ""
                : r.at_border                          ? " (outside the building: not a room)"
                                                       : " (too low to stand in: not a room)");
  }
  return 0;
}

} // namespace hilight::cli
