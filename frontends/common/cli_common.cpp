#include "cli_common.hpp"
#include "hilight/solve/solve_renderers.hpp"

#include "hilight/error.hpp"
#include "hilight/threads.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace hilight::cli {

namespace fs = std::filesystem;

const CLI::Validator FiniteNonNegative(
    [](std::string& text) -> std::string {
      char* end = nullptr;
      double v = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || !std::isfinite(v) || v < 0) return "'" + text + "' is not a finite number >= 0";
      return {};
    },
    "NUMBER >= 0");

const CLI::Validator BounceCount = bounce_count_validator();

void RendererOptions::add_to(CLI::App& app, const std::string& tuning_group) {
  app.add_option("--bounces", bounces,
                 "how many times light bounces off surfaces: all (as in reality), 0 (direct light only), "
                 "1 (the first bounce), or a count up to 1000")
      ->check(BounceCount)
      ->capture_default_str();
  app.add_option("--threads", threads, "worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
  app.add_option("--renderer", name, "renderer plugin: embree, povray (the reference), ism-vulkan (hilight plugins lists them)")
      ->capture_default_str();
  auto* samples = app.add_option("--bounce-samples", bounce_samples, "gather rays per point for the bounce (renderer default if 0)")
                      ->check(CLI::Range(0, 4096));
  auto* set = app.add_option("--set", settings, "renderer setting key=value (repeatable)");
  if (!tuning_group.empty())
    for (CLI::Option* o : {samples, set}) o->group(tuning_group);
}

std::string RendererOptions::bounces_for(const Registry& registry) const {
  const int asked = bounce_count(), most = registry.renderer_traits(name).max_bounces;
  if (most == kAllBounces || (asked != kAllBounces && asked <= most)) return bounces;
  if (asked != kAllBounces)
    throw InputError("--bounces " + bounces + ": renderer " + name + " carries at most " + std::to_string(most) + " bounce(s)");
  return std::to_string(most);
}

void RendererOptions::note_bounces(const Registry& registry) const {
  if (bounces_for(registry) == bounces) return;
  std::fprintf(stderr, "note: renderer %s carries at most %s bounce(s); the light of later bounces is left out\n", name.c_str(),
               bounces_for(registry).c_str());
}

std::vector<std::string> RendererOptions::assignments(const Registry* registry) const {
  std::vector<std::string> out;
  for (const auto& kv : settings) {
    const std::string key = setting_key(kv);
    if (key != "bounces" && !(key == "bounce_samples" && bounce_samples > 0)) out.push_back(kv);
  }
  out.push_back("bounces=" + (registry ? bounces_for(*registry) : bounces));
  if (bounce_samples > 0) out.push_back("bounce_samples=" + std::to_string(bounce_samples));
  return out;
}

std::unique_ptr<Renderer> RendererOptions::create(const Registry& registry, std::shared_ptr<const Scene> scene) const {
  set_thread_limit(threads);
  const Properties props = Properties::from_assignments(assignments(&registry));
  auto renderer = registry.create_renderer(name, props);
  renderer->set_scene(std::move(scene));
  note_bounces(registry);  // once the set-up has succeeded: bad input gets one line
  return renderer;
}


void check_output_type(const std::string& path, const std::vector<std::string>& known, const std::string& advice) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext.empty() || std::find(known.begin(), known.end(), ext) != known.end()) return;
  throw InputError(path, "unknown output type '" + ext + "' (" + advice + ")");
}

void add_scene_options(CLI::App& app, SceneLoadOptions& options, const std::string& tuning_group) {
  app.add_option("--unit", options.unit,
                 "the scene file's length unit when its format does not say (OBJ, PLY, ...), or a glTF written in another "
                 "unit than its metres: mm, cm, m, in, ft (default m); positions in files and options are in it")
      ->check(CLI::IsMember({"mm", "cm", "m", "in", "ft"}));
  auto* edge = app.add_option("--max-edge", options.max_edge, "longest edge after tessellation, in the file's unit (default: diagonal/40)")
                   ->check(FiniteNonNegative);
  auto* vertices = app.add_option("--max-vertices", options.max_vertices, "the most vertices the tessellation may make")
                       ->check(CLI::Range(size_t(1), size_t(2000000000)))
                       ->capture_default_str();
  if (!tuning_group.empty())
    for (CLI::Option* o : {edge, vertices}) o->group(tuning_group);
}

} // namespace hilight::cli
