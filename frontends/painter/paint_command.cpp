// hilight paint SCENE [options]: parses the command line, loads the scene and
// the script (so bad input fails before any window opens), runs the painter.
#include "paint_command.hpp"

#include "cli_arguments.hpp"

#include "hilight/error.hpp"
#include "hilight/light_cache_store.hpp"
#include "hilight/io/atomic_file.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/light_cache.hpp"
#include "hilight/threads.hpp"
#include "painter_app.hpp"

#include <CLI/CLI.hpp>
#include <cctype>
#include <cmath>

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

} // namespace

int run_paint(const std::vector<std::string>& args, Registry& registry) {
  CLI::App app("Paint the illumination you want onto a scene; hilight finds the lights", "paint");
  PaintOptions o;
  std::string scene, target, lights, script, screenshot, window_screenshot, record, timings, size = "1280x800", cache_dir;
  int threads = 0, bounce_samples = 0;
  std::string bounces = "1";
  bool no_auto = false, no_cache = false;
  app.add_option("scene", scene, "scene file (any format assimp reads)")->required();
  app.add_option("--max-edge", o.max_edge, "longest edge after tessellation (default: diagonal/40)")->check(CLI::Range(0.f, 1e30f));
  app.add_option("--target", target, "target PLY or glTF with vertex colours to start from (as `hilight solve --target` reads)");
  app.add_option("--lights", lights, "lights JSON or glTF (KHR_lights_punctual) to start from");
  app.add_option("--renderer", o.job.renderer, "renderer plugin for the view and the solve")->capture_default_str();
  app.add_option("--bounces", bounces, "diffuse bounces: all (every bounce), 0 (direct light only), 1, or a count up to 1000")
      ->check(bounce_count_validator())
      ->capture_default_str();
  app.add_option("--bounce-samples", bounce_samples, "gather rays per point for the bounce (renderer default if 0)")
      ->check(CLI::Range(0, 4096));
  app.add_option("--set", o.job.renderer_settings, "renderer setting key=value (repeatable)");
  app.add_option("--optimizer", o.job.optimizer, "refinement plugin (varpro, nelder-mead)")->capture_default_str();
  app.add_option("--opt", o.job.optimizer_settings, "optimizer setting key=value (repeatable)");
  app.add_option("--sampler", o.job.sampler, "surface sampling plugin")->capture_default_str();
  app.add_option("--samples", o.job.settings.samples, "surface samples used by the solve (default: target points / 14, within 3000-10000)")
      ->check(CLI::Range(10, 10000000));
  // D̄ is only reported after a fine-tune; on fewer points it costs less of the stroke's latency.
  o.job.settings.evaluation_points = 256;
  app.add_option("--evaluation-points", o.job.settings.evaluation_points, "target points D-bar is reported on (0: all)")
      ->check(CLI::Range(0, 100000000))
      ->capture_default_str();
  std::vector<std::string> place_rules;
  app.add_option("--place", place_rules,
                 "where lights may stand (repeatable): ceiling[:OFFSET], height:MIN:MAX, box:X0,Y0,Z0,X1,Y1,Z1, "
                 "exclude:X0,Y0,Z0,X1,Y1,Z1 (as hilight solve)");
  app.add_option("--cache-dir", cache_dir, "where the light cache is kept (default: ~/.cache/hilight)");
  app.add_option("--cache", o.job.cache, "light cache plugin (grid, adaptive) or none: every response from the renderer")
      ->capture_default_str();
  app.add_option("--cache-setting", o.job.cache_settings, "light cache setting key=value (repeatable, as hilight solve)");
  app.add_option_function<int>("--cache-cells", [&](int cells) { o.job.cache_settings.push_back("cells=" + std::to_string(cells)); },
                               "the same as --cache-setting cells=N");
  app.add_flag("--no-cache", no_cache, "the same as --cache none");
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
  app.add_option("--threads", threads, "worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
  if (auto code = parse_arguments(app, args)) return *code;
  if (!std::isfinite(o.max_edge) || o.max_edge < 0.f) throw InputError("paint: --max-edge must be a finite number >= 0");
  parse_size(size, o.width, o.height);
  o.scene = scene;
  o.target = target;
  o.lights = lights;
  o.script = script;
  o.screenshot = screenshot;
  o.window_screenshot = window_screenshot;
  o.record = record;
  o.timings = timings;
  o.auto_fine_tune = !no_auto;
  o.job.renderer_settings.push_back("bounces=" + bounces);
  if (bounce_samples > 0) o.job.renderer_settings.push_back("bounce_samples=" + std::to_string(bounce_samples));
  for (const auto& rule : place_rules) o.job.settings.placement.add(rule);
  if (no_cache) o.job.cache = PluginDefaults::no_cache;
  o.job.settings.cache_dir = o.job.cache == PluginDefaults::no_cache ? std::filesystem::path() : cache_dir.empty() ? default_cache_dir() : std::filesystem::path(cache_dir);
  o.job.settings.cache_cap_bytes = default_cache_cap_bytes();
  if (o.exit_after_script && script.empty() && !o.bench && screenshot.empty() && window_screenshot.empty())
    throw InputError("paint: --exit without --script, --screenshot or --bench would do nothing");
  set_thread_limit(threads);

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
  o.started = std::chrono::steady_clock::now();  // --timings: open_to_first_frame counts from here
  auto loaded = std::make_shared<const Scene>(load_scene(o.scene, {o.max_edge}));
  PainterApp painter(o, registry, loaded, std::move(session));
  return painter.run();
}

} // namespace hilight::painter
