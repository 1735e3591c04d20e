// Plugin entry of the `embree` renderer (CPU ray tracing with Embree 3).
//
// | property        | default | meaning                                              |
// |-----------------|---------|------------------------------------------------------|
// | bounces         | 1       | 0 = direct light only, 1 = plus first diffuse bounce,|
// |                 |         | N = N bounces, all = every bounce (multi_bounce.hpp) |
// | bounce_samples  | 128     | gather rays per point for the bounce (even, >= 2)    |
// | transport_samples | 32    | gather rays per scene vertex for the bounces after   |
// |                 |         | the first (even, >= 2)                               |
// | seed            | 1       | seed of the gather's sample stream                   |
// | bounce_direct   | exact   | direct light at gather hits: exact shadow rays, or   |
// |                 |         | "vertex": interpolated from the hit triangle's       |
// |                 |         | vertices (fast for many lights; used by the cache)   |
// | hot_spots       | on      | surfaces near a light lit as virtual lights, not by  |
// |                 |         | gather hits (no fireflies; hot_spots.hpp)            |
// | bounce_rest_share | 0.01  | "all" adds the geometric rest once it is at most     |
// |                 |         | this share of the sum (hilight/bounce_series.hpp)    |
#include "embree_renderer.hpp"
#include "hilight/bounces.hpp"
#include "hilight/error.hpp"
#include "hilight/plugin.hpp"
#include "hilight/version.hpp"
#include "hilight/registry.hpp"

namespace {

std::unique_ptr<hilight::Renderer> create(const hilight::Properties& props) {
  hilight::embree::EmbreeSettings s;
  s.bounces = hilight::bounces_property(props, s.bounces, "renderer embree: bounces");
  long long transport = props.get_int("transport_samples", s.transport_samples);
  if (transport < 2 || transport > 4096) throw hilight::InputError("renderer embree: transport_samples must be in [2, 4096]");
  s.transport_samples = int(transport + (transport & 1));
  long long samples = props.get_int("bounce_samples", s.bounce_samples);
  if (samples < 2 || samples > 4096) throw hilight::InputError("renderer embree: bounce_samples must be in [2, 4096]");
  s.bounce_samples = int(samples + (samples & 1));
  s.seed = uint64_t(props.get_int("seed", 1));
  std::string bounce_direct = props.get_string("bounce_direct", "exact");
  if (bounce_direct != "exact" && bounce_direct != "vertex")
    throw hilight::InputError("renderer embree: bounce_direct must be exact or vertex");
  s.vertex_interpolated_bounce = bounce_direct == "vertex";
  const std::string hot = props.get_string("hot_spots", "on");
  if (hot != "on" && hot != "off") throw hilight::InputError("renderer embree: hot_spots must be on or off");
  s.hot_spots = hot == "on";
  s.bounce_rest_share = props.get_double("bounce_rest_share", s.bounce_rest_share);
  if (!(s.bounce_rest_share > 0 && s.bounce_rest_share < 1)) throw hilight::InputError("renderer embree: bounce_rest_share must be in (0, 1)");
  return std::make_unique<hilight::embree::EmbreeRenderer>(s);
}

void register_embree(hilight::PluginRegistrar& registrar) {
  registrar.renderer(create);
  // The fast twin reads direct light at gather hits from the vertices (fast
  // for many lights) and gathers without hot patches (1.6x per light; its
  // fireflies are the reference polish's to remove), and carries the
  // bounces after the first with 8 transport rays a vertex, not 32: those
  // bounces are the smoothest light in the scene, and every evaluation of a
  // moved light transports it over every vertex (4x its cost in a furnished
  // flat; the reference measures and polishes at the user's setting). The
  // preview gathers 16 rays a point: a stroke's fine-tune shows in a
  // fraction of a render. Direct light at a solve's samples takes
  // milliseconds. Its "all" ends sooner (the rest added at 10% of the sum,
  // the ratios steady to 2%: the cold product solve 9.6 → 8.0 s): the
  // reference measures the answer with the strict rule.
  registrar.renderer_traits({{"bounce_direct=vertex", "hot_spots=off", "transport_samples=8", "bounce_rest_share=0.1"}, {"bounce_samples=16"}, true});
}

} // namespace

HILIGHT_PLUGIN("renderer", HILIGHT_PLUGIN_NAME, HILIGHT_VERSION, "CPU ray tracing (Embree 3): direct light and every diffuse bounce by gathering",
               register_embree)
