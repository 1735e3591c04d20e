#pragma once
/// Illuminance criteria instead of paint (issue 14 §3, after EN 12464-1):
/// grids of calculation points, each with the maintained mean illuminance
/// it needs (Ē ≥ lux) and the uniformity (U0 = Emin/Ē ≥ u0). A work plane
/// is a virtual surface at a height over the floor, facing up; walls and
/// ceilings are points on the scene's surfaces, facing into the room.
/// Illuminance is in lux, lengths in the scene's unit (metres).
#include "hilight/ray_scene.hpp"
#include "hilight/named_room.hpp"
#include "hilight/regions.hpp"
#include "hilight/surface_points.hpp"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace hilight {

struct CriterionGrid {
  enum class Kind { WorkPlane, Walls, Ceiling };
  std::string name;  ///< "workplane", "walls", "ceiling", or the user's
  Kind kind = Kind::WorkPlane;
  double lux = 0;      ///< Ē must reach this
  double u0 = 0;       ///< Emin/Ē must reach this (0: no uniformity asked)
  double spacing = 0;  ///< between points
  std::vector<Vec3> points;
  std::vector<Vec3> normals;  ///< unit: the illuminance is on the plane facing this way
};

struct IlluminanceCriteria {
  std::string source;  ///< file, for messages
  std::string length_unit = "m";  ///< of the points in the file: the scene file's (scene_origin.hpp)
  std::vector<CriterionGrid> grids;
  size_t size() const;  ///< points over every grid
  /// Every grid's points in grid order, with albedo 1: a renderer's radiance
  /// at such a point is E/π (irradiance over π), whatever the surface's albedo.
  SurfacePoints points() const;
};

/// EN 12464-1's grid spacing for an area whose longer side is `d` metres:
/// p = 0.2 · 5^log10(d), at most 10 m.
double en12464_spacing(double d);

/// Ē, Emin, U0 of one grid's illuminances (lux), and whether the grid's
/// criteria are met (within `tolerance`, relative).
struct GridFigures {
  double mean = 0, min = 0, max = 0, u0 = 0;
  bool met = false;
};
GridFigures grid_figures(const CriterionGrid& grid, std::span<const double> lux, double tolerance = 1e-3);

/// Illuminance in lux at points of albedo 1 from a renderer's radiance
/// there (W/(sr·m²), RGB): 683 · π · luminance.
std::vector<double> lux_from_radiance(std::span<const Rgb> radiance);

/// Where a grid lies: a region (a room, as `hilight info` numbers them), or
/// named rooms (an IFC's IfcSpaces, a storey's, or rooms split at doors:
/// named_room.hpp; in one of them), or a box, or (none) the whole scene.
struct GridArea {
  std::optional<int> region;
  std::vector<NamedRoom> rooms;
  std::optional<Bounds> box;
};

/// A work plane `height` over the floor under each point (the lowest
/// upward-facing surface in the area), points on a square grid of
/// `spacing` (0: EN 12464-1's for the area's longer side) at the cells'
/// centres, none within `border` of a wall (EN 12464-1's band of 0.5 m).
/// InputError when no point is left.
CriterionGrid make_work_plane(const RayScene& rays, const Regions& regions, const GridArea& area, float height, double lux,
                              double u0, double spacing = 0, float border = 0.5f);

/// The walls or the ceiling facing into the area: points on the scene's
/// triangles of that orientation (walls: within 30° of vertical; ceiling:
/// facing down) that some point of `plane` sees (the room's own surfaces,
/// not the far side of a wall or the inside of a cupboard), above the plane
/// (what stands below it is furniture, not the room), one per cell of
/// `spacing` (0: EN 12464-1's). InputError when no point is found.
CriterionGrid make_surface_grid(const RayScene& rays, const Regions& regions, const GridArea& area, CriterionGrid::Kind kind,
                                double lux, double u0, const CriterionGrid& plane, double spacing = 0);

/// EN 12464-1's immediate surround of a task whose maintained Ē is
/// `task_lux`: 500 lx for ≥ 750, 300 for ≥ 500, 200 for ≥ 300, else the task's.
double surround_lux(double task_lux);

/// EN 12464-1's zones around a task area (`task`, a box; `task_plane` its
/// work plane): the immediate surround, a band `surround_width` (0.5 m)
/// around it, Ē ≥ surround_lux(task) and U0 ≥ 0.40; the background, a band
/// `background_width` (3 m) beyond that, Ē ≥ a third of the surround's and
/// U0 ≥ 0.10. Work-plane points at `height` in the task's rooms, clear of
/// the walls by `border`, at EN 12464-1's spacing for each band's outer
/// side but at most half its width. A band with no point in the rooms is
/// left out (a task that fills its room has no background).
std::vector<CriterionGrid> make_zones(const RayScene& rays, const Regions& regions, const Bounds& task, const CriterionGrid& task_plane,
                                      float height, float border = 0.5f, float surround_width = 0.5f, float background_width = 3.f);

const char* to_string(CriterionGrid::Kind kind);

} // namespace hilight
