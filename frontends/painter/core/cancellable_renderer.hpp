#pragma once
/// A renderer that stops a solve between its batches: it forwards every call
/// to the renderer it wraps, but first throws SolveCancelled once the flag is
/// set. The Solver asks for φ many times per stage (seeding, every simplex
/// step of refinement), so a cancel takes effect within one batch, not only
/// at the Solver's next stage report.
#include "core/solve_job.hpp"

#include <atomic>

namespace hilight::painter {

class CancellableRenderer : public Renderer {
public:
  CancellableRenderer(Renderer& inner, const std::atomic<bool>& cancel) : m_inner(inner), m_cancel(cancel) {}

  void set_scene(std::shared_ptr<const Scene> scene) override { m_inner.set_scene(std::move(scene)); }
  std::vector<Rgb> illuminate(const SurfacePoints& points, std::span<const Light> lights) override;
  std::vector<Rgb> unit_responses(const SurfacePoints& points, std::span<const Light> lights,
                                  Transport transport = Transport::All) override;
  std::string settings_key() const override { return m_inner.settings_key(); }
  Image render_image(const Camera& camera, std::span<const Light> lights, int width, int height) override;
  uint64_t rays_cast() const override { return m_inner.rays_cast(); }
  std::vector<std::pair<std::string, double>> baseline_figures(const SurfacePoints& points,
                                                               std::span<const Light> lights) override {
    return m_inner.baseline_figures(points, lights);
  }

private:
  void check() const {
    if (m_cancel.load(std::memory_order_relaxed)) throw SolveCancelled();
  }
  Renderer& m_inner;
  const std::atomic<bool>& m_cancel;
};

} // namespace hilight::painter
