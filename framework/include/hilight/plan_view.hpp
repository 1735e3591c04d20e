#pragma once
/// Plans (issue 20): orthographic top views of a scene cut at a height, north
/// (−Z) up, as the solve's HTML report shows each storey; and the readout of
/// the lux below a light that the report and the painter's plan view print
/// beside each light's marker.
#include "hilight/image.hpp"
#include "hilight/ray_scene.hpp"

#include <optional>
#include <vector>

namespace hilight {

/// One storey's plan: what lies below `section`, seen from there.
struct PlanSection {
  float floor = 0.f;    ///< the storey's floor height
  float section = 0.f;  ///< where the plan cuts: rays start here, straight down
  float top = 0.f;      ///< the next storey's floor (lights below it belong to this storey)
};

/// The storeys of `scene`, lowest first, at most `most`: the heights where
/// large upward-facing areas lie (floors and slabs: at least a fifth of the
/// largest such area), 2 m apart at least, with room above them (a flat
/// roof's top is no storey). Each is cut 1.5 m over its floor, or halfway to
/// the next floor when that is nearer. With no such height: one section
/// over the whole scene (a product seen from above). Lengths in metres.
std::vector<PlanSection> plan_sections(const Scene& scene, size_t most = 4);

/// Pixels of a plan over an area's x–z extent (5% margin), square, at most
/// `max_width` by 2 × `max_width`.
struct PlanFrame {
  PlanFrame(const Bounds& area, int max_width);
  /// Where world point p falls, in pixels (x right, y down = +Z).
  glm::vec2 pixel_of(const Vec3& p) const { return {(p.x - x0) / pixel, (p.z - z0) / pixel}; }
  float x0 = 0.f, z0 = 0.f, pixel = 1.f;
  int width = 1, height = 1;
};

/// The plan of `section` in `frame`: each pixel the per-vertex `values`
/// blended at the first surface straight below the cut. A pixel whose ray
/// starts inside a solid (it meets a back face first: a wall cut through) is
/// covered, black, and marked in `cut` (one per pixel) when given; a pixel
/// over nothing stays uncovered.
Image plan_image(const RayScene& rays, const PlanFrame& frame, float section, const std::vector<Rgb>& values,
                 std::vector<uint8_t>* cut = nullptr);

/// Lux on the first surface below `p`, at that triangle's corner nearest the
/// hit: E = 683 · π · luminance(radiance / albedo) (a diffuse surface's
/// radiance is albedo/π · irradiance). nullopt with nothing below, no
/// radiance (`radiance` not one per vertex) or a black surface.
std::optional<double> lux_below(const RayScene& rays, const std::vector<Rgb>& radiance, const std::vector<Rgb>& albedo,
                                const Vec3& p);

/// Lux at every vertex, as lux_below reads it (0 on a black surface): what
/// a plan of illuminance shows (plan_image of these as grey values).
std::vector<Rgb> vertex_lux(const std::vector<Rgb>& radiance, const std::vector<Rgb>& albedo);

/// How far over a storey's floor a surface still counts as its floor (a rug, a step).
constexpr float kFloorTolerance = 0.3f;

/// Lux on the floor straight below `p` (issue 36): through whatever stands
/// over it — a table, a lamp's own fitting 2 cm below it — to the first
/// upward surface within kFloorTolerance of the storey's `floor` height,
/// blended from its triangle's corners. nullopt with no floor below (a
/// stairwell), no radiance, or a black floor.
std::optional<double> lux_on_floor(const RayScene& rays, const std::vector<Rgb>& radiance, const std::vector<Rgb>& albedo,
                                   const Vec3& p, float floor);

/// The floor of the storey `p` stands in (plan_sections): the highest storey
/// floor at or below p (the lowest when p is under every floor).
float storey_floor(const std::vector<PlanSection>& sections, const Vec3& p);

} // namespace hilight
