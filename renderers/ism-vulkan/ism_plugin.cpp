// Plugin entry of the `ism-vulkan` renderer: direct light from cube shadow
// maps, the first bounce from VPLs with imperfect shadow maps and the later
// ones through bounce points' hemisphere maps, on Vulkan (a GPU when
// present, else Mesa's lavapipe). docs/ism-vulkan.md explains.
//
// | property        | default | meaning                                                  |
// |-----------------|---------|----------------------------------------------------------|
// | bounces         | 1       | 0 = direct light only, 1 = plus the first bounce (VPLs), |
// |                 |         | N (up to 1000) or all = every bounce (traits: all)       |
// | bounce_points   | 2048    | surface samples carrying bounces 2.. (16..32767)         |
// | bounce_map      | 16      | their and the points' hemisphere maps, texels (4..64)    |
// | shadow_size     | 512     | cube ID map face resolution, texels (16..4096)          |
// | vpls            | 256     | virtual point lights per light (1..16384)                |
// | ism_size        | 32      | imperfect shadow map per VPL, texels (power of 2, 4..256) |
// | points_per_vpl  | 4096    | scene points splatted into each ISM                      |
// | ism_points      | 262144  | scene point samples in all (VPLs take random subsets)    |
// | ism_bias        | 0.04    | ISM depth bias, fraction of the distance                 |
// | vpl_clamp       | 0.05    | VPL distances clamped below this × scene diagonal        |
// | chunk_mb        | 192     | device memory per batch of lights (one submission each)  |
// | memory_mb       | 0       | own device-memory limit (0 = 3/4 of the largest heap)    |
// | workgroup       | 64      | compute work-group width                                 |
// | device          | auto    | auto (discrete > integrated > cpu), gpu, cpu, or index   |
// | validation      | false   | Vulkan validation layer on; its errors fail the call     |
// | seed            | 1       | VPL spiral rotation and ISM point pool                   |
// The environment variable HILIGHT_VULKAN_VALIDATION=1 also turns validation on.
#include "hilight/bounces.hpp"
#include "ism_renderer.hpp"
#include "hilight/error.hpp"
#include "hilight/plugin.hpp"
#include "hilight/version.hpp"
#include "hilight/registry.hpp"

#include <cstdlib>

namespace {

using hilight::InputError;

long long in_range(const hilight::Properties& props, const char* key, long long fallback, long long lo, long long hi) {
  long long v = props.get_int(key, fallback);
  if (v < lo || v > hi)
    throw InputError("renderer ism-vulkan: " + std::string(key) + " must be in [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "]");
  return v;
}

double positive(const hilight::Properties& props, const char* key, double fallback) {
  double v = props.get_double(key, fallback);
  if (!(v >= 0) || v > 1e6) throw InputError("renderer ism-vulkan: " + std::string(key) + " must be a number >= 0");
  return v;
}

std::unique_ptr<hilight::Renderer> create(const hilight::Properties& props) {
  hilight::ism::IsmSettings s;
  s.bounces = hilight::bounces_property(props, s.bounces, "renderer ism-vulkan: bounces");
  s.bounce_points = uint32_t(in_range(props, "bounce_points", s.bounce_points, 16, 32767));
  s.bounce_map = uint32_t(in_range(props, "bounce_map", s.bounce_map, 4, 64));
  s.shadow_size = uint32_t(in_range(props, "shadow_size", s.shadow_size, 16, 4096));
  s.vpls = uint32_t(in_range(props, "vpls", s.vpls, 1, 16384));
  s.ism_size = uint32_t(in_range(props, "ism_size", s.ism_size, 4, 256));
  if (s.ism_size & (s.ism_size - 1)) throw InputError("renderer ism-vulkan: ism_size must be a power of two");
  s.points_per_vpl = uint32_t(in_range(props, "points_per_vpl", s.points_per_vpl, 1, 1 << 20));
  s.ism_points = uint32_t(in_range(props, "ism_points", s.ism_points, 1, 1 << 26));
  s.ism_bias = float(positive(props, "ism_bias", s.ism_bias));
  s.vpl_clamp = float(positive(props, "vpl_clamp", s.vpl_clamp));
  s.chunk_mb = uint32_t(in_range(props, "chunk_mb", s.chunk_mb, 1, 1 << 20));
  s.memory_mb = uint64_t(in_range(props, "memory_mb", 0, 0, 1ll << 30));
  s.workgroup = uint32_t(in_range(props, "workgroup", s.workgroup, 1, 1024));
  s.seed = uint64_t(props.get_int("seed", 1));
  s.device.device = props.get_string("device", "auto");
  const char* env = std::getenv("HILIGHT_VULKAN_VALIDATION");
  s.device.validation = props.get_bool("validation", env && std::string(env) == "1");
  props.get_int("bounce_samples", 0);  // Embree's knob: meaningless here, but a solve passes it to any renderer
  if (s.workgroup > 1024 || (s.workgroup & (s.workgroup - 1)))
    throw InputError("renderer ism-vulkan: workgroup must be a power of two up to 1024");
  return std::make_unique<hilight::ism::IsmRenderer>(s);
}

// Probing makes a Vulkan instance and device: once per process is enough.
std::string probe() {
  static const std::string reason = hilight::ism::vulkan_unavailable_reason();
  return reason;
}

std::string detail() {
  static const std::string summary = "device: " + hilight::ism::vulkan_device_summary();
  return summary;
}

void register_ism(hilight::PluginRegistrar& registrar) {
  registrar.renderer(create, probe, detail);
  registrar.renderer_traits({{"vpls=64"}, {}, false, hilight::kAllBounces});  // fewer VPLs a light in the fast twin; the reference re-fits
}

} // namespace

HILIGHT_PLUGIN("renderer", HILIGHT_PLUGIN_NAME, HILIGHT_VERSION,
               "imperfect shadow maps on Vulkan: cube ID shadow maps, first bounce from VPLs, later ones from bounce points", register_ism)
