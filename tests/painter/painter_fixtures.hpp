#pragma once
// Small scenes and helpers shared by the painter core's tests.
#include "core/document.hpp"
#include "core/solve_job.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "../support.hpp"

#include <memory>

namespace painter_test {

using namespace hilight;

struct World {
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const RayScene> rays;
  std::unique_ptr<painter::Document> document() const { return std::make_unique<painter::Document>(scene, rays); }
};

inline World make_world(Scene raw, float max_edge) {
  World w;
  w.scene = test::finish(std::move(raw), max_edge);
  w.rays = std::make_shared<const RayScene>(*w.scene);
  return w;
}

/// A 10 x 10 floor with boxes standing on it (each its own material = object).
inline World floor_with_boxes(const std::vector<std::pair<Vec3, Vec3>>& boxes, float max_edge = 0.4f) {
  Scene raw = builders::plane(5.f, Rgb(0.7f));
  int i = 0;
  for (const auto& [lo, hi] : boxes) builders::add_box(raw, lo, hi, Rgb(0.6f), false, "box" + std::to_string(i++));
  return make_world(std::move(raw), max_edge);
}

/// Solve settings that keep the tests quick (cache in memory only).
inline painter::SolveJobOptions quick_options() {
  painter::SolveJobOptions o;
  o.renderer_settings = {"bounce_samples=16"};
  o.settings.samples = 800;
  o.cache_settings = {"cells=6"};
  return o;
}

} // namespace painter_test
