// hilight target workplane SCENE -o C.json: illuminance criteria to solve
// for instead of paint (issue 14 §3; docs/solve.md, "Illuminance criteria").
#include "cli_common.hpp"
#include "commands.hpp"
#include "hilight/error.hpp"
#include "hilight/io/criteria_file.hpp"
#include "hilight/light_space.hpp"
#include "hilight/regions.hpp"
#include "ifc_spaces.hpp"
#include "hilight/scene_origin.hpp"
#include "progress_display.hpp"
#include "solve_options.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace hilight::cli {

namespace {

/// X0,Y0,Z0,X1,Y1,Z1 → a box (corners in any order).
Bounds parse_box(const std::string& text) {
  std::stringstream ss(text);
  std::string item;
  std::vector<float> v;
  while (std::getline(ss, item, ',')) {
    try {
      size_t used = 0;
      v.push_back(std::stof(item, &used));
      if (used != item.size() || !std::isfinite(v.back())) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw InputError("--box " + text + ": \"" + item + "\" is not a number");
    }
  }
  if (v.size() != 6) throw InputError("--box " + text + ": expected X0,Y0,Z0,X1,Y1,Z1");
  Bounds b;
  b.extend(Vec3(v[0], v[1], v[2]));
  b.extend(Vec3(v[3], v[4], v[5]));
  return b;
}

} // namespace

int run_target(const std::vector<std::string>& args) {
  CommandProgress progress;  // first: its clock is the command's
  CLI::App app("Make lux criteria to solve for: a work plane (EN 12464-1 grid) with the lux and uniformity wanted, "
               "optionally walls and ceiling.\n"
               "  hilight target workplane SCENE --region 3 --lux 500 -o desks.json\n"
               "  hilight solve SCENE --target desks.json --luminaire panel.ies -o lights.json",
               "target");
  std::string kind, scene_path, output, box_text;
  float height = 0.75f, border = 0.5f;
  double lux = 500, u0 = 0.6, walls = 0, ceiling = 0, surface_u0 = 0.1, spacing = 0;
  std::string region;
  bool append = false;
  app.add_option("kind", kind, "workplane: a horizontal calculation grid at --height over the floor")
      ->required()
      ->check(CLI::IsMember({"workplane"}));
  app.add_option("scene", scene_path, "scene file")->required();
  app.add_option("-o,--output", output, "criteria file to write (.json)")->required();
  app.add_option("--height", height, "work plane height over the floor")->check(CLI::Range(0.0, 1e6))->capture_default_str();
  app.add_option("--region", region,
                 "the room: a number as hilight info numbers the regions, or a room's name as it lists them (an IFC's "
                 "IfcSpace or storey: Wohnen; elsewhere room1, ...); default: the whole scene");
  app.add_option("--box", box_text, "or the area as X0,Y0,Z0,X1,Y1,Z1 (the floor is the lowest one inside)");
  app.add_option("--lux", lux, "maintained mean illuminance wanted on the work plane, lx")->check(CLI::Range(0.0, 1e7))->capture_default_str();
  app.add_option("--u0", u0, "uniformity wanted: Emin/Ē")->check(CLI::Range(0.0, 1.0))->capture_default_str();
  app.add_option("--walls", walls, "mean illuminance wanted on the walls above the work plane, lx (0: none)")->check(CLI::Range(0.0, 1e7));
  app.add_option("--ceiling", ceiling, "mean illuminance wanted on the ceiling, lx (0: none)")->check(CLI::Range(0.0, 1e7));
  app.add_option("--surface-u0", surface_u0, "uniformity wanted on walls and ceiling (EN 12464-1: 0.1)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  app.add_option("--spacing", spacing, "grid spacing (default: EN 12464-1's 0.2·5^log10(d), d the area's longer side)")
      ->check(CLI::Range(1e-4, 1e6));
  app.add_option("--border", border, "no work-plane point within this of a wall (EN 12464-1: 0.5)")->check(FiniteNonNegative)->capture_default_str();
  app.add_flag("--append", append, "add these grids to the criteria already in the output file");
  bool zones = false;
  app.add_flag("--zones", zones,
               "with --box (the task area): EN 12464-1's immediate surround (a 0.5 m band, Ē from the standard's table, U0 0.40) "
               "and background (a 3 m band beyond, a third of it, U0 0.10) as grids too");
  SceneLoadOptions scene_options;
  add_scene_options(app, scene_options, kAdvanced);
  progress.add_to(app);
  if (auto code = parse_arguments(app, args)) return *code;
  if (!region.empty() && !box_text.empty()) throw InputError("--region and --box: give one area");
  if (zones && box_text.empty()) throw InputError("--zones needs the task area as --box X0,Y0,Z0,X1,Y1,Z1 (its surround and background lie around it)");
  check_output_type(output, {".json"}, "criteria are written as .json");
  check_writable(output);
  IlluminanceCriteria criteria;
  if (append && std::filesystem::exists(output)) criteria = read_criteria(output);
  const auto same_unit = [&](const std::string& unit) {
    if (criteria.grids.size() && criteria.length_unit != unit)
      throw InputError(output, "its points are in " + criteria.length_unit + ", the scene in " + unit + " (--unit)");
  };

  progress.start();
  std::optional<ProgressStage> stage(std::in_place, "loading the scene");
  const Scene scene = load_scene(scene_path, scene_options);
  same_unit(scene.frame.unit);
  const RayScene rays(scene);
  stage.emplace("finding the rooms");
  const Regions regions(rays);
  stage.emplace("laying out the grids");
  // Positions in the scene's coordinates here, the world's in the file (scene_origin.hpp).
  for (auto& g : criteria.grids)
    for (auto& p : g.points) p = to_local(p, scene.frame);
  GridArea area;
  if (!region.empty()) {  // a number (a region), or a room's name
    PlacementRules named;
    try {
      named.add("region:" + region);
      named.resolve_room_names(scene_rooms(scene_path, named, rays));
      // In a building, a region outside it (or too low to stand in) is no room to light.
      refuse_regions_not_rooms(named, regions, building_kind(scene, ifc_has_storeys(scene_path)));
    } catch (const InputError& e) {
      const std::string what = e.what(), prefix = "--place region:";
      throw InputError("--region " + (what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what));
    }
    if (!named.regions.empty()) area.region = named.regions.front();
    area.rooms = named.rooms;
  }
  if (!box_text.empty()) {
    Bounds b = parse_box(box_text);
    area.box = Bounds{to_local(b.lo, scene.frame), to_local(b.hi, scene.frame)};
  }
  const auto in_scene = [&](const std::string& what) { return scene_path + ": " + what; };
  try {
    CriterionGrid plane = make_work_plane(rays, regions, area, height, lux, u0, spacing, border);
    if (zones) plane.name = "task";
    criteria.grids.push_back(plane);
    if (zones)
      for (auto& band : make_zones(rays, regions, *area.box, plane, height, border)) criteria.grids.push_back(std::move(band));
    if (walls > 0) criteria.grids.push_back(make_surface_grid(rays, regions, area, CriterionGrid::Kind::Walls, walls, surface_u0, plane, spacing));
    if (ceiling > 0)
      criteria.grids.push_back(make_surface_grid(rays, regions, area, CriterionGrid::Kind::Ceiling, ceiling, surface_u0, plane, spacing));
  } catch (const InputError& e) {
    throw InputError(in_scene(e.what()));
  }
  IlluminanceCriteria world = criteria;
  world.length_unit = scene.frame.unit;
  for (auto& g : world.grids)
    for (auto& p : g.points) p = Vec3(to_world(p, scene.frame));
  write_criteria(output, world);
  stage.reset();  // the bar's line is cleared before the lines below
  for (const auto& g : criteria.grids)
    std::fprintf(stderr, "hilight: %s: %zu points, spacing %.2f, Ē ≥ %g lx, U0 ≥ %g\n", g.name.c_str(), g.points.size(), g.spacing,
                 g.lux, g.u0);
  std::fprintf(stderr, "hilight: criteria -> %s (hilight solve %s --target %s --luminaire FILE)\n", output.c_str(),
               scene_path.c_str(), output.c_str());
  return 0;
}

} // namespace hilight::cli
