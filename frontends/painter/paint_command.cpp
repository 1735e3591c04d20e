// hilight paint SCENE [options]: parses the command line, loads the scene and
// the script (so bad input fails before any window opens), runs the painter.
#include "paint_command.hpp"

#include "cli_arguments.hpp"
#include "criteria_options.hpp"
#include "ifc_spaces.hpp"
#include "solve_options.hpp"

#include "hilight/error.hpp"
#include "hilight/light_cache_store.hpp"
#include "hilight/io/atomic_file.hpp"
#include "hilight/io/criteria_file.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/ray_scene.hpp"
#include "hilight/scene_origin.hpp"
#include "hilight/light_cache.hpp"
#include "hilight/threads.hpp"
#include "painter_app.hpp"

#include <CLI/CLI.hpp>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace hilight::painter {

namespace {

/// "WxH" with both in [64, 8192].
void parse_size(const std::string& text, int& width, int& height) {
  int w = 0, h = 0;
  char x = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &rest) != 3 || (x != 'x' && x != 'X') || w < 64 || h < 64 ||
      w > 8192 || h > 8192)
    throw InputError("paint: --size must be WIDTHxHEIGHT, each 64..8192 (e.g. 1280x800), not '" + text + "'");
  width = w;
  height = h;
}

/// An image path's extension must be one write_image knows.
void check_image_path(const std::string& option, const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".png" && ext != ".exr")
    throw InputError(path.string(), option + ": unknown image type (use .png or .exr)");
  check_writable(path);
}

/// A scene loaded for painting, with what holds it built.
struct OpenedScene {
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const RayScene> rays;  ///< held: the painter's RayScene::shared finds it built
};

/// Loads `o.scene` (unless `loaded` holds it) and settles the command line's
/// rules on it (o's job placement, building note, storeys and named rooms).
OpenedScene open_scene(PaintOptions& o, const PlacementRules& given_rules, const std::optional<Light>& given_luminaire,
                       std::shared_ptr<const Scene> loaded = nullptr) {
  o.started = std::chrono::steady_clock::now();  // --timings: open_to_first_frame counts from here
  OpenedScene opened;
  if (!loaded) loaded = std::make_shared<const Scene>(load_scene(o.scene, o.scene_options));
  opened.scene = loaded;
  // --area-light's size is in the scene's unit (a luminaire file's opening is in metres already).
  o.job.settings.luminaire = given_luminaire;
  if (given_luminaire && is_area(given_luminaire->type) && !given_luminaire->profile) o.job.settings.luminaire->size *= float(loaded->frame.scale);
  // The rules as hilight solve takes them (cli::settle_placement, as the place action does): in the file's
  // coordinates, moved into the scene's frame; rooms and storeys by name (an IFC's IfcSpaces, else free
  // space split at doors), a bad name or a region:K that is not a room refused here; a building's lights
  // hang from the ceiling unless --place says where (not when --lights gives them: their places are the
  // user's); the Placement panel says why, Anywhere lifts it.
  PlacementRules& rules = o.job.settings.placement;
  rules = rules_to_local(given_rules, loaded->frame);
  if (!rules.regions.empty()) opened.rays = RayScene::shared(loaded);
  o.ifc_storeys = cli::ifc_has_storeys(o.scene);
  o.named_rooms.reset();
  const cli::PlacementScene placement_scene{loaded, o.ifc_storeys,
                                            [&](const RayScene& r) {
                                              opened.rays = RayScene::shared(loaded);
                                              o.named_rooms = cli::scene_rooms(o.scene, r);
                                              return *o.named_rooms;
                                            },
                                            nullptr};
  o.building_note = cli::settle_placement(rules, placement_scene, o.lights.empty());
  if (!o.building_note.empty()) std::fprintf(stderr, "hilight: %s\n", o.building_note.c_str());
  return opened;
}

} // namespace

int run_paint(const std::vector<std::string>& args, Registry& registry) {
  CLI::App app("Paint the illumination you want onto a scene; hilight finds the lights", "paint");
  PaintOptions o;
  std::string scene, target, lights, script, screenshot, window_screenshot, record, timings, size = "1280x800";
  // The solve's options as hilight solve takes them (frontends/common/solve_options.hpp),
  // with the painter's defaults: one bounce, and D̄ (reported only after a
  // fine-tune) on fewer points, which costs less of the stroke's latency.
  cli::SolveOptions solve;
  solve.renderer.bounces = "1";
  solve.spec.settings.evaluation_points = 256;
  bool no_auto = false;
  app.add_option("scene", scene, "scene file (any format assimp reads)")->required();
  cli::add_scene_options(app, o.scene_options, "");  // --unit, --max-edge, --max-vertices, as hilight solve's
  app.add_option("--target", target,
                 "target PLY or glTF with vertex colours to start from, or lux criteria (.json, from `hilight target workplane`: "
                 "Solve places --luminaire for them), as `hilight solve --target` reads it");
  app.add_option("--lights", lights, "lights JSON or glTF (KHR_lights_punctual) to start from");
  solve.add_placement(app);
  solve.add_luminaire(app);
  solve.add_units(app);
  solve.add_renderer(app);
  solve.add_plugins(app);
  solve.add_luminaire_tuning(app, "");
  app.add_option("--script", script, "session JSON to replay ({\"actions\": [...]}, docs/painter.md)");
  app.add_option("--screenshot", screenshot, "write the final frame (after the script) as PNG");
  app.add_option("--window-screenshot", window_screenshot, "the final frame with the panels, as PNG (for bug reports)");
  app.add_flag("--exit", o.exit_after_script, "quit after the script and screenshot (headless replay)");
  app.add_option("--record", record, "record this session here (default: $XDG_STATE_HOME/hilight/sessions/)");
  app.add_flag("--no-record", o.no_record, "do not record the session (unless --record is given)");
  app.add_option("--view", o.view, "view to start in (keys 1/2/3 switch)")
      ->check(CLI::IsMember({"result", "target", "difference"}))
      ->capture_default_str();
  app.add_option("--size", size, "window size WIDTHxHEIGHT")->capture_default_str();
  app.add_option("--timings", timings, "write frame and stroke-to-fine-tune times as JSON ('-': stdout)");
  app.add_flag("--bench", o.bench, "after the script: timed orbit, strokes and fine-tunes (use with --timings)");
  app.add_flag("--no-auto-fine-tune", no_auto, "do not fine-tune the lights after each brush stroke");
  cli::add_criteria_design_options(app, o.design, "Lux criteria (a .json target)");
  if (auto code = parse_arguments(app, args)) return *code;
  parse_size(size, o.width, o.height);
  o.scene = scene;
  o.target = target;
  const bool lux_target = cli::is_criteria_target(target);
  if (lux_target) {  // lux criteria: Solve places the luminaire for them
    o.criteria = read_criteria(target);
    o.target.clear();
    check_design_settings(o.design.settings);
  } else {
    cli::refuse_without_criteria(app, cli::criteria_design_option_names());
  }
  o.lights = lights;
  o.script = script;
  o.screenshot = screenshot;
  o.window_screenshot = window_screenshot;
  o.record = record;
  o.timings = timings;
  o.auto_fine_tune = !no_auto;
  // Lux criteria are about lux a meter would read: every bounce, as hilight
  // solve takes them, unless --bounces says otherwise (there is no stroke to
  // keep quick).
  if (lux_target && !app.count("--bounces")) solve.renderer.bounces = "all";
  o.job = solve.to_spec(registry);
  o.job.settings.placement = solve.placement();
  // As hilight solve takes them (solve_options.hpp): every light this luminaire; the files in these units.
  const std::optional<Light> given_luminaire = solve.luminaire();
  if (o.criteria) {
    criteria_luminaire(given_luminaire, target);
    o.auto_fine_tune = false;  // nothing painted to fine-tune to
  }
  o.units = solve.units();
  o.quantity = solve.target_quantity();
  if (o.exit_after_script && script.empty() && !o.bench && screenshot.empty() && window_screenshot.empty())
    throw InputError("paint: --exit without --script, --screenshot or --bench would do nothing");
  set_thread_limit(solve.renderer.threads);

  // Output paths before anything runs: a script's save_* must not have
  // written files when the run then fails on a bad --screenshot.
  if (!o.screenshot.empty()) check_image_path("--screenshot", o.screenshot);
  if (!o.window_screenshot.empty()) check_image_path("--window-screenshot", o.window_screenshot);
  if (!o.timings.empty() && o.timings != "-") check_writable(o.timings);
  if (!o.record.empty()) check_writable(o.record);

  // Input first: a bad renderer, scene or script fails before any window opens.
  if (const std::string why = registry.renderer_unavailable_reason(o.job.renderer); !why.empty())
    throw InputError("paint: renderer '" + o.job.renderer + "' is unavailable: " + why);
  std::optional<Session> session;
  if (!o.script.empty()) session = read_session(o.script);
  // An open_scene (the Files panel, a script) reads the scene, then ends
  // the window; it starts again on the new scene with the rules the command
  // line gave. Rules that do not fit it (a room name it lacks) bring the old
  // scene back, afresh, and say why (in a replay, an error).
  const PlacementRules given_rules = o.job.settings.placement;
  std::filesystem::path previous;
  std::shared_ptr<const Scene> next_loaded;
  for (;;) {
    OpenedScene opened;
    try {
      opened = open_scene(o, given_rules, given_luminaire, std::move(next_loaded));
    } catch (const InputError& e) {
      if (previous.empty() || o.exit_after_script) throw;
      o.open_error = std::string("cannot open the scene: ") + e.what();
      o.scene = previous;
      // The recording goes on from the old scene, without the open that failed.
      if (o.recorded_before && !o.recorded_before->actions.empty() && o.recorded_before->actions.back().type == OpenSceneAction::kType)
        o.recorded_before->actions.pop_back();
      opened = open_scene(o, given_rules, given_luminaire);
    }
    std::optional<PainterApp::NextScene> next;
    int code = 0;
    {
      PainterApp painter(o, registry, opened.scene, std::move(session));
      code = painter.run();
      next = painter.next_scene();
    }
    if (!next) return code;
    previous = o.scene;
    o.scene = next->scene;
    next_loaded = next->loaded;
    o.target.clear();
    o.criteria.reset();  // in the first scene's coordinates
    o.lights.clear();
    session = std::move(next->rest_of_script);
    o.recorded_before = std::move(next->recorded);
    o.record = next->record_path;
    o.open_error.clear();
  }
}

} // namespace hilight::painter
