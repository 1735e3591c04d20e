#pragma once
/// Stopping a solve (issue 12: a stop token, not a throwing callback). A
/// Solver's public calls take a std::stop_token; once stop is requested the
/// Solver throws SolveCancelled at its next stage and its renderers (wrapped
/// in a StoppableRenderer) before their next batch of φ — the Solver asks
/// for φ many times per stage (seeding, every simplex step), so a stop takes
/// effect within one batch.
#include "hilight/renderer.hpp"

#include <stdexcept>
#include <stop_token>

namespace hilight {

/// Thrown out of a Solver's call whose stop token was requested.
class SolveCancelled : public std::runtime_error {
public:
  SolveCancelled() : std::runtime_error("solve cancelled") {}
};

/// Forwards every call to `inner`, first throwing SolveCancelled once `stop`
/// (a token its owner may replace between calls) has been requested.
class StoppableRenderer : public Renderer {
public:
  StoppableRenderer(Renderer& inner, const std::stop_token& stop) : m_inner(inner), m_stop(stop) {}

  void set_scene(std::shared_ptr<const Scene> scene) override { m_inner.set_scene(std::move(scene)); }
  std::vector<Rgb> illuminate(const SurfacePoints& points, std::span<const Light> lights) override;
  std::vector<Rgb> unit_responses(const SurfacePoints& points, std::span<const Light> lights,
                                  Transport transport = Transport::All) override;
  std::string settings_key() const override { return m_inner.settings_key(); }
  Image render_image(const Camera& camera, std::span<const Light> lights, int width, int height) override;
  uint64_t rays_cast() const override { return m_inner.rays_cast(); }
  void release_scratch() override { m_inner.release_scratch(); }
  std::vector<std::pair<std::string, double>> baseline_figures(const SurfacePoints& points,
                                                               std::span<const Light> lights) override {
    return m_inner.baseline_figures(points, lights);
  }

private:
  void check() const {
    if (m_stop.stop_requested()) throw SolveCancelled();
  }
  Renderer& m_inner;
  const std::stop_token& m_stop;
};

} // namespace hilight
