#include "ism_renderer.hpp"

#include "crease_candidates.hpp"
#include "cube_culling.hpp"

#include "hilight/error.hpp"
#include "hilight/scene.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <stdexcept>
#include <tbb/parallel_for.h>

namespace hilight::ism {

namespace {

// SPIR-V compiled from shaders/ by glslc at build time.
const uint32_t kTriangleRasterVert[] =
#include "triangle_raster.vert.inc"
    ;
const uint32_t kTriangleRasterFrag[] =
#include "triangle_raster.frag.inc"
    ;
const uint32_t kDirect[] =
#include "direct.comp.inc"
    ;
const uint32_t kVplGenerate[] =
#include "vpl_generate.comp.inc"
    ;
const uint32_t kIsmSplat[] =
#include "ism_splat.comp.inc"
    ;
const uint32_t kIsmPull[] =
#include "ism_pull.comp.inc"
    ;
const uint32_t kIsmPush[] =
#include "ism_push.comp.inc"
    ;
const uint32_t kGather[] =
#include "gather.comp.inc"
    ;
const uint32_t kBounceSplat[] =
#include "bounce_splat.comp.inc"
    ;

struct GpuLight {
  float position[4];
  float direction[4];
  float cone[4];  // cos cutoff, cos of the full-intensity core, 1 spot / 2 luminaire, unused
  float c0[4];    // a luminaire's C0 axis, w: its profile table's offset
  float c90[4];   // its C90 axis
};

/// Profile tables as common.glsl reads them: candela over the peak every 5° of
/// C and 2.5° of γ (bilinear there; Embree interpolates the file's own grid).
constexpr uint32_t kProfileC = 73, kProfileG = 73;

std::vector<float> profile_table(const Photometry& p) {
  std::vector<float> t(size_t(kProfileC) * kProfileG);
  const double peak = p.peak() > 0 ? p.peak() : 1.0;
  for (uint32_t c = 0; c < kProfileC; ++c)
    for (uint32_t g = 0; g < kProfileG; ++g) t[size_t(c) * kProfileG + g] = float(p.intensity(5.0 * c, 2.5 * g) / peak);
  return t;
}

/// Parts per area or line source: each costs a light's shadow maps and VPLs.
constexpr int kAreaElements = 16;

GpuLight to_gpu(const Light& light, uint32_t profile_offset) {
  GpuLight g{};
  for (int k = 0; k < 3; ++k) {
    g.position[k] = light.position[k];
    g.direction[k] = light.direction[k];
  }
  if (light.type == LightType::Spot) {
    const SpotCone cone = SpotCone::of(light);
    g.cone[0] = cone.cos_cutoff;
    g.cone[1] = cone.cos_inner;
    g.cone[2] = 1.f;
  }
  if (light.type == LightType::Luminaire) {
    const LuminaireFrame frame = LuminaireFrame::of(light);
    for (int k = 0; k < 3; ++k) {
      g.direction[k] = frame.nadir[k];
      g.c0[k] = frame.c0[k];
      g.c90[k] = frame.c90[k];
    }
    g.cone[2] = 2.f;
    g.c0[3] = float(profile_offset);
    // Type C files say which γ they measured (type B ones cover the front).
    const bool type_c = light.profile && light.profile->type == Photometry::Type::C;
    g.direction[3] = type_c ? float(light.profile->vertical.front()) : 0.f;
    g.c90[3] = type_c ? float(light.profile->vertical.back()) : 90.f;
  }
  return g;
}

struct DirectParams {
  uint32_t points, lights, size;
  float epsilon;
};
struct VplParams {
  uint32_t lights, vpls, size, seed;
  float lift;
};
struct SplatParams {
  uint32_t vpls, per_vpl, pool, size;
};
struct PullParams {
  uint32_t vpls, size, source, target, from_ism;
};
struct PushParams {
  uint32_t vpls, size, source, target;
};
struct GatherParams {
  uint32_t points, lights, vpls, size;
  float min_dist2, bias_rel, bias_const;
};
struct BounceSplatParams {
  uint32_t receivers, emitters, size;
  float depth_scale;
  uint32_t pass;
  float radius;
};

/// Point sets up to this many keep their bounce gather rows between calls
/// (about 3 kB a point at the default map); larger ones (images) make them
/// chunk by chunk on each call.
constexpr size_t kCachedGatherPoints = 32768;

/// Offsets (in floats) of each level of a VPL's pull-push pyramid, finest first.
std::vector<uint32_t> pyramid_offsets(uint32_t vpls, uint32_t size) {
  std::vector<uint32_t> offsets;
  uint32_t offset = 0;
  for (uint32_t s = size; s >= 1; s /= 2) {
    offsets.push_back(offset);
    offset += vpls * s * s;
  }
  offsets.push_back(offset);  // total
  return offsets;
}

template <class T, size_t N> std::span<const uint32_t> spirv(const T (&code)[N]) { return {code, N}; }

} // namespace

struct IsmRenderer::PointBuffers {
  uint64_t key = 0;
  size_t count = 0;
  Buffer positions, normals, albedo;
  Buffer crease;  ///< kCreaseCandidates triangles touching each point (crease_candidates.hpp)
  std::vector<ShadingPoint> at;  ///< where each point is shaded (for the wedge test)
  std::vector<Vec3> shading_normals;
  mutable std::unique_ptr<GatherRows> bounce_rows;  ///< their gather of the bounce points (small sets only)
};

struct IsmRenderer::Bounces {
  std::unique_ptr<PointBuffers> points;  ///< the bounce points, albedo 1 (the direct kernel gives E/π there)
  std::vector<Vec3> normals;             ///< their face normals: side 0 is the side they point to
  Buffer emitters;                       ///< position, normal (w: open sides): what bounce_splat.comp splats
  std::vector<float> weights;            ///< paraboloid_cosine_weights(bounce_map)
  float radius = 0.f;                    ///< a disk of each one's share of the area: √(A/(π M))
  std::unique_ptr<BounceSeries> series;
};

struct IsmRenderer::Workspace {
  uint32_t lights = 0;
  size_t points = 0;
  Buffer light_data, triangles, vpls, ism, pyramid, result;
  Buffer bounce_direct;  ///< the direct light at the bounce points (bounces ≥ 2)
  Buffer wedge;  ///< a bit per (light, point): the point's own wedge blocks the light (in_own_wedge)
  Buffer bounce_wedge;  ///< the same for the bounce points: all clear (flat face points have no wedge)
  Buffer face_indices, face_ids;  ///< culled triangle lists of the chunk's cube faces (grown on demand)
  Buffer profiles;                ///< the chunk's luminaire profile tables (grown on demand)
};

struct IsmRenderer::Kernels {
  ComputeKernel direct, vpl, splat, pull, push, gather, bounce_splat;
  Kernels(VulkanContext& c, uint32_t w)
      : direct(c, spirv(kDirect), 11, sizeof(DirectParams), w), vpl(c, spirv(kVplGenerate), 6, sizeof(VplParams), w),
        splat(c, spirv(kIsmSplat), 3, sizeof(SplatParams), w), pull(c, spirv(kIsmPull), 2, sizeof(PullParams), w),
        push(c, spirv(kIsmPush), 1, sizeof(PushParams), w), gather(c, spirv(kGather), 6, sizeof(GatherParams), w),
        bounce_splat(c, spirv(kBounceSplat), 4, sizeof(BounceSplatParams), w) {}
};

/// Wall-clock seconds per stage, when profiling: each mark submits what was
/// recorded since the last one and waits for it. (Lavapipe's timestamp
/// queries do not bracket its deferred raster and compute work, so GPU
/// timestamps attribute time to the wrong stages there.)
class IsmRenderer::StageClock {
public:
  bool enabled = false;
  std::map<std::string, double> seconds;

  void start() { m_last = std::chrono::steady_clock::now(); }
  /// The time since the previous mark is booked to `stage`; `flush` submits and waits.
  template <class Flush> void mark(const char* stage, Flush&& flush) {
    if (!enabled) return;
    flush();
    const auto now = std::chrono::steady_clock::now();
    seconds[stage] += std::chrono::duration<double>(now - m_last).count();
    m_last = now;
  }

private:
  std::chrono::steady_clock::time_point m_last;
};

IsmRenderer::IsmRenderer(const IsmSettings& settings) : m_settings(settings) {
  m_context = std::make_unique<VulkanContext>(settings.device);
  m_context->set_memory_budget(VkDeviceSize(settings.memory_mb) << 20);
  VkCommandBufferAllocateInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  info.commandPool = m_context->command_pool();
  info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  info.commandBufferCount = 1;
  check(vkAllocateCommandBuffers(m_context->device(), &info, &m_cmd), "vkAllocateCommandBuffers");
  VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  check(vkCreateFence(m_context->device(), &fence, nullptr, &m_fence), "vkCreateFence");
  m_clock = std::make_unique<StageClock>();
}

IsmRenderer::~IsmRenderer() {
  vkDeviceWaitIdle(m_context->device());
  // Everything that holds Vulkan objects goes before the device does.
  m_clock.reset();
  m_workspace.reset();
  m_points.reset();
  m_vertex_buffers.reset();
  m_bounces.reset();
  m_kernels.reset();
  m_raster.reset();
  m_buffers.reset();
  if (m_fence) vkDestroyFence(m_context->device(), m_fence, nullptr);
  if (m_cmd) vkFreeCommandBuffers(m_context->device(), m_context->command_pool(), 1, &m_cmd);
}

void IsmRenderer::set_scene(std::shared_ptr<const Scene> scene) {
  std::lock_guard lock(m_mutex);
  if (m_scene) throw std::logic_error("IsmRenderer: set_scene may be called once");
  const Scene& s = *scene;
  m_rays = RayScene::shared(scene);
  VulkanContext& ctx = *m_context;
  m_buffers = std::make_unique<SceneBuffers>(ctx, s, m_settings.ism_points, m_settings.seed);
  m_raster = std::make_unique<TriangleRaster>(ctx, m_buffers->vertices, spirv(kTriangleRasterVert), spirv(kTriangleRasterFrag));
  m_kernels = std::make_unique<Kernels>(ctx, m_settings.workgroup);
  m_scene = std::move(scene);
}

const IsmRenderer::PointBuffers& IsmRenderer::upload_points(const SurfacePoints& points) {
  const uint64_t key = points.content_key();
  if (m_points && m_points->key == key && m_points->count == points.size()) return *m_points;
  m_points.reset();
  m_points = make_point_buffers(points);
  return *m_points;
}

std::unique_ptr<IsmRenderer::PointBuffers> IsmRenderer::make_point_buffers(const SurfacePoints& points) {
  const uint64_t key = points.content_key();
  auto pb = std::make_unique<PointBuffers>();
  const size_t n = points.size();
  const VkDeviceSize bytes = n * 4 * sizeof(float);
  pb->positions = Buffer(*m_context, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true, "the surface points");
  pb->normals = Buffer(*m_context, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true, "the surface normals");
  pb->albedo = Buffer(*m_context, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true, "the surface albedo");
  const std::vector<uint32_t> crease = crease_candidates(*m_scene, points, 0.25f * m_scene->max_edge > 0 ? 0.25f * m_scene->max_edge : 0.01f * m_scene->diagonal());
  pb->crease = Buffer(*m_context, std::max<size_t>(crease.size(), 1) * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true,
                      "the surface points' crease triangles");
  std::memcpy(pb->crease.data<uint32_t>(), crease.data(), crease.size() * sizeof(uint32_t));
  float *pos = pb->positions.data<float>(), *nor = pb->normals.data<float>(), *alb = pb->albedo.data<float>();
  pb->at.resize(n);
  pb->shading_normals = points.normals;
  // Shaded where every renderer shades them (shading_point, rendering model);
  // positions' w says the point is smooth (its rays skip their first ε).
  tbb::parallel_for(size_t(0), n, [&](size_t i) {
    const ShadingPoint at = shading_point(*m_rays, points.positions[i], points.normals[i]);
    pb->at[i] = at;
    const Vec3 p = at.position;
    for (int a = 0; a < 3; ++a) {
      pos[4 * i + a] = p[a];
      nor[4 * i + a] = points.normals[i][a];
      alb[4 * i + a] = points.albedo[i][a];
    }
    // Which sides face free space (bit 0: the side n points to; bit 1: the
    // other): a side inside a closed solid receives no bounce, which the
    // imperfect shadow maps alone would let through (docs/ism-vulkan.md).
    const float lift = 1e-3f * m_scene->diagonal();
    const Vec3& normal = points.normals[i];
    const uint32_t open =
        uint32_t(!m_rays->inside_solid(p + normal * lift)) | uint32_t(!m_rays->inside_solid(p - normal * lift)) << 1;
    pos[4 * i + 3] = at.smooth ? 1.f : 0.f;
    alb[4 * i + 3] = 0.f;
    nor[4 * i + 3] = float(open);
  });
  pb->key = key;
  pb->count = n;
  return pb;
}

uint32_t IsmRenderer::lights_per_chunk(size_t light_count, size_t point_count) const {
  const IsmSettings& s = m_settings;
  const uint64_t texels = uint64_t(s.shadow_size) * s.shadow_size;
  uint64_t per_light = 6 * texels * 12 + point_count * 16 + sizeof(GpuLight);  // ID map, its copy, depth
  if (s.bounces != 0) per_light += uint64_t(s.vpls) * (80 + uint64_t(s.ism_size) * s.ism_size * 10);
  if (every_bounce_path()) per_light += uint64_t(s.bounce_points) * 16;
  uint64_t chunk = std::max<uint64_t>(1, (uint64_t(s.chunk_mb) << 20) / per_light);
  chunk = std::min<uint64_t>(chunk, TriangleRaster::max_views(*m_context, s.shadow_size, s.shadow_size) / 6);
  return uint32_t(std::max<uint64_t>(1, std::min<uint64_t>(chunk, light_count)));
}

IsmRenderer::Workspace& IsmRenderer::workspace(uint32_t lights, size_t point_count) {
  if (m_workspace && m_workspace->lights >= lights && m_workspace->points >= point_count) return *m_workspace;
  m_workspace.reset();
  const IsmSettings& s = m_settings;
  VulkanContext& ctx = *m_context;
  auto ws = std::make_unique<Workspace>();
  ws->lights = lights;
  ws->points = point_count;
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  const VkBufferUsageFlags filled = storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  const VkDeviceSize texels = VkDeviceSize(lights) * 6 * s.shadow_size * s.shadow_size;
  ws->light_data = Buffer(ctx, lights * sizeof(GpuLight), storage, true, "the lights");
  ws->triangles = Buffer(ctx, texels * 4, filled, false, "the shadow maps");
  ws->result = Buffer(ctx, VkDeviceSize(lights) * point_count * 16, filled, true, "the results");
  if (every_bounce_path()) {
    ws->bounce_direct = Buffer(ctx, VkDeviceSize(lights) * s.bounce_points * 16, storage, true, "the bounce points' direct light");
    const VkDeviceSize bits = VkDeviceSize((lights + 31) / 32) * s.bounce_points * 4;
    ws->bounce_wedge = Buffer(ctx, bits, storage, true, "the bounce points' wedge bits");
    std::memset(ws->bounce_wedge.data<uint32_t>(), 0, size_t(bits));
  }
  ws->wedge = Buffer(ctx, VkDeviceSize((lights + 31) / 32) * point_count * 4, storage, true, "the wedge bits");
  if (s.bounces != 0) {
    const uint32_t vpls = lights * s.vpls;
    ws->vpls = Buffer(ctx, VkDeviceSize(vpls) * 80, storage, false, "the VPLs");  // 5 vec4s each
    ws->ism = Buffer(ctx, VkDeviceSize(vpls) * s.ism_size * s.ism_size * 4, filled, false, "the imperfect shadow maps");
    ws->pyramid = Buffer(ctx, VkDeviceSize(pyramid_offsets(vpls, s.ism_size).back()) * 4, storage, false, "the ISM pyramids");
  }
  m_workspace = std::move(ws);
  return *m_workspace;
}

std::vector<RasterDraw> IsmRenderer::upload_face_triangles(std::span<const Light> lights, Workspace& ws) {
  std::vector<std::vector<uint32_t>> indices(lights.size()), ids(lights.size());
  std::vector<std::vector<RasterDraw>> draws(lights.size());
  tbb::parallel_for(size_t(0), lights.size(),
                    [&](size_t j) { cull_to_cube_faces(*m_scene, lights[j], indices[j], ids[j], draws[j]); });
  size_t total = 0;
  for (const auto& list : ids) total += list.size();
  const VkDeviceSize id_bytes = std::max<size_t>(total, 1) * sizeof(uint32_t);
  if (!ws.face_ids || ws.face_ids.size() < id_bytes) {
    ws.face_ids.reset();
    ws.face_indices.reset();
    // Room to grow, so a chunk with a few more visible triangles does not reallocate.
    const VkDeviceSize capacity = id_bytes + id_bytes / 2;
    ws.face_ids = Buffer(*m_context, capacity, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true, "the shadow maps' triangle lists");
    ws.face_indices = Buffer(*m_context, 3 * capacity, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, true, "the shadow maps' triangle lists");
  }
  std::vector<RasterDraw> out;
  uint32_t offset = 0;
  for (size_t j = 0; j < lights.size(); ++j) {
    std::memcpy(ws.face_ids.data<uint32_t>() + offset, ids[j].data(), ids[j].size() * sizeof(uint32_t));
    std::memcpy(ws.face_indices.data<uint32_t>() + 3 * size_t(offset), indices[j].data(), indices[j].size() * sizeof(uint32_t));
    for (RasterDraw d : draws[j]) out.push_back({d.first + offset, d.count});
    offset += uint32_t(ids[j].size());
  }
  return out;
}

void IsmRenderer::record_chunk(VkCommandBuffer cmd, const PointBuffers& pb, std::span<const Light> lights, Transport transport, Later later,
                               Workspace& ws, StageClock& clock) {
  const IsmSettings& s = m_settings;
  const uint32_t c = uint32_t(lights.size()), n = uint32_t(pb.count);
  const float diagonal = m_scene->diagonal();
  GpuLight* gpu = ws.light_data.data<GpuLight>();
  // Each profile's table once, however many lights carry it.
  std::vector<float> tables;
  std::map<const Photometry*, uint32_t> table_of;
  for (const Light& l : lights)
    if (l.type == LightType::Luminaire && l.profile && !table_of.count(l.profile.get())) {
      table_of[l.profile.get()] = uint32_t(tables.size());
      const std::vector<float> t = profile_table(*l.profile);
      tables.insert(tables.end(), t.begin(), t.end());
    }
  if (tables.empty()) tables.push_back(0.f);
  const VkDeviceSize table_bytes = tables.size() * sizeof(float);
  if (!ws.profiles || ws.profiles.size() < table_bytes) {
    ws.profiles.reset();
    ws.profiles = Buffer(*m_context, table_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true, "the luminaire profiles");
  }
  std::memcpy(ws.profiles.data<float>(), tables.data(), table_bytes);
  std::vector<RasterView> views;
  for (uint32_t j = 0; j < c; ++j) {
    const auto table = lights[j].profile ? table_of.find(lights[j].profile.get()) : table_of.end();
    gpu[j] = to_gpu(lights[j], table != table_of.end() ? table->second : 0u);
    for (const auto& v : cube_views(lights[j].position, 1e-4f * diagonal, 4.f * diagonal)) views.push_back(v);
  }
  const std::vector<RasterDraw> draws = upload_face_triangles(lights, ws);
  clock.start();
  auto flush = [&] {
    submit_and_wait(cmd);
    begin_commands(cmd);
  };
  m_raster->record(cmd, views, draws, ws.face_indices, ws.face_ids, s.shadow_size, s.shadow_size, ws.triangles);
  full_barrier(cmd);
  clock.mark("shadow_maps", flush);
  const Kernels& k = *m_kernels;
  if (transport != Transport::IndirectOnly && later != Later::Only) {
    // Which lights each smooth point's own wedge blocks: geometry alone,
    // the same test every renderer makes (rendering model).
    uint32_t* bits = ws.wedge.data<uint32_t>();
    std::memset(bits, 0, size_t((c + 31) / 32) * n * sizeof(uint32_t));
    tbb::parallel_for(uint32_t(0), n, [&](uint32_t i) {
      const ShadingPoint& at = pb.at[i];
      if (!at.smooth || at.wedge == 0.f) return;
      for (uint32_t j = 0; j < c; ++j) {
        const Vec3 d = lights[j].position - at.position;
        const float length = glm::length(d);
        if (length > 0.f && in_own_wedge(*m_rays, at, pb.shading_normals[i], d / length)) bits[(j / 32) * n + i] |= 1u << (j % 32);
      }
    });
    DirectParams p{n, c, s.shadow_size, m_rays->epsilon()};
    k.direct.dispatch(cmd, {&pb.positions, &pb.normals, &pb.albedo, &ws.light_data, &ws.triangles, &m_buffers->corners, &m_buffers->neighbours,
                                   &pb.crease, &ws.result, &ws.profiles, &ws.wedge},
                      &p,
                      uint64_t(n) * c);
  } else {
    vkCmdFillBuffer(cmd, ws.result.handle(), 0, VK_WHOLE_SIZE, 0);
  }
  if (every_bounce_path() && transport != Transport::DirectOnly && later != Later::Excluded) {
    // The direct light at the bounce points: e₀ of the later bounces.
    const PointBuffers& bp = *m_bounces->points;
    DirectParams p{uint32_t(bp.count), c, s.shadow_size, m_rays->epsilon()};
    k.direct.dispatch(cmd, {&bp.positions, &bp.normals, &bp.albedo, &ws.light_data, &ws.triangles, &m_buffers->corners,
                            &m_buffers->neighbours, &bp.crease, &ws.bounce_direct, &ws.profiles, &ws.bounce_wedge},
                      &p, uint64_t(bp.count) * c);
  }
  full_barrier(cmd);
  clock.mark("direct", flush);
  if (s.bounces == 0 || transport == Transport::DirectOnly || later == Later::Only) return;

  const uint32_t vpls = c * s.vpls;
  VplParams vp{c, s.vpls, s.shadow_size, uint32_t(s.seed * 2654435761u), 1e-4f * diagonal};
  k.vpl.dispatch(cmd, {&ws.light_data, &ws.triangles, &m_buffers->corners, &m_buffers->triangle_albedo, &ws.vpls, &ws.profiles}, &vp, vpls);
  vkCmdFillBuffer(cmd, ws.ism.handle(), 0, VK_WHOLE_SIZE, 0xFFFFFFFFu);
  full_barrier(cmd);
  clock.mark("vpls", flush);
  SplatParams sp{vpls, s.points_per_vpl, s.ism_points, s.ism_size};
  k.splat.dispatch(cmd, {&ws.vpls, &m_buffers->pool, &ws.ism}, &sp, uint64_t(vpls) * s.points_per_vpl);
  full_barrier(cmd);
  clock.mark("ism_splat", flush);
  const std::vector<uint32_t> offsets = pyramid_offsets(vpls, s.ism_size);
  const size_t levels = offsets.size() - 1;
  PullParams resolve{vpls, s.ism_size, 0, 0, 1};
  k.pull.dispatch(cmd, {&ws.ism, &ws.pyramid}, &resolve, uint64_t(vpls) * s.ism_size * s.ism_size);
  full_barrier(cmd);
  for (size_t l = 1; l < levels; ++l) {
    const uint32_t size = s.ism_size >> l;
    PullParams pull{vpls, size, offsets[l - 1], offsets[l], 0};
    k.pull.dispatch(cmd, {&ws.ism, &ws.pyramid}, &pull, uint64_t(vpls) * size * size);
    full_barrier(cmd);
  }
  for (size_t l = levels - 1; l-- > 0;) {
    const uint32_t size = s.ism_size >> l;
    PushParams push{vpls, size, offsets[l + 1], offsets[l]};
    k.push.dispatch(cmd, {&ws.pyramid}, &push, uint64_t(vpls) * size * size);
    full_barrier(cmd);
  }
  clock.mark("pull_push", flush);
  const float min_dist = s.vpl_clamp * diagonal;
  GatherParams gp{n, c, s.vpls, s.ism_size, min_dist * min_dist, s.ism_bias, 2e-3f * diagonal};
  k.gather.dispatch(cmd, {&pb.positions, &pb.normals, &pb.albedo, &ws.vpls, &ws.pyramid, &ws.result}, &gp, uint64_t(n) * c);
  full_barrier(cmd);
  clock.mark("gather", flush);
}

void IsmRenderer::begin_commands(VkCommandBuffer cmd) {
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkResetCommandBuffer(cmd, 0), "vkResetCommandBuffer");
  check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
}

void IsmRenderer::submit_and_wait(VkCommandBuffer cmd) {
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  check(vkResetFences(m_context->device(), 1, &m_fence), "vkResetFences");
  check(vkQueueSubmit(m_context->queue(), 1, &submit, m_fence), "vkQueueSubmit");
  check(vkWaitForFences(m_context->device(), 1, &m_fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
}

std::vector<Rgb> IsmRenderer::unit_responses(const SurfacePoints& points, std::span<const Light> lights, Transport transport) {
  return responses(points, lights, transport, Later::Included);
}

std::vector<Rgb> IsmRenderer::responses(const SurfacePoints& points, std::span<const Light> lights, Transport transport, Later later) {
  if (std::none_of(lights.begin(), lights.end(), [](const Light& l) { return is_area(l.type); }))
    return point_responses(points, lights, transport, later);
  // An area or line source as its parts, each a cosine (or its profile's)
  // luminaire carrying an equal share (lighting.hpp: area_light_elements);
  // its φ is the sum of theirs.
  Lighting parts;
  std::vector<size_t> first(lights.size() + 1, 0);
  for (size_t j = 0; j < lights.size(); ++j) {
    for (const Light& part : area_light_elements(lights[j], kAreaElements)) parts.push_back(part);
    first[j + 1] = parts.size();
  }
  const std::vector<Rgb> each = point_responses(points, parts, transport, later);
  const size_t n = points.size();
  std::vector<Rgb> out(n * lights.size(), Rgb(0.f));
  for (size_t j = 0; j < lights.size(); ++j) {
    const float share = 1.f / float(first[j + 1] - first[j]);
    for (size_t e = first[j]; e < first[j + 1]; ++e)
      for (size_t i = 0; i < n; ++i) out[j * n + i] += share * each[e * n + i];
  }
  return out;
}

std::vector<Rgb> IsmRenderer::point_responses(const SurfacePoints& points, std::span<const Light> lights, Transport transport,
                                              Later later) {
  std::lock_guard lock(m_mutex);
  if (!m_scene) throw std::logic_error("IsmRenderer: set_scene was not called");
  const size_t n = points.size();
  std::vector<Rgb> out(n * lights.size(), Rgb(0.f));
  m_clock->seconds.clear();
  if (n == 0 || lights.empty()) return out;
  // The images' vertices keep buffers (and maps) of their own, beside the last other point set.
  const bool vertices = m_vertices && &points == m_vertices.get();
  if (vertices && !m_vertex_buffers) m_vertex_buffers = make_point_buffers(points);
  const PointBuffers& pb = vertices ? *m_vertex_buffers : upload_points(points);
  const bool later_bounces = every_bounce_path() && transport != Transport::DirectOnly && later != Later::Excluded;
  if (later_bounces) bounces();
  std::vector<Rgb> field;  // d₁ + … + d_{B−1} at the bounce points, per light: gathered once, after every chunk
  uint32_t chunk = lights_per_chunk(lights.size(), n);
  // Thread numbers in the shaders are 32-bit: keep points × lights within them.
  chunk = uint32_t(std::min<size_t>(chunk, std::max<size_t>(1, (size_t(1) << 31) / n)));
  Workspace& ws = workspace(chunk, n);
  for (size_t start = 0; start < lights.size(); start += chunk) {
    const size_t count = std::min<size_t>(chunk, lights.size() - start);
    begin_commands(m_cmd);
    record_chunk(m_cmd, pb, lights.subspan(start, count), transport, later, ws, *m_clock);
    submit_and_wait(m_cmd);
    const float* result = ws.result.data<float>();
    for (size_t j = 0; j < count; ++j)
      for (size_t i = 0; i < n; ++i) {
        const float* r = result + 4 * (j * n + i);
        out[(start + j) * n + i] = Rgb(r[0], r[1], r[2]);
      }
    if (later_bounces) {
      const std::vector<Rgb> f = later_bounce_field(lights.subspan(start, count), ws);
      field.insert(field.end(), f.begin(), f.end());
    }
  }
  if (later_bounces) gather_later_bounces(points, pb, field, lights.size(), out.data());
  m_context->throw_on_validation_errors();
  return out;
}

const IsmRenderer::Bounces& IsmRenderer::bounces() {
  if (m_bounces) return *m_bounces;
  const IsmSettings& s = m_settings;
  auto b = std::make_unique<Bounces>();
  SurfacePoints sampled = sample_bounce_points(*m_scene, s.bounce_points, s.seed);
  const std::vector<Rgb> albedo = sampled.albedo;
  std::fill(sampled.albedo.begin(), sampled.albedo.end(), Rgb(1.f));
  b->points = make_point_buffers(sampled);
  b->normals = sampled.normals;
  const size_t m = sampled.size();
  b->emitters = Buffer(*m_context, m * 32, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true, "the bounce points");
  float* e = b->emitters.data<float>();
  const float* pos = b->points->positions.data<float>();
  for (size_t i = 0; i < m; ++i)
    for (int a = 0; a < 4; ++a) {
      e[8 * i + a] = a < 3 ? pos[4 * i + a] : 1.f;
      e[8 * i + 4 + a] = a < 3 ? sampled.normals[i][a] : b->points->normals.data<float>()[4 * i + 3];  // w: open sides
    }
  b->weights = paraboloid_cosine_weights(s.bounce_map);
  b->radius = float(std::sqrt(surface_area(*m_scene) / (kPi * double(m))));
  m_bounces = std::move(b);
  try {
    GatherRows transport = bounce_rows(*m_bounces->points, 0, m);
    m_bounces->series = std::make_unique<BounceSeries>(std::move(transport), albedo, s.bounces);
  } catch (...) {
    m_bounces.reset();
    throw;
  }
  return *m_bounces;
}

GatherRows IsmRenderer::bounce_rows(const PointBuffers& pb, size_t first, size_t count) {
  const IsmSettings& s = m_settings;
  const Bounces& b = *m_bounces;
  const uint32_t emitters = uint32_t(b.normals.size()), texels = s.bounce_map * s.bounce_map;
  // Receivers per pass: maps within 64 MB, thread numbers within 32 bits.
  const size_t per_pass = std::max<size_t>(1, std::min<size_t>((size_t(64) << 20) / (size_t(texels) * 4 * 2),
                                                               (size_t(1) << 31) / (size_t(2) * emitters)));
  const size_t pass = std::min(per_pass, count);
  Buffer receivers(*m_context, pass * 2 * 32, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true, "the bounce receivers");
  Buffer nearest(*m_context, pass * 2 * texels * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, true,
                 "the bounce maps");
  Buffer drawn(*m_context, pass * 2 * texels * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, true,
               "the bounce maps");
  const float* pos = pb.positions.data<float>();
  const float* nor = pb.normals.data<float>();
  GatherRows rows;
  for (size_t begin = first; begin < first + count; begin += pass) {
    const size_t here = std::min(pass, first + count - begin);
    float* r = receivers.data<float>();
    for (size_t i = 0; i < here; ++i) {
      const size_t p = begin + i;
      const uint32_t open = uint32_t(nor[4 * p + 3]);
      for (int side = 0; side < 2; ++side) {
        float* at = r + 16 * i + 8 * side;
        const float sign = side == 0 ? 1.f : -1.f;
        for (int a = 0; a < 3; ++a) {
          at[a] = pos[4 * p + a];
          at[4 + a] = sign * nor[4 * p + a];
        }
        at[3] = 1.f;
        at[7] = (open >> side) & 1u ? 1.f : 0.f;
      }
    }
    begin_commands(m_cmd);
    vkCmdFillBuffer(m_cmd, nearest.handle(), 0, VK_WHOLE_SIZE, 0xFFFFFFFFu);
    vkCmdFillBuffer(m_cmd, drawn.handle(), 0, VK_WHOLE_SIZE, 0xFFFFFFFFu);
    full_barrier(m_cmd);
    for (uint32_t step = 0; step < 2; ++step) {
      BounceSplatParams params{uint32_t(2 * here), emitters, s.bounce_map, 65000.f / (1.01f * m_scene->diagonal()), step,
                               b.radius};
      m_kernels->bounce_splat.dispatch(m_cmd, {&receivers, &b.emitters, &nearest, &drawn}, &params, uint64_t(2 * here) * emitters);
      full_barrier(m_cmd);
    }
    submit_and_wait(m_cmd);
    rows.append(nearest.data<uint32_t>(), drawn.data<uint32_t>(), 2 * here, s.bounce_map, b.weights);
  }
  return rows;
}

std::vector<Rgb> IsmRenderer::later_bounce_field(std::span<const Light> lights, const Workspace& ws) {
  const Bounces& b = *m_bounces;
  const size_t m = b.normals.size(), c = lights.size();
  // e₀ per (bounce point, side): the direct kernel's E/π on the side facing the light.
  std::vector<float> direct(c * 2 * m, 0.f);
  const float* result = ws.bounce_direct.data<float>();
  const float* pos = b.points->positions.data<float>();
  for (size_t j = 0; j < c; ++j)
    for (size_t i = 0; i < m; ++i) {
      const Vec3 p(pos[4 * i], pos[4 * i + 1], pos[4 * i + 2]);
      const int side = glm::dot(b.normals[i], p - lights[j].position) < 0.f ? 0 : 1;
      direct[j * 2 * m + 2 * i + side] = float(kPi) * result[4 * (j * m + i)];
    }
  return b.series->bounced(direct, c);
}

void IsmRenderer::gather_later_bounces(const SurfacePoints& points, const PointBuffers& pb, const std::vector<Rgb>& f,
                                       size_t c, Rgb* out) {
  const Bounces& b = *m_bounces;
  const size_t n = pb.count;
  if (n <= kCachedGatherPoints) {
    if (!pb.bounce_rows) pb.bounce_rows = std::make_unique<GatherRows>(bounce_rows(pb, 0, n));
    b.series->gather(*pb.bounce_rows, points.albedo, 0, f, c, out, n);
    return;
  }
  for (size_t first = 0; first < n; first += kCachedGatherPoints) {
    const size_t count = std::min(kCachedGatherPoints, n - first);
    b.series->gather(bounce_rows(pb, first, count), points.albedo, first, f, c, out, n);
  }
}

std::vector<Rgb> IsmRenderer::illuminate(const SurfacePoints& points, std::span<const Light> lights) {
  // Linear in the intensities: Σ_j I_j ⊙ φ_j, from one batch.
  std::vector<Rgb> unit = unit_responses(points, lights, Transport::All);
  const size_t n = points.size();
  std::vector<Rgb> out(n, Rgb(0.f));
  for (size_t j = 0; j < lights.size(); ++j)
    for (size_t i = 0; i < n; ++i) out[i] += lights[j].intensity * unit[j * n + i];
  return out;
}

std::vector<std::pair<std::string, double>> IsmRenderer::baseline_figures(const SurfacePoints& points,
                                                                          std::span<const Light> lights) {
  // One profiled call: every stage submitted and waited for on its own.
  m_clock->enabled = true;
  try {
    unit_responses(points, lights, Transport::All);
  } catch (...) {
    m_clock->enabled = false;
    throw;
  }
  std::lock_guard lock(m_mutex);
  m_clock->enabled = false;
  std::vector<std::pair<std::string, double>> out;
  for (const auto& [stage, seconds] : m_clock->seconds) out.emplace_back("stage_" + stage + "_seconds", seconds);
  return out;
}

std::string IsmSettings::key() const {
  return "ism-vulkan/bounces=" + std::to_string(bounces) + "/shadow=" + std::to_string(shadow_size) + "/vpls=" +
         std::to_string(vpls) + "/ism=" + std::to_string(ism_size) + "/ppv=" + std::to_string(points_per_vpl) + "/pool=" +
         std::to_string(ism_points) + "/bias=" + std::to_string(ism_bias) + "/clamp=" +
         std::to_string(vpl_clamp) + "/seed=" + std::to_string(seed) +
         (bounces != 0 && bounces != 1 ? "/bpoints=" + std::to_string(bounce_points) + "/bmap=" + std::to_string(bounce_map) : "");
}

} // namespace hilight::ism
