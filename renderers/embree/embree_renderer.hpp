#pragma once
/// The Embree renderer: direct light with shadow rays and the first bounce by
/// gathering (first_bounce.hpp). Parameters are in embree_plugin.cpp.
#include "hilight/ray_scene.hpp"
#include "first_bounce.hpp"
#include "keyed_lru.hpp"
#include "visibility_memo.hpp"
#include "multi_bounce.hpp"
#include "hilight/renderer.hpp"

#include "hilight/progress.hpp"

#include "hilight/bounce_series.hpp"

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>

namespace hilight::embree {

struct EmbreeSettings {
  int bounces = 1;           ///< 0: direct only; 1: plus the first diffuse bounce; N; kAllBounces
  int bounce_samples = 128;  ///< gather rays per point (even)
  int transport_samples = 32;  ///< gather rays per scene vertex for bounces after the first (even; multi_bounce.hpp)
  /// "All" adds the geometric rest once it is at most this share of the sum
  /// (BounceSeriesSum::kRestShare; the fast twin takes a looser one).
  double bounce_rest_share = BounceSeriesSum::kRestShare;
  bool hot_spots = true;     ///< near-light hot patches lit as virtual lights (hot_spots.hpp)
  uint64_t seed = 1;         ///< gather sample stream
  /// Direct light at the gather's hit points: exact shadow rays per hit, or
  /// interpolated across each hit triangle from its vertices (one shadow ray
  /// per scene vertex and light: much faster for many points, smooths shadow
  /// edges within a triangle).
  bool vertex_interpolated_bounce = false;
  /// Bounces after the first: the vertex transport (multi_bounce.hpp) is needed.
  bool further_bounces() const { return bounces != 0 && bounces != 1; }
};

/// A long call's progress (hilight/progress.hpp): one stage whose units are
/// ray casts, the estimate of each phase's time; each phase a part of it
/// that the loops inside advance by their own items. A short call (under
/// kReported rays) reports nothing.
class CallProgress {
public:
  static constexpr double kReported = 1e6;
  /// Unnamed: what the call is for is its caller's stage, what it does now its phase's.
  explicit CallProgress(double rays) {
    if (rays >= kReported) m_stage.emplace("", rays);
  }
  ProgressStage* stage() { return m_stage ? &*m_stage : nullptr; }

  class Phase {
  public:
    /// `items`: what the loops advance the phase by in all; `rays`: its share of the call.
    Phase(CallProgress* call, const char* name, double items, double rays)
        : m_call(call ? call->stage() : nullptr), m_rays(rays) {
      if (m_call && rays > 0) m_stage.emplace(name, items, rays);
    }
    ~Phase() {
      m_stage.reset();
      if (m_call) m_call->advance(m_rays);
    }
    Phase(const Phase&) = delete;
    Phase& operator=(const Phase&) = delete;
    ProgressStage* stage() { return m_stage ? &*m_stage : nullptr; }
    void advance(double items) {
      if (m_stage) m_stage->advance(items);
    }

  private:
    ProgressStage* m_call;
    double m_rays;
    std::optional<ProgressStage> m_stage;
  };

private:
  std::optional<ProgressStage> m_stage;
};

class EmbreeRenderer final : public Renderer {
public:
  explicit EmbreeRenderer(const EmbreeSettings& settings) : m_settings(settings) {}

  void set_scene(std::shared_ptr<const Scene> scene) override;
  std::vector<Rgb> illuminate(const SurfacePoints& points, std::span<const Light> lights) override;
  std::vector<Rgb> unit_responses(const SurfacePoints& points, std::span<const Light> lights,
                                  Transport transport = Transport::All) override;
  std::string settings_key() const override;
  Image render_image(const Camera& camera, std::span<const Light> lights, int width, int height) override;
  uint64_t rays_cast() const override { return m_rays.load(); }
  /// Drops the kept bounce gathers and shading points (results unchanged).
  void release_scratch() override {
    m_gathers.clear();
    m_shading_points.clear();
    m_visibility.clear();
  }
  std::vector<std::pair<std::string, double>> baseline_figures(const SurfacePoints& points,
                                                               std::span<const Light> lights) override;

private:
  /// The gather for `points` (`key`: their content_key()), reused while the same point set comes back.
  std::shared_ptr<const BounceGather> gather_for(const SurfacePoints& points, uint64_t key, CallProgress* progress = nullptr);
  /// Ray casts of the phases of a call over `points` (a light cache's
  /// blocks, a whole scene's vertices): what its progress is measured in.
  double gather_rays(const SurfacePoints& points, uint64_t key, bool bounce);
  double further_rays(size_t lights, bool bounce) const;
  /// Ray casts per point and light of the final loop.
  double point_rays(Transport transport) const;
  /// Where each point is shaded (hilight::shading_point), per point set.
  std::shared_ptr<const std::vector<ShadingPoint>> shading_points(const SurfacePoints& points, uint64_t key);
  /// Calls visit(i, j, unit RGB response) for every point i and light j, in
  /// parallel over points; lights in groups whose bounced fields fit in memory.
  static constexpr size_t kMaxGroup = 64;  ///< lights transported together at most (for_each_response)
  template <class Visit>
  void for_each_response(const SurfacePoints& points, std::span<const Light> lights, Transport transport, Visit&& visit);
  template <class Visit>
  void for_each_response_group(const SurfacePoints& points, uint64_t key, std::span<const Light> lights, Transport transport, Visit&& visit,
                               CallProgress* progress);
  /// The operator of the bounces after the first (null at 0 or 1 bounce), built once.
  const MultiBounce* multi_bounce(CallProgress* progress = nullptr);
  /// Per light, the light bounced once or more at every (vertex, side)
  /// (MultiBounce::bounced_field); empty without further bounces. Also
  /// returns, through `direct`, e₀ at the entries `also_direct` lists (for
  /// the vertex mode, which reads it too).
  std::vector<Rgb> bounced_fields(std::span<const PreparedLight> lights, const std::vector<uint32_t>& also_direct,
                                  std::vector<float>& direct, CallProgress* progress = nullptr);
  /// Unit direct irradiance at scene vertices for each light, on each side
  /// (light-major; per vertex: normal side, then the other), computed for the
  /// entries in `vertex_sides` (BounceGather::vertex_sides_read), 0 elsewhere.
  std::vector<float> vertex_direct_irradiance(std::span<const PreparedLight> lights, const std::vector<uint32_t>& vertex_sides,
                                              CallProgress* progress = nullptr);
  /// Each light's hot patches (empty when hot_spots is off or there is no bounce).
  std::vector<HotSpots> hot_spots_of(std::span<const PreparedLight> lights);

  EmbreeSettings m_settings;
  std::shared_ptr<const Scene> m_scene;
  std::shared_ptr<const RayScene> m_embree;  ///< shared with every other user of the scene
  KeyedLru<BounceGather> m_gathers{4};
  KeyedLru<std::vector<ShadingPoint>> m_shading_points{4};
  VisibilityMemo m_visibility;
  std::vector<ShadingPoint> m_vertex_shading;  ///< shading_point() of every scene vertex
  std::once_flag m_multi_once;
  std::unique_ptr<MultiBounce> m_multi;
  std::atomic<bool> m_multi_built{false};  ///< m_multi is made (for progress estimates)
  std::atomic<uint64_t> m_rays{0};  ///< calls may come from several threads (concurrent refinements)
};

} // namespace hilight::embree
