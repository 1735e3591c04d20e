// Plugin entry of the `povray` reference renderer (the real POV-Ray 3.7).
//
// | property        | default | meaning                                                |
// |-----------------|---------|--------------------------------------------------------|
// | bounces         | 1       | 0 = direct only, N = N bounces (radiosity recursion,   |
// |                 |         | up to 20), all = 20 (POV-Ray's most; docs/povray.md)   |
// | radiosity_count | 800     | radiosity rays per sample                              |
// | error_bound     | 0.15    | radiosity error_bound                                  |
// | pretrace_end    | 0.005   | radiosity pretrace_end                                 |
// | timeout         | 600     | seconds one POV-Ray run may take                       |
// | bounce_samples, seed      | accepted for interface compatibility, unused  |
#include "hilight/bounces.hpp"
#include "hilight/error.hpp"
#include "hilight/plugin.hpp"
#include "hilight/version.hpp"
#include "hilight/registry.hpp"
#include "povray_process.hpp"
#include "povray_renderer.hpp"

namespace {

std::unique_ptr<hilight::Renderer> create(const hilight::Properties& props) {
  hilight::povray::PovraySettings s;
  s.executable = hilight::povray::find_povray();
  s.pov.bounces = hilight::bounces_property(props, 1, "renderer povray: bounces");
  if (s.pov.bounces > hilight::kPovMaxBounces)
    throw hilight::InputError("renderer povray: bounces must be 'all' or at most " + std::to_string(hilight::kPovMaxBounces) +
                              " (POV-Ray's radiosity recursion_limit)");
  s.pov.radiosity_count = int(props.get_int("radiosity_count", s.pov.radiosity_count));
  s.pov.error_bound = props.get_double("error_bound", s.pov.error_bound);
  s.pov.pretrace_end = props.get_double("pretrace_end", s.pov.pretrace_end);
  s.timeout_seconds = props.get_double("timeout", s.timeout_seconds);
  props.get_int("bounce_samples", 0);  // Embree's knobs: meaningless here, but a
  props.get_int("seed", 0);            // solve passes them to any renderer
  if (s.pov.radiosity_count < 1 || s.pov.radiosity_count > 1600) throw hilight::InputError("renderer povray: radiosity_count must be in [1, 1600]");
  if (!(s.pov.error_bound > 0)) throw hilight::InputError("renderer povray: error_bound must be > 0");
  if (!(s.timeout_seconds > 0)) throw hilight::InputError("renderer povray: timeout must be > 0");
  return std::make_unique<hilight::povray::PovrayRenderer>(s);
}

std::string probe() {
  return hilight::povray::find_povray().empty() ? "no povray program on PATH (Debian package povray)" : "";
}

void register_povray(hilight::PluginRegistrar& registrar) { registrar.renderer(create, probe); }

} // namespace

HILIGHT_PLUGIN("renderer", HILIGHT_PLUGIN_NAME, HILIGHT_VERSION, "reference renderer: the real POV-Ray 3.7 (mesh_camera baking, radiosity)",
               register_povray)
