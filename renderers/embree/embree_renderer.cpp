#include "embree_renderer.hpp"

#include "shared_gathers.hpp"

#include "hilight/bounces.hpp"

#include <algorithm>
#include <chrono>
#include <iterator>
#include <stdexcept>
#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

namespace hilight::embree {

void EmbreeRenderer::set_scene(std::shared_ptr<const Scene> scene) {
  if (m_scene) throw std::logic_error("EmbreeRenderer: set_scene may be called once");
  m_gathers.clear();
  m_shading_points.clear();
  m_embree.reset();
  m_scene = std::move(scene);
  m_embree = RayScene::shared(m_scene);
  // Where each vertex is shaded (shading_point: creases inside their triangle);
  // computed here, once, so no later (possibly concurrent) call has to.
  const Scene& s = *m_scene;
  m_vertex_shading.resize(s.positions.size());
  tbb::parallel_for(size_t(0), s.positions.size(),
                    [&](size_t v) { m_vertex_shading[v] = shading_point(*m_embree, s.positions[v], s.normals[v]); });
}

namespace {
/// A ray cast's cost against one hit read in the vertex transport's steps (for progress only).
constexpr double kReadsPerRay = 20.0;
} // namespace

double EmbreeRenderer::gather_rays(const SurfacePoints& points, uint64_t key, bool bounce) {
  if (!bounce) return 0.0;
  const double rays = double(points.size()) * m_settings.bounce_samples;
  return rays < CallProgress::kReported / 4 || m_gathers.contains(key) ? 0.0 : rays;
}

double EmbreeRenderer::further_rays(size_t lights, bool bounce) const {
  if (!bounce || !m_settings.further_bounces()) return 0.0;
  const double v = double(m_scene->positions.size());
  const double build = m_multi_built.load() ? 0.0 : v * m_settings.transport_samples;
  const int steps = m_multi_built.load() ? m_multi->expected_steps()
                                          : (m_settings.bounces == kAllBounces ? 8 : m_settings.bounces - 1);
  return build + 2.0 * v * double(lights) + double(steps) * double(lights) * 2.0 * v * m_settings.transport_samples / kReadsPerRay;
}

std::shared_ptr<const BounceGather> EmbreeRenderer::gather_for(const SurfacePoints& points, uint64_t key, CallProgress* progress) {
  auto origins = shading_points(points, key);
  return m_gathers.get(key, [&]() -> std::shared_ptr<const BounceGather> {
    const SharedGathers::Key shared{m_embree.get(), key, m_settings.bounce_samples, m_settings.seed};
    if (auto other = SharedGathers::find(shared)) return other;  // the same rays, cast by another renderer
    CallProgress::Phase phase(progress, "gathering the first bounce", double(points.size()),
                              double(points.size()) * m_settings.bounce_samples);
    auto gather = std::make_shared<const BounceGather>(*m_embree, points, *origins, m_settings.bounce_samples, m_settings.seed,
                                                       phase.stage());
    m_rays += gather->rays_cast();
    SharedGathers::add(shared, gather);
    return gather;
  });
}

std::shared_ptr<const std::vector<ShadingPoint>> EmbreeRenderer::shading_points(const SurfacePoints& points, uint64_t key) {
  return m_shading_points.get(key, [&] {
    auto out = std::make_shared<std::vector<ShadingPoint>>(points.size());
    tbb::parallel_for(size_t(0), points.size(),
                      [&](size_t i) { (*out)[i] = shading_point(*m_embree, points.positions[i], points.normals[i]); });
    return std::shared_ptr<const std::vector<ShadingPoint>>(std::move(out));
  });
}

const MultiBounce* EmbreeRenderer::multi_bounce(CallProgress* progress) {
  if (!m_settings.further_bounces()) return nullptr;
  std::call_once(m_multi_once, [&] {
    const double vertices = double(m_scene->positions.size());
    CallProgress::Phase phase(progress, "tracing paths between surfaces", vertices, vertices * m_settings.transport_samples);
    m_multi = std::make_unique<MultiBounce>(*m_embree, m_vertex_shading, m_settings.transport_samples, m_settings.seed,
                                            m_settings.bounces, m_settings.bounce_rest_share, phase.stage());
    m_rays += m_multi->rays_cast();
    m_multi_built.store(true);
  });
  return m_multi.get();
}

std::vector<Rgb> EmbreeRenderer::bounced_fields(std::span<const PreparedLight> lights, const std::vector<uint32_t>& also_direct,
                                                std::vector<float>& direct, CallProgress* progress) {
  const MultiBounce* multi = multi_bounce(progress);
  if (!multi) return {};
  std::vector<uint32_t> entries;
  entries.reserve(multi->vertex_sides_read().size() + also_direct.size());
  std::set_union(multi->vertex_sides_read().begin(), multi->vertex_sides_read().end(), also_direct.begin(), also_direct.end(),
                 std::back_inserter(entries));
  // Its estimate counted every side of every vertex.
  const double v = double(m_scene->positions.size()), l = double(lights.size());
  if (progress && progress->stage()) progress->stage()->advance(std::max(0.0, 2.0 * v - double(entries.size())) * l);
  direct = vertex_direct_irradiance(lights, entries, progress);
  const int steps = multi->expected_steps();
  CallProgress::Phase phase(progress, "bouncing the light on", steps,
                            double(steps) * l * 2.0 * v * m_settings.transport_samples / kReadsPerRay);
  return multi->bounced_field(direct, lights.size(), phase.stage());
}

std::string EmbreeRenderer::settings_key() const {
  // A cache on disk holds responses of one model: a key changes with it
  // ("patches=planes": every cell's patches, not only hot ones).
  std::string further;
  if (m_settings.further_bounces()) {
    further = "/transport_samples=" + std::to_string(m_settings.transport_samples);
    if (m_settings.bounce_rest_share != BounceSeriesSum::kRestShare) further += "/rest_share=" + std::to_string(m_settings.bounce_rest_share);
  }
  return "embree/bounces=" + bounces_text(m_settings.bounces) + further + "/samples=" + std::to_string(m_settings.bounce_samples) +
         "/seed=" + std::to_string(m_settings.seed) + "/vertex_bounce=" + std::to_string(m_settings.vertex_interpolated_bounce) +
         "/hot_spots=" + std::to_string(m_settings.hot_spots) + (m_settings.hot_spots ? "/patches=planes" : "");
}

std::vector<float> EmbreeRenderer::vertex_direct_irradiance(std::span<const PreparedLight> lights,
                                                           const std::vector<uint32_t>& vertex_sides, CallProgress* progress) {
  // Two values per vertex and light: the side its normal points to, the
  // other; only those the gather reads are computed (the rest stay 0).
  const Scene& scene = *m_scene;
  const size_t v_count = scene.positions.size();
  std::vector<float> out(2 * v_count * lights.size());
  tbb::combinable<uint64_t> rays([] { return uint64_t(0); });
  CallProgress::Phase phase(progress, "direct light at the vertices", double(vertex_sides.size()),
                            double(vertex_sides.size()) * double(lights.size()));
  tbb::parallel_for(tbb::blocked_range<size_t>(0, vertex_sides.size(), 128), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t j = 0; j < lights.size(); ++j)
      for (size_t k = r.begin(); k != r.end(); ++k) {
        const uint32_t entry = vertex_sides[k], v = entry / 2;
        const ShadingPoint& p = m_vertex_shading[v];
        const Vec3& n = scene.normals[v];
        out[j * 2 * v_count + entry] = unit_direct_irradiance_on_side(*m_embree, p, n, entry & 1 ? -n : n, lights[j], rays.local());
      }
    phase.advance(double(r.size()));
  });
  m_rays += rays.combine(std::plus<uint64_t>());
  return out;
}

std::vector<HotSpots> EmbreeRenderer::hot_spots_of(std::span<const PreparedLight> lights) {
  std::vector<HotSpots> out;
  if (!m_settings.hot_spots || m_settings.bounces == 0) return out;
  uint64_t cast = 0;
  out.reserve(lights.size());
  for (const auto& light : lights) out.emplace_back(*m_embree, light, /*every_cell=*/!m_settings.vertex_interpolated_bounce, cast);
  m_rays += cast;
  return out;
}

template <class Visit>
void EmbreeRenderer::for_each_response(const SurfacePoints& points, std::span<const Light> lights, Transport transport,
                                       Visit&& visit) {
  if (!m_embree) throw std::logic_error("EmbreeRenderer: set_scene was not called");
  // Each light's bounced field takes ~80 bytes a scene vertex while it is
  // iterated: lights go in groups that keep that under 128 MB (at 512 MB a
  // furnished flat of 258k vertices peaked at 1.36 GB in a solve), and of
  // at most 64 lights. A group's walks over the hits serve its lights
  // together, so groups much smaller cost time (the bench building's cache
  // build: 2 lights a group 16.5 s, 5 lights 14.1 s, 11 lights 12.8 s); a
  // group larger than the walks' blocks of 16 lights gains nothing, while
  // in a small scene 128 MB is more than the rest of a solve (the bundled
  // room's every-bounce solve took 1.22× one bounce's memory; with at most
  // 64 lights 1.18×). The bits are the same in any group (40 lights in the
  // room, one group or two).
  size_t group = lights.size();
  if (m_settings.further_bounces() && transport != Transport::DirectOnly)
    group = std::clamp<size_t>(size_t(128e6 / (80.0 * double(std::max<size_t>(1, m_scene->positions.size())))), 1, kMaxGroup);
  // The call's ray casts, for its progress: the gather (unless kept), the
  // further bounces' transport for each group, the points' own rays.
  const bool bounce = m_settings.bounces != 0 && transport != Transport::DirectOnly;
  // The point set's key (a hash of its contents) once a call: it finds the
  // gather, the shading points and the visibility memo kept for it.
  const uint64_t key = points.content_key();
  double rays = gather_rays(points, key, bounce) + double(points.size()) * double(lights.size()) * point_rays(transport);
  for (size_t j0 = 0; j0 < lights.size(); j0 += group) rays += further_rays(std::min(group, lights.size() - j0), bounce);
  CallProgress progress(rays);
  for (size_t j0 = 0; j0 < lights.size(); j0 += group)
    for_each_response_group(points, key, lights.subspan(j0, std::min(group, lights.size() - j0)), transport,
                            [&](size_t i, size_t j, const Rgb& r) { visit(i, j0 + j, r); }, &progress);
}

double EmbreeRenderer::point_rays(Transport transport) const {
  const bool direct = transport != Transport::IndirectOnly, bounce = m_settings.bounces != 0 && transport != Transport::DirectOnly;
  // Each gather hit's shadow ray toward the light, unless read from the vertices.
  return (direct ? 1.0 : 0.0) + (bounce ? (m_settings.vertex_interpolated_bounce ? 1.0 : double(m_settings.bounce_samples)) : 0.0);
}

template <class Visit>
void EmbreeRenderer::for_each_response_group(const SurfacePoints& points, uint64_t key, std::span<const Light> lights, Transport transport,
                                             Visit&& visit, CallProgress* progress) {
  std::vector<PreparedLight> prepared(lights.begin(), lights.end());
  const bool want_direct = transport != Transport::IndirectOnly;
  std::shared_ptr<const BounceGather> gather_owner;
  if (m_settings.bounces != 0 && transport != Transport::DirectOnly) gather_owner = gather_for(points, key, progress);
  const BounceGather* gather = gather_owner.get();
  std::vector<float> vertex_direct;
  std::vector<Rgb> bounced;  // the light bounced once or more, at the vertices (more than one bounce)
  if (gather) {
    const std::vector<uint32_t> none, &direct_read = m_settings.vertex_interpolated_bounce ? gather->vertex_sides_read() : none;
    bounced = bounced_fields(prepared, direct_read, vertex_direct, progress);
    if (bounced.empty() && m_settings.vertex_interpolated_bounce) vertex_direct = vertex_direct_irradiance(prepared, direct_read);
  }
  const size_t v_count = m_scene->positions.size();
  auto shading_owner = want_direct || gather ? shading_points(points, key) : nullptr;
  const std::vector<HotSpots> hot = gather ? hot_spots_of(prepared) : std::vector<HotSpots>();
  tbb::combinable<uint64_t> rays([] { return uint64_t(0); });
  // Points in chunks, lights inside: neighbouring points' rays toward one
  // light are coherent, and the chunk's data stays in cache across lights.
  // Small batches (one light over a few thousand samples, the refinement's
  // staple) get few, large chunks: task scheduling would cost more than rays.
  const size_t work = points.size() * std::max<size_t>(1, lights.size());
  const size_t grain = work < 200000 ? std::max<size_t>(32, points.size() / 8) : 32;
  CallProgress::Phase phase(progress, "lighting the points", double(points.size()),
                            double(points.size()) * double(prepared.size()) * point_rays(transport));
  // The interpolated bounce walks each point's gather hits once for a block
  // of lights (BounceGather::kLightBlock), reading the lights' direct light
  // at a vertex side together: vertex_direct turned to [vertex side][light].
  const bool interpolated = gather && m_settings.vertex_interpolated_bounce;
  const size_t l_count = prepared.size();
  // With further bounces and no patches of light, a hit's direct light and
  // its light bounced again are read at the same hit with the same weights:
  // one field of both, one walk over the hits (the same light, rounded
  // once per hit rather than once per walk).
  const bool merged = interpolated && !bounced.empty() &&
                      std::none_of(hot.begin(), hot.end(), [](const HotSpots& h) { return !h.empty(); });
  // Otherwise per vertex side and block, whether any of the block's lights
  // reaches it (a hit on dark corners only is passed by).
  std::vector<float> direct_by_side;
  std::vector<uint8_t> lit;
  const size_t blocks = (l_count + BounceGather::kLightBlock - 1) / BounceGather::kLightBlock;
  if (merged) {
    tbb::parallel_for(size_t(0), 2 * v_count, [&](size_t entry) {
      for (size_t j = 0; j < l_count; ++j) bounced[entry * l_count + j] += Rgb(vertex_direct[j * 2 * v_count + entry]);
    });
    std::vector<float>().swap(vertex_direct);
  } else if (interpolated) {
    direct_by_side.resize(vertex_direct.size());
    lit.assign(2 * v_count * blocks, 0);
    tbb::parallel_for(size_t(0), 2 * v_count, [&](size_t entry) {
      for (size_t j = 0; j < l_count; ++j) {
        const float e = vertex_direct[j * 2 * v_count + entry];
        direct_by_side[entry * l_count + j] = e;
        lit[entry * blocks + j / BounceGather::kLightBlock] |= uint8_t(e != 0.f);
      }
    });
    if (bounced.empty()) std::vector<float>().swap(vertex_direct);
  }
  // Which points see each point-like light's place, kept across calls.
  std::vector<std::shared_ptr<VisibilityMemo::Answers>> sees(l_count);
  if (want_direct) {
    for (size_t j = 0; j < l_count; ++j)
      if (!prepared[j].extended()) sees[j] = m_visibility.get(key, points.size(), prepared[j].position);
  }
  std::vector<const HotSpots*> hot_of(l_count, nullptr);
  for (size_t j = 0; j < hot.size(); ++j) hot_of[j] = &hot[j];
  tbb::combinable<std::vector<Rgb>> indirect_buffer, further_buffer;
  constexpr size_t kChunk = 32;  // points whose bounce is gathered before the lights' loop
  tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), grain), [&](const tbb::blocked_range<size_t>& range) {
    uint64_t& local_rays = rays.local();
    std::vector<Rgb>& indirect = indirect_buffer.local();
    std::vector<Rgb>& further = further_buffer.local();  // the light bounced twice or more, per point and light
    for (size_t begin = range.begin(); begin < range.end(); begin += kChunk) {
      const size_t end = std::min(range.end(), begin + kChunk);
      if (!bounced.empty()) {
        further.resize((end - begin) * l_count);
        for (size_t i = begin; i != end; ++i)
          gather->field_irradiance(i, BounceGather::kBothSides, bounced.data(), l_count, &further[(i - begin) * l_count]);
      }
      if (interpolated && !merged) {
        indirect.resize((end - begin) * l_count);
        for (size_t i = begin; i != end; ++i)
          for (size_t j0 = 0; j0 < l_count; j0 += BounceGather::kLightBlock)
            gather->interpolated_indirect_irradiance(i, &direct_by_side[j0], l_count, std::min(BounceGather::kLightBlock, l_count - j0),
                                                     &hot_of[j0], &lit[j0 / BounceGather::kLightBlock], blocks,
                                                     (*shading_owner)[i].position, &indirect[(i - begin) * l_count + j0]);
      }
      for (size_t j = 0; j < prepared.size(); ++j) {
        const PreparedLight& light = prepared[j];
        for (size_t i = begin; i != end; ++i) {
          const Vec3& n = points.normals[i];
          Rgb e(want_direct ? unit_direct_irradiance(*m_embree, (*shading_owner)[i], n, n, light, local_rays,
                                                     sees[j] ? &(*sees[j])[i] : nullptr)
                            : 0.f);
          if (gather) {
            const ShadingPoint& at = (*shading_owner)[i];
            const HotSpots* h = hot_of[j];
            if (interpolated) {
              if (!merged) e += indirect[(i - begin) * l_count + j];
              // The patches' light without its shadow first: where it is 0
              // (the point behind or near every patch) no shadow ray can change it.
              if (h && !h->empty()) {
                const Rgb seen = h->irradiance_seen(at, n, true);
                if (seen != Rgb(0.f) && h->sees_light(*m_embree, at, n, local_rays)) e += seen;
              }
            } else {
              e += gather->unit_indirect_irradiance(i, light, h, at.position, local_rays);
              if (h) e += h->irradiance(*m_embree, at, n, local_rays);
            }
            if (!bounced.empty()) e += further[(i - begin) * l_count + j];
          }
          visit(i, j, points.albedo[i] * float(1.0 / kPi) * e);
        }
      }
    }
    phase.advance(double(range.size()));
  });
  m_rays += rays.combine(std::plus<uint64_t>());
}

std::vector<Rgb> EmbreeRenderer::illuminate(const SurfacePoints& points, std::span<const Light> lights) {
  m_rays = 0;
  std::vector<Rgb> out(points.size(), Rgb(0.f));
  // Each point is owned by exactly one task, so the += below does not race.
  for_each_response(points, lights, Transport::All, [&](size_t i, size_t j, const Rgb& r) { out[i] += lights[j].intensity * r; });
  return out;
}

std::vector<Rgb> EmbreeRenderer::unit_responses(const SurfacePoints& points, std::span<const Light> lights,
                                                Transport transport) {
  m_rays = 0;
  std::vector<Rgb> out(points.size() * lights.size());
  const size_t m = points.size();
  for_each_response(points, lights, transport, [&](size_t i, size_t j, const Rgb& r) { out[j * m + i] = r; });
  return out;
}

Image EmbreeRenderer::render_image(const Camera& camera, std::span<const Light> lights, int width, int height) {
  if (!m_embree) throw std::logic_error("EmbreeRenderer: set_scene was not called");
  m_rays = 0;
  const Scene& scene = *m_scene;
  // Indirect irradiance at the vertices, interpolated across each triangle;
  // direct light is exact per pixel so shadow edges stay sharp.
  const std::vector<PreparedLight> prepared(lights.begin(), lights.end());
  std::vector<Rgb> vertex_indirect;
  const bool bounce = m_settings.bounces != 0;
  const SurfacePoints vertices = bounce ? SurfacePoints::from_vertices(scene) : SurfacePoints();
  const double light_count = double(prepared.size()), pixel_rays = double(width) * height * (1.0 + light_count),
               vertex_rays = bounce ? double(vertices.size()) * light_count * m_settings.bounce_samples : 0.0;
  const uint64_t vertices_key = bounce ? vertices.content_key() : 0;
  CallProgress progress(
                        gather_rays(vertices, vertices_key, bounce) + further_rays(prepared.size(), bounce) + vertex_rays + pixel_rays);
  if (bounce) {
    auto gather_owner = gather_for(vertices, vertices_key, &progress);
    const BounceGather& gather = *gather_owner;
    const std::vector<HotSpots> hot = hot_spots_of(prepared);
    std::vector<float> unused;
    const std::vector<Rgb> bounced = bounced_fields(prepared, {}, unused, &progress);
    vertex_indirect.assign(vertices.size(), Rgb(0.f));
    tbb::combinable<uint64_t> rays([] { return uint64_t(0); });
    CallProgress::Phase phase(&progress, "bounce light at the vertices", double(vertices.size()), vertex_rays);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, vertices.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
      std::vector<Rgb> further(bounced.empty() ? 0 : prepared.size());  // the light bounced twice or more, per light
      for (size_t i = r.begin(); i != r.end(); ++i) {
        if (!bounced.empty()) gather.field_irradiance(i, BounceGather::kBothSides, bounced.data(), prepared.size(), further.data());
        for (size_t j = 0; j < prepared.size(); ++j) {
          const HotSpots* h = hot.empty() ? nullptr : &hot[j];
          const ShadingPoint& at = m_vertex_shading[i];
          Rgb e = gather.unit_indirect_irradiance(i, prepared[j], h, at.position, rays.local());
          if (h) e += h->irradiance(*m_embree, at, scene.normals[i], rays.local());
          if (!bounced.empty()) e += further[j];
          vertex_indirect[i] += prepared[j].intensity * e;
        }
      }
      phase.advance(double(r.size()));
    });
    m_rays += rays.combine(std::plus<uint64_t>());
  }
  Image image(width, height);
  const Camera::Basis b = camera.basis();
  const float aspect = float(width) / float(height);
  tbb::combinable<uint64_t> rays([] { return uint64_t(0); });
  CallProgress::Phase phase(&progress, "shading the pixels", double(height), pixel_rays);
  tbb::parallel_for(tbb::blocked_range<int>(0, height, 4), [&](const tbb::blocked_range<int>& rows) {
    uint64_t& local_rays = rays.local();
    for (int y = rows.begin(); y != rows.end(); ++y)
      for (int x = 0; x < width; ++x) {
        float sx = (2.f * (float(x) + 0.5f) / float(width) - 1.f) * b.tan_half_fov * aspect;
        float sy = (1.f - 2.f * (float(y) + 0.5f) / float(height)) * b.tan_half_fov;
        Vec3 dir = glm::normalize(b.forward + sx * b.right + sy * b.up);
        Hit hit = m_embree->intersect(camera.eye, dir);
        ++local_rays;
        if (!hit.valid()) continue;
        // Shaded as a vertex is (rendering model): the side of a light by the
        // shading normal, from the smooth surface over the facets.
        const ShadingPoint front = smooth_hit_point(*m_embree, hit, 1.f), back = smooth_hit_point(*m_embree, hit, -1.f);
        const Vec3 n = m_embree->hit_normal(hit);
        Rgb e(0.f);
        for (const auto& light : prepared) {
          const ShadingPoint& at = glm::dot(n, light.position - front.position) >= 0.f ? front : back;
          e += light.intensity * unit_direct_irradiance(*m_embree, at, n, n, light, local_rays);
        }
        if (!vertex_indirect.empty()) {
          const auto& tri = scene.triangles[hit.triangle];
          e += (1.f - hit.u - hit.v) * vertex_indirect[tri[0]] + hit.u * vertex_indirect[tri[1]] + hit.v * vertex_indirect[tri[2]];
        }
        image.at(x, y) = scene.triangle_albedo(hit.triangle) * float(1.0 / kPi) * e;
        image.covered[size_t(y) * width + x] = 1;
      }
    phase.advance(double(rows.size()));
  });
  m_rays += rays.combine(std::plus<uint64_t>());
  return image;
}

std::vector<std::pair<std::string, double>> EmbreeRenderer::baseline_figures(const SurfacePoints& points,
                                                                             std::span<const Light> lights) {
  if (!m_embree) throw std::logic_error("EmbreeRenderer: set_scene was not called");
  // The same shadow rays unit_responses casts at bounces=0, built up front so
  // that only rtcOccluded1 is timed: the ceiling φ can approach.
  struct Segment { Vec3 origin, dir; float tfar; };
  std::vector<PreparedLight> prepared(lights.begin(), lights.end());
  std::vector<Segment> segments;
  segments.reserve(points.size() * lights.size());
  const float eps = m_embree->epsilon();
  const auto shading = shading_points(points, points.content_key());  // where unit_responses starts its rays
  for (size_t i0 = 0; i0 < points.size(); i0 += 32)
    for (const auto& light : prepared)
      for (size_t i = i0; i < std::min(points.size(), i0 + 32); ++i) {
        Vec3 d = light.position - (*shading)[i].position;
        float dist = glm::length(d);
        if (dist <= eps) continue;
        Vec3 w = d / dist;
        const Vec3& n = points.normals[i];
        if (glm::dot(n, w) == 0.f || light.angular(-w) == 0.f) continue;
        segments.push_back({(*shading)[i].ray_start(w, glm::dot(n, w) >= 0.f ? n : -n, eps), w, dist - 2.f * eps});
      }
  tbb::combinable<uint64_t> blocked([] { return uint64_t(0); });
  auto start = std::chrono::steady_clock::now();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, segments.size(), 32 * prepared.size()), [&](const tbb::blocked_range<size_t>& r) {
    uint64_t& local = blocked.local();
    for (size_t s = r.begin(); s != r.end(); ++s) local += m_embree->occluded(segments[s].origin, segments[s].dir, segments[s].tfar);
  });
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {{"raw_occlusion_rays", double(segments.size())},
          {"raw_occlusion_seconds", seconds},
          {"raw_occlusion_rays_per_second", double(segments.size()) / seconds},
          {"raw_occluded_fraction", double(blocked.combine(std::plus<uint64_t>())) / double(std::max<size_t>(1, segments.size()))}};
}

} // namespace hilight::embree
