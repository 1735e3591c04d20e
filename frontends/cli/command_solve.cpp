// hilight solve SCENE --target T.ply -o LIGHTS.json: the inverse solve.
#include "cli_common.hpp"
#include "solve_options.hpp"
#include "command_solve_criteria.hpp"
#include "ifc_spaces.hpp"
#include "commands.hpp"
#include "hilight/error.hpp"
#include "hilight/io/atomic_file.hpp"
#include "hilight/io/lights_json.hpp"
#include "hilight/io/gltf.hpp"
#include "hilight/io/html_report.hpp"
#include "hilight/io/lights_file.hpp"
#include "hilight/light_cache_store.hpp"
#include "hilight/io/photometry_io.hpp"
#include "hilight/units.hpp"
#include "hilight/scene_origin.hpp"
#include "hilight/solve/fit_notes.hpp"
#include "hilight/solve/judge.hpp"
#include "hilight/solve/solve_session.hpp"
#include "hilight/threads.hpp"
#include "progress_display.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <unistd.h>

namespace hilight::cli {

namespace {

/// D̄ above which the result is called a poor fit (the paper's solves end
/// below 1.5%): the Judge's, so the warning and the solve's diagnosis agree.
constexpr double kPoorFit = Judge::kPoorFitDbar;

nlohmann::json report_json(const SolveReport& r, const std::string& renderer, const std::string& optimizer, const std::string& sampler,
                           const std::string& mode) {
  nlohmann::json cuts = nlohmann::json::array();
  for (const auto& c : r.cuts) {
    nlohmann::json j = {{"lights", c.lights}, {"dbar_initial", c.dbar_initial}, {"refined", c.refined}};
    if (c.refined) {
      j["dbar_refined"] = c.dbar_refined;
      j["lights_refined"] = c.refined_lights.size();  // weak lights pruned after refinement
    }
    cuts.push_back(j);
  }
  // The solve's stages in the order they ran: what each cost and did.
  nlohmann::json stages = nlohmann::json::array();
  for (const auto& st : r.stages) {
    nlohmann::json j = {{"name", st.name},       {"seconds", st.seconds}, {"dbar_before", st.dbar_before},
                        {"dbar_after", st.dbar_after}, {"dbar_over", st.target ? "target points" : "samples"},
                        {"kept", st.kept}};
    if (!st.skipped.empty()) j["skipped"] = st.skipped;
    stages.push_back(j);
  }
  return {{"mode", mode},
          {"poor_fit", r.dbar > kPoorFit},
          {"lights", r.chosen},
          {"dbar", r.dbar},
          {"dbar_points", r.dbar_points},
          {"dbar_measured", r.dbar_points == r.target_points ? "every target point, by the reference renderer (as hilight render)"
                                                             : "evenly spaced target points, by the reference renderer"},
          {"dbar_samples", r.dbar_samples},
          {"residual_samples", r.residual_samples},
          {"cuts", cuts},
          {"improvement_ratios", r.improvement},
          {"seconds", r.seconds},
          {"stages", stages},
          {"samples", r.samples},
          {"target_points", r.target_points},
          {"seed_lights", r.seed_lights},
          {"seed_lights_tried", r.seeds_tried},
          {"light_cache", r.cache_state},
          {"open_space", r.open_space},
          {"unreachable_share", r.unreachable},
          {"dbar_inside_bounds", r.dbar_closed >= 0 ? nlohmann::json(r.dbar_closed) : nlohmann::json(nullptr)},
          {"renderer", renderer},
          {"optimizer", optimizer},
          {"sampler", sampler}};
}

} // namespace


int run_solve(const std::vector<std::string>& args, Registry& registry) {
  CommandProgress progress;  // first: the summary's time is the whole command's
  CLI::App app("Find the lights that produce a target: how many, where, how bright.\n"
               "  hilight solve SCENE --target painted.ply -o lights.json\n"
               "  hilight solve SCENE --target desks.json --luminaire panel.ies -o lights.json   (lux criteria)",
               "solve");
  app.footer(exit_codes_help(true));
  std::string scene_path, target_path, output, report_path, initial_path, mode = "solve", hints_path;
  SolveOptions solve;  // the options hilight paint shares (frontends/common/solve_options.hpp)
  bool quiet = false;
  double max_dbar = -1;
  SolveSettings& s = solve.spec.settings;
  RendererOptions& ropts = solve.renderer;
  CriteriaSolve criteria;
  std::string mount;
  float mount_offset = -1.f;
  bool vertex_colours = false;
  std::string html_path;
  const std::string& units_name = solve.units_name;
  SceneLoadOptions scene_options;
  // What a user needs, in the order they need it; the rest under kSolveAdvanced.
  app.add_option("scene", scene_path, "the scene: any format assimp reads (OBJ, glTF, FBX, IFC, ...)")->required();
  app.add_option("--target", target_path,
                 "the light wanted: painted colours (.ply, or .gltf/.glb with vertex colours), or lux criteria "
                 "(.json from hilight target workplane; needs --luminaire)")
      ->required();
  app.add_option("-o,--output", output, "where to write the lights: .json (hilight's lights file) or .gltf/.glb (scene and lights, for Blender)")
      ->required();
  app.add_option("--lights", s.fixed_count, "how many lights (default: the solve decides)")->check(CLI::Range(1, 10000));
  solve.add_placement(app);
  solve.add_luminaire(app);  // --luminaire, --area-light (hilight paint takes them too)
  app.add_option("--mount", mount, "ceiling: every light hangs --offset below the ceiling (the same as --place ceiling:OFFSET)")
      ->check(CLI::IsMember({"ceiling"}));
  app.add_option("--offset", mount_offset, "with --mount ceiling: how far below the ceiling")->check(CLI::Range(1e-6, 1e6));
  solve.add_units(app);  // --units, --target-quantity
  app.add_option("--report-html", html_path,
                 "write a page to look at: target, result and difference from three views, a plan of each storey, the lights, timings");
  app.add_option("--report", report_path, "write the figures as JSON (D̄, light count, flux, timings)");
  app.add_option("--mode", mode, "solve; fine-tune (move and dim the lights of --initial); add (lights for what --initial misses)")
      ->check(CLI::IsMember({"solve", "fine-tune", "add"}))
      ->capture_default_str();
  app.add_option("--initial", initial_path, "the lights to start from, with --mode fine-tune or add");
  app.add_option("--max-dbar", max_dbar, "fail (exit 3, lights still written) when the fit's error D̄ is above this, e.g. 0.015")
      ->check(CLI::Range(0.0, 1e9));
  add_scene_options(app, scene_options, kSolveAdvanced);
  solve.add_renderer(app, kSolveAdvanced);
  app.add_flag("-q,--quiet", quiet, "no progress or summary on stderr (warnings stay)");
  progress.add_to(app);

  // Advanced: the paper's parameters, the plugins and their tuning.
  app.add_option("--spot-hints", hints_path, "lights JSON of spotlights wanted (position, direction, cutoff; intensity ignored)")->group(kSolveAdvanced);
  solve.add_luminaire_tuning(app, kSolveAdvanced);
  app.add_flag("--vertex-colours", vertex_colours, "with a .gltf/.glb output: the result as COLOR_0 and the target as COLOR_1 (alpha: weight) per vertex")
      ->group(kSolveAdvanced);
  app.add_option("--energy-tolerance", criteria.design.settings.energy_tolerance,
                 "with criteria: the fewest luminaires whose total flux is within this share of the least possible")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str()
      ->group(kSolveAdvanced);
  app.add_option("--candidate-spacing", criteria.design.settings.candidate_spacing,
                 "with criteria: the lattice of places tried (default: a third of the finest grid's spacing)")
      ->check(CLI::Range(1e-4, 1e6))
      ->group(kSolveAdvanced);
  add_criteria_options(app, criteria, "Lux criteria (a .json target)");
  solve.add_paper_parameters(app, kSolveAdvanced);
  solve.add_plugins(app, kSolveAdvanced);
  if (auto code = parse_arguments(app, args)) return *code;

  s.placement = solve.placement();
  if (mount_offset >= 0.f && mount.empty()) throw InputError("--offset needs --mount ceiling");
  if (!mount.empty()) s.placement.add(mount_offset >= 0.f ? "ceiling:" + std::to_string(mount_offset) : "ceiling");
  if (mode != "solve" && initial_path.empty()) throw InputError("--mode " + mode + " needs --initial LIGHTS.json");
  if (mode == "solve" && !initial_path.empty()) throw InputError("--initial needs --mode fine-tune or add");
  check_output_type(output, {".json", ".gltf", ".glb", ".ifc"},
                    "use .json for hilight's lights file, .gltf or .glb for the scene and its lights, .ifc for luminaires "
                    "found for criteria");
  check_writable(output);
  if (is_ifc_path(output) && !is_criteria_target(target_path))
    throw InputError("-o " + output + ": IFC output is for a luminaire result (a solve for illuminance criteria, a .json target)");
  if (!report_path.empty()) check_writable(report_path);
  if (!html_path.empty()) check_writable(html_path);
  if (vertex_colours && !is_gltf_path(output)) throw InputError("--vertex-colours needs a .gltf or .glb output, not " + output);
  s.luminaire = solve.luminaire();  // --luminaire (sized, turned) or --area-light, checked
  check_criteria_options(app, is_criteria_target(target_path));
  if (is_criteria_target(target_path)) {
    if (mode != "solve") throw InputError("--mode " + mode + " works on painted targets, not on criteria (" + target_path + ")");
    progress.start(quiet);
    criteria.scene_path = scene_path;
    criteria.target_path = target_path;
    criteria.output = output;
    criteria.report_path = report_path;
    criteria.html_path = html_path;
    criteria.units_name = units_name;
    criteria.scene_options = scene_options;
    criteria.quiet = quiet;
    criteria.luminaire = s.luminaire;
    criteria.placement = s.placement;
    criteria.design.settings.fixed_count = s.fixed_count;
    criteria.renderer = ropts;
    return solve_for_criteria(criteria, registry);
  }
  const Units units = solve.units();
  const TargetQuantity quantity = solve.target_quantity();
  // Read now to fail before the scene loads, and again once its frame is known.
  auto read_hints = [&](const SceneFrame* frame) {
    Lighting hints = read_lights_file(hints_path, units, frame);
    for (auto& h : hints) {
      if (h.type != LightType::Spot) throw InputError(hints_path, "spot hints must be spotlights");
      h.intensity = Rgb(1.f);
    }
    return hints;
  };
  Lighting initial = initial_path.empty() ? Lighting{} : read_lights_file(initial_path, units);
  if (!hints_path.empty()) s.spot_hints = read_hints(nullptr);
  SolveSession::check_names(registry, solve.to_spec(registry));  // unknown plugins fail before the scene loads

  progress.start(quiet);
  set_thread_limit(ropts.threads);
  std::optional<ProgressStage> stage(std::in_place, "loading the scene");
  auto scene = std::make_shared<const Scene>(load_scene(scene_path, scene_options));
  auto rays = RayScene::shared(scene);
  // Positions read in the world's coordinates, solved in the scene's (scene_origin.hpp).
  if (!initial_path.empty()) initial = lights_from_file(initial_path, units, *scene);
  if (!hints_path.empty()) s.spot_hints = read_hints(&scene->frame);
  s.placement = rules_to_local(std::move(s.placement), scene->frame);
  // Rooms by name (an IFC's IfcSpaces), no region that is not a room, and a building's lights on its
  // ceiling unless told otherwise: the painter's path too (settle_placement).
  const PlacementScene placement_scene{scene, ifc_has_storeys(scene_path),
                                       [&](const RayScene& r) { return scene_rooms(scene_path, r); }, nullptr};
  const std::string building_note = settle_placement(s.placement, placement_scene, mode == "solve" && s.spot_hints.empty());
  // --area-light's size is in the scene's unit (a file's opening is in metres already).
  if (s.luminaire && is_area(s.luminaire->type) && !s.luminaire->profile) s.luminaire->size *= float(scene->frame.scale);
  stage.emplace("reading the target");
  Target target = read_target(target_path, *scene, *rays);
  target_from_units(target, units, quantity);
  // Settling renders the direct light hundreds of times: milliseconds each
  // where the renderer says so (Embree), a POV-Ray run or a GPU submission
  // each with the others. Direct light needs none (the polish's slopes
  // through it are clean: the lamps to 10⁻⁵ of the size after a turn).
  s.settle_fine_tune = ropts.bounce_count() != 0 && registry.renderer_traits(ropts.name).cheap_direct;
  const SolveSpec spec = solve.to_spec(registry);

  stage.emplace("preparing the renderers");
  SolveSession session(registry, spec, scene, rays);
  stage.reset();
  ropts.note_bounces(registry);
  // The Solver's stages name one part of "solving"; it says them from
  // whichever thread reaches them (cuts are refined two at a time).
  std::optional<ProgressStage> solver_stage;
  const auto solver_owned = session.make_solver([&](const std::string& name) {
    if (solver_stage) solver_stage->rename(name);
  });
  Solver& solver = *solver_owned;
  SolveReport report;
  Lighting lights;
  try {
    stage.emplace(mode == "solve" ? "solving" : mode == "add" ? "adding lights" : "fine-tuning");
    solver_stage.emplace("");
    lights = mode == "fine-tune" ? solver.fine_tune(target, initial, report)
             : mode == "add"     ? solver.add_lights(target, initial, report)
                                 : solver.solve(target, report);
    solver_stage.reset();
    stage.reset();
  } catch (const InputError& e) {
    // The solver names the lights ("lights to fine-tune: light 0 ..."); the user needs the file.
    const std::string what = e.what();
    if (what.rfind("lights to ", 0) == 0) throw InputError(initial_path, what);
    if (what.rfind("spot hints", 0) == 0) throw InputError(hints_path, what);
    throw;
  }
  stage.emplace("writing " + std::filesystem::path(output).filename().string());
  if (is_gltf_path(output)) {
    GltfExport gltf;
    gltf.scene = scene.get();
    gltf.lights = lights;
    gltf.figures = {{"lights", double(report.chosen)}, {"dbar", report.dbar}, {"dbar_points", double(report.dbar_points)}};
    if (vertex_colours) {
      gltf.result = session.reference().illuminate(SurfacePoints::from_vertices(*scene), lights);
      target_per_vertex(target, scene->positions.size(), gltf.target, gltf.target_weight);
    }
    write_gltf(output, gltf);
  } else {
    write_lights_file(output, lights, units, scene->frame);
  }
  if (!report_path.empty()) {
    nlohmann::json j = report_json(report, spec.renderer, spec.optimizer, spec.sampler, mode);
    // Which light the fit counted: lux from one bounce and from every one differ by up to 2x.
    const int bounces = bounces_property(Properties::from_assignments(spec.renderer_settings), 1, "--bounces");
    j["bounces"] = bounces_text(bounces);
    j["bounce_model"] = bounce_model(bounces);
    // Each light's luminous flux (lm) and the total: what a lighting designer budgets.
    nlohmann::json flux = nlohmann::json::array();
    double total = 0;
    for (const auto& l : lights) {
      flux.push_back(luminous_flux(l));
      total += flux.back().get<double>();
    }
    j["luminous_flux_lm"] = flux;
    j["total_luminous_flux_lm"] = total;
    if (s.luminaire && s.luminaire->profile) {  // each light's share of the luminaire's rated output, and the power it draws
      nlohmann::json dimming = nlohmann::json::array();
      double watts = 0;
      for (const auto& l : lights) {
        const double d = luminaire_dimming(l);
        dimming.push_back(d);
        watts += d * l.profile->input_watts;
      }
      j["luminaire"] = s.luminaire->profile_path;
      j["dimming"] = dimming;
      j["electrical_power_w"] = s.luminaire->profile->input_watts > 0 ? nlohmann::json(watts) : nlohmann::json(nullptr);
    }
    j["units"] = units_name;
    if (s.fixed_count > 0) j["lights_asked"] = s.fixed_count;  // "lights" (report.chosen) may be fewer
    std::string text = j.dump(2) + "\n";
    write_atomically(report_path, text);
  }
  if (!html_path.empty()) {
    stage.emplace("writing the HTML report");
    HtmlReport page;
    page.scene = scene.get();
    page.rays = rays.get();
    page.title = scene_path + " — target " + target_path;
    target_per_vertex(target, scene->positions.size(), page.target, page.target_weight);
    page.result = session.reference().illuminate(SurfacePoints::from_vertices(*scene), lights);
    page.lights = lights;
    page.report = report;
    page.units = units_name;
    write_html_report(html_path, page);
  }
  stage.reset();
  progress.stop();  // the bar's line is cleared before the summary
  if (!quiet) {
    const std::string over = report.dbar_points == report.target_points
                                 ? "all " + std::to_string(report.target_points) + " target points"
                                 : std::to_string(report.dbar_points) + " of " + std::to_string(report.target_points) + " target points";
    const auto spots = std::count_if(lights.begin(), lights.end(), [](const Light& l) { return l.type == LightType::Spot; });
    const std::string of_them = s.luminaire && s.luminaire->profile ? " (" + std::filesystem::path(s.luminaire->profile_path).filename().string() + ")"
                                : s.luminaire ? std::string(" (") + to_string(s.luminaire->type) + ")"
                                : spots     ? " (" + std::to_string(spots) + (spots == 1 ? " spot)" : " spots)")
                                            : "";
    std::fprintf(stderr, "hilight: %zu light%s%s, D̄ %.2f%% over %s (%zu samples), %s -> %s\n", report.chosen,
                 report.chosen == 1 ? "" : "s", of_them.c_str(), 100.0 * report.dbar, over.c_str(), report.samples,
                 progress.time_summary().c_str(), output.c_str());
    if (!building_note.empty()) std::fprintf(stderr, "hilight: %s\n", building_note.c_str());
    if (report.open_space)
      std::fprintf(stderr, "hilight: lit from outside: lights beyond the scene's bounds (inside them D̄ was %.1f%%)\n",
                   100.0 * report.dbar_closed);
  }
  if (s.luminaire)
    for (size_t j = 0; j < lights.size(); ++j)
      if (lights[j].profile && luminaire_dimming(lights[j]) > 1.0 + 1e-6)
        std::fprintf(stderr, "hilight: warning: light %zu needs %.0f%% of the luminaire's rated output (more luminaires, or a brighter one)\n", j,
                     100.0 * luminaire_dimming(lights[j]));
  // A count not reached, a poor fit and why, whatever --quiet says (no silent
  // failure; --max-dbar makes it an error after the files are written). The
  // painter's Solve panel says the same (fit_notes.hpp).
  for (const FitNote& note : fit_notes(report, {s.fixed_count, !building_note.empty()}))
    std::fprintf(stderr, "hilight: %s%s\n", note.warning ? "warning: " : "", note.text.c_str());
  if (max_dbar >= 0 && report.dbar > max_dbar) {
    std::fprintf(stderr, "hilight: %s: D̄ %.2f%% is above --max-dbar %.2f%% (lights written to %s)\n", target_path.c_str(),
                 100.0 * report.dbar, 100.0 * max_dbar, output.c_str());
    return 3;
  }
  return 0;
}

} // namespace hilight::cli
