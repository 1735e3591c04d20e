#pragma once
/// Adaptive refinement at shadow and spot edges (issue 11): per-vertex light
/// on the default tessellation shows shadows as blocky, dotted steps. Where
/// the direct light changes fast across a triangle (its vertices' values
/// differ by more than `contrast` of the brightest), the triangle's edges are
/// split at their midpoints — neighbours split the shared edge too, so the
/// mesh stays watertight — and the light is measured again on the new
/// vertices, pass after pass, until nothing changes fast, edges reach
/// `min_edge`, or the vertex budget is spent (the most contrasted triangles
/// first).
#include "hilight/lighting.hpp"
#include "hilight/scene.hpp"

#include <functional>
#include <memory>
#include <vector>

namespace hilight {

struct ShadowRefinementSettings {
  size_t vertex_budget = 0;  ///< most vertices in the result; 0: 4× the scene's
  float contrast = 0.3f;     ///< split when (max − min) > contrast × max over a triangle's vertices
  float min_edge = 0.f;      ///< never split an edge shorter than this; 0: the scene's max_edge / 16 (or diagonal / 1000)
  int passes = 8;            ///< at most this many rounds of measuring and splitting
};

/// The direct light (any unit: only its changes matter) at every vertex of a scene.
using VertexLight = std::function<std::vector<Rgb>(const std::shared_ptr<const Scene>& scene)>;

struct ShadowRefinementResult {
  std::shared_ptr<const Scene> scene;
  size_t split_edges = 0;  ///< new vertices
  int passes = 0;          ///< rounds that split something
};

/// The scene refined where `direct_light` changes fast; the input when nothing does.
ShadowRefinementResult refine_shadow_edges(std::shared_ptr<const Scene> scene, const VertexLight& direct_light,
                                           const ShadowRefinementSettings& settings = {});

} // namespace hilight
