#pragma once
/// Paper §4.1, Fig. 4c: erase a shadow by clicking it.
///
/// find_shadow_pairs casts a ray from the clicked surface point to each light
/// that would otherwise reach it (in front of the surface, inside a spot's
/// cone) and reports the object each blocked ray hits first: the occluder–
/// light pairs that cast the shadow there. With several, the UI lets the
/// designer pick one.
///
/// Removing a pair's shadow: the paper hides the occluder, but hilight's
/// scene is the designer's geometry and stays as it is. Instead the painter
/// paints the wish into the target: every vertex that this occluder shadows
/// from this light gets the light's unshadowed direct contribution
/// (ρ/π · I · cos θ · S(α) / d², docs/rendering-model.md) added to its target
/// — its current target where painted, else its current illumination — and
/// is marked as cared for. A fine-tune or solve then moves the lights so the
/// shadow leaves the painted area (one undo step).
#include "core/document.hpp"
#include "core/region.hpp"
#include "core/scene_objects.hpp"
#include "hilight/renderer.hpp"

#include <cstdint>
#include <vector>

namespace hilight::painter {

struct ShadowPair {
  uint32_t occluder = 0;   ///< object id (SceneObjects)
  size_t light = 0;        ///< index into the lights
  Vec3 blocked_at{0.f};    ///< where the ray from the click to the light hit the occluder

  bool operator==(const ShadowPair&) const = default;
};

/// The pairs shadowing `click` (ordered by light index).
std::vector<ShadowPair> find_shadow_pairs(const SceneObjects& objects, const RayScene& rays, const Lighting& lights,
                                          const SurfacePick& click);

/// Vertices shadowed from `pair.light` by exactly `pair.occluder` (their ray to
/// the light hits that object first), and which the light would otherwise reach.
std::vector<uint32_t> shadowed_vertices(const SceneObjects& objects, const RayScene& rays, const Lighting& lights,
                                        const ShadowPair& pair);

/// Paints the pair's shadow away in the target (see above); returns the
/// vertices changed. `renderer`: bound to the scene, not in use elsewhere.
std::vector<uint32_t> erase_shadow(Document& document, const SceneObjects& objects, Renderer& renderer,
                                   const ShadowPair& pair);

} // namespace hilight::painter
