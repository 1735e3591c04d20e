#pragma once
/// The desired illumination Ψ: RGB radiance at points bound to the scene's
/// surface, with a weight per point (only points with weight > 0 are kept:
/// weight 0 means "don't care").
#include "hilight/ray_scene.hpp"
#include "hilight/surface_points.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace hilight {

/// Where a point lies on the scene: triangle and barycentrics (u for the
/// triangle's second vertex, v for its third).
struct SurfaceBinding {
  uint32_t triangle = 0;
  float u = 0.f, v = 0.f;
};

struct Target {
  std::string source;
  SurfacePoints points;                 ///< on the surface: position, shading normal, albedo
  std::vector<SurfaceBinding> binding;  ///< per point
  /// Per point: the scene vertex it stands for (shaded exactly as `hilight
  /// render` shades that vertex), or -1 for a point between vertices.
  std::vector<int32_t> vertex;
  std::vector<Rgb> value;               ///< Ψ per point, linear radiance
  std::vector<float> weight;            ///< > 0

  size_t size() const { return value.size(); }
  /// ‖Ψ‖ over the points, weighted: sqrt(Σ w |Ψ|²).
  double norm() const;
};

/// Fraction of the scene diagonal within which a target point must lie of the
/// surface to be bound to it.
constexpr float kTargetSurfaceTolerance = 1e-3f;
/// The largest target value taken (issue 35): a thousand times the sun's
/// disk in cd/m². Near float's limit (3e38) the solve's sums overflow and
/// its lights came out NaN; bind_target refuses such targets.
constexpr float kLargestTargetValue = 1e12f;

/// Reads a target PLY (red green blue as float = linear, or uchar = sRGB;
/// optional float weight; optional nx ny nz) and binds each point: to the
/// scene vertex it lies on (hilight/vertex_binding.hpp), else to the nearest
/// surface point. A .gltf/.glb is read the same way from its vertex colours
/// (COLOR_0, linear; weight from _WEIGHT or alpha; io/gltf.hpp).
/// Throws InputError naming the file and how many points are wrong.
Target read_target(const std::filesystem::path& path, const Scene& scene, const RayScene& rays);

/// Binds given positions to the scene (tests, painter): same rules.
/// `normals` (optional, may be empty) pick the right vertex or side at creases.
Target bind_target(const std::string& source, const std::vector<Vec3>& positions, const std::vector<Rgb>& values,
                   const std::vector<float>& weights, const Scene& scene, const RayScene& rays,
                   const std::vector<Vec3>& normals = {});

/// The target's values and weights per scene vertex (0 where no target point
/// stands for the vertex): for per-vertex outputs (glTF colours, reports).
void target_per_vertex(const Target& target, size_t vertex_count, std::vector<Rgb>& values, std::vector<float>& weights);

/// Per scene vertex: a triangle that uses it (the one whose plane agrees best
/// with the vertex normal) and the barycentrics of that corner.
std::vector<SurfaceBinding> vertex_triangles(const Scene& scene);

/// A point on the surface from its binding: position, shading normal, albedo.
void surface_point_at(const Scene& scene, const SurfaceBinding& b, Vec3& position, Vec3& normal, Rgb& albedo);

} // namespace hilight
