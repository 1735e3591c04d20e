#pragma once
/// The immutable scene every stage works on: a tessellated triangle mesh with
/// per-vertex normals and one diffuse albedo per triangle (from its material).
#include "hilight/math.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace hilight {

struct Material {
  std::string name;
  Rgb albedo{0.8f};
};

/// A file's coordinates against hilight's (scene_origin.hpp).
struct SceneFrame {
  glm::dvec3 origin{0.0};  ///< in the file's unit: the scene was moved home by this
  double scale = 1.0;      ///< metres per file unit
  std::string unit = "m";  ///< the file's length unit: mm, cm, m, in or ft
  bool identity() const { return origin == glm::dvec3(0.0) && scale == 1.0; }
};

struct Scene {
  std::string source;                          ///< file it was loaded from (for messages)
  std::vector<Vec3> positions;                 ///< per vertex
  std::vector<Vec3> normals;                   ///< per vertex, unit length
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<uint32_t> triangle_material;     ///< per triangle, index into materials
  std::vector<Material> materials;
  Bounds bounds;

  size_t input_vertex_count = 0;               ///< before tessellation
  size_t input_triangle_count = 0;
  float max_edge = 0.f;                        ///< tessellation limit used
  /// Where the scene sits and its unit (scene_origin.hpp): positions in its
  /// file are `world`, inside hilight `local` = (world − origin) · scale,
  /// in metres near the origin. They cross at the file boundary.
  SceneFrame frame;

  /// The scene's size, which every relative tolerance is a share of
  /// (docs/rendering-model.md, "Tolerances"): the diameter of the smallest
  /// ball holding its vertices. For a box-shaped scene (a room) it is the
  /// diagonal of its box; unlike that diagonal it does not change when the
  /// scene is turned. Set by update_bounds().
  float diagonal() const { return size; }
  float size = 0.f;
  /// Where lights may stand: the bounds, except that an axis shorter than a
  /// quarter of the diagonal (a flat or open scene: a floor with low objects)
  /// is grown to half the diagonal so there is room for lights: on the side
  /// most of the surface area faces (above a floor), else on both sides, but
  /// never beyond a closed side (side_openness() under kOpenSide: a one-storey
  /// flat 16 m across keeps its floor and ceiling; light_bounds.hpp).
  Bounds light_bounds() const;
  Rgb triangle_albedo(size_t t) const { return materials[triangle_material[t]].albedo; }
  /// Albedo of a vertex: that of the first triangle using it (vertices are not
  /// shared across materials after loading, so this is unambiguous in practice).
  std::vector<Rgb> vertex_albedo() const;
  /// Unit geometric normal of triangle t (from its winding).
  Vec3 face_normal(size_t t) const;
  /// Calls `visit` with points spread over every triangle, closer than
  /// `spacing` apart (at most 256 steps along a triangle's edge): what a
  /// rasterisation of the surfaces into cells of twice that size needs.
  void for_each_surface_point(float spacing, const std::function<void(const Vec3&)>& visit) const;
  /// Recomputes bounds from positions.
  void update_bounds();
};

} // namespace hilight
