#pragma once
/// The geometry of a luminaire layout (issue 34; docs/solve.md,
/// "Illuminance criteria"): a luminaire's footprint on the ceiling and the
/// spacing rules between two of them, the room a layout is drawn in (its
/// axes, its rectangle, its floor), the regular arrays of a room (rows ×
/// columns, or snapped to a ceiling grid), and the glare of a layout by the
/// CIE 117 formula (UGR) at the standard observer positions.
#include "hilight/illuminance_criteria.hpp"
#include "hilight/light_space.hpp"
#include "hilight/lighting.hpp"

#include <optional>
#include <string>
#include <map>
#include <vector>

namespace hilight {

/// A luminaire's outline seen from below: a rectangle `length` along
/// `axis` (its C0 plane, or an area source's `up`) and `width` across, on
/// the horizontal through `centre`. 0 × 0 for a point.
struct Footprint {
  Vec3 centre{0.f};
  Vec3 axis{1.f, 0.f, 0.f};  ///< unit, horizontal
  float length = 0.f, width = 0.f;
};

/// The luminous opening, metres (length along its C0 plane or `up`, width
/// across): an area source's own; a point-like luminaire's file's (a round
/// one: its diameter both ways); 0 × 0 when the file gives none. Its area
/// gives the luminance (UGR).
glm::vec2 luminous_opening(const Light& light);
/// The size a luminaire takes on the ceiling, the same way: the body where
/// the file gives one larger than the opening (EULUMDAT), else the opening.
/// Outlines, spacing and the fit in the room use it.
glm::vec2 luminaire_size(const Light& light);
/// Its outline where it stands (`size` from luminaire_size or the user's).
Footprint footprint_of(const Light& light, glm::vec2 size);
/// The horizontal direction of the light's length (C0, or an area source's `up`).
Vec3 length_axis(const Light& light);
/// The luminaire turned `degrees` about its aim (a luminaire's spin; an
/// area source's `up` and so its outline), as the design's places turn it.
Light turned(const Light& light, float degrees);

/// Spacing rules between luminaires: outlines never overlap (touching is
/// allowed), centres at least `min_spacing` apart.
struct SpacingRules {
  double min_spacing = 0;
  /// Spacing-to-height ratio: no luminaire farther from its nearest
  /// neighbour than this × its height over the work plane (0: none).
  double max_spacing_ratio = 0;
};
/// True when the two would break the rules (overlap, or centres too near).
bool too_close(const Footprint& a, const Footprint& b, const SpacingRules& rules);

/// The room a layout is drawn in: its axes (`u`, `v`: horizontal, the
/// sides of the smallest rectangle around the work plane), that rectangle
/// pushed out to the walls (`u_lo`..`u_hi` along u, `v_lo`..`v_hi` along v,
/// from the world origin), the floor, the work plane and the mount heights.
struct RoomFrame {
  Vec3 u{1.f, 0.f, 0.f}, v{0.f, 0.f, 1.f};
  float u_lo = 0, u_hi = 0, v_lo = 0, v_hi = 0;
  float floor_y = 0, plane_y = 0, mount_y = 0;
  double floor_area = 0;  ///< m²: the free floor of the rooms the criteria lie in
  float length() const { return u_hi - u_lo; }
  float width() const { return v_hi - v_lo; }
  /// World point at (a, b) in the room's axes, at height y.
  Vec3 at(float a, float b, float y) const { return a * u + b * v + Vec3(0.f, y, 0.f); }
};
/// `mount_y`: the height luminaires stand at over the area (the ceiling mount).
RoomFrame room_frame(const LightSpace& space, const IlluminanceCriteria& criteria, float mount_y);

/// A regular array: `rows` × `columns` (rows along v, columns along u)
/// at spacings `du`, `dv`, every luminaire turned `turn` degrees from the
/// template, all dimmed alike; `positions` where they stand.
struct ArrayLayout {
  int columns = 0, rows = 0;
  float du = 0, dv = 0, turn = 0;
  std::vector<Vec3> positions;  ///< fewer than columns × rows where the room's outline clips the grid
  std::string describe() const;  ///< "3 × 4 at 3.00 × 3.00 m", or "…, 10 in the room" when clipped
};

struct ArrayRules {
  glm::vec2 size{0.f};       ///< the luminaire's length and width (luminaire_size)
  SpacingRules spacing;
  float height_over_plane = 0;  ///< for the spacing-to-height ratio
  /// Snapped to a ceiling grid: centres in tiles of this size whose
  /// corners are at `grid_origin` + k·tile (world x, z); 0: no grid.
  double tile = 0;
  std::optional<glm::dvec2> grid_origin;
  size_t min_count = 1, max_count = 400;
  size_t exact_count = 0;  ///< 0: any count in [min, max]
};
/// Every array of the room with `count` luminaires (shapes whose spacings
/// differ by at most 2:1, or any shape for an exact count) that keeps the
/// rules, at each turn in `turns` (degrees from the template): aligned with
/// the room (each luminaire in the middle of its cell), or on the tiles of
/// the grid, centred in the room. Positions are moved onto the mount by
/// `space`; an array any of whose luminaires cannot stand there, or whose
/// outline would cross a wall, is left out — unless the room fills less
/// than kClippedFill of its rectangle (an L-shaped room): there a grid over
/// the rectangle keeps the places that fit and drops the rest, as a
/// designer draws one grid over the whole plan (`count` is then what is
/// kept, of up to 1.25·count/fill cells). `cache` (may be null) keeps the
/// grids' fits between calls for other counts.
constexpr double kClippedFill = 0.95;
struct ArrayFitCache;
std::vector<ArrayLayout> room_arrays(const LightSpace& space, const RoomFrame& room, const Light& luminaire, const ArrayRules& rules,
                                     const std::vector<float>& turns, size_t count, ArrayFitCache* cache = nullptr);
/// The places of each grid that fit (room_arrays), kept across counts.
struct ArrayFitCache {
  std::map<std::string, std::vector<Vec3>> fits;
};

/// True when the outline at `f` (at the mount height) stays clear of walls.
bool clear_of_walls(const RayScene& rays, const Footprint& f);

/// CIE 117's position index for a source at `sigma` degrees from the line
/// of sight and `tau` degrees from the vertical plane through it (the
/// Guth index in the closed form of Kim et al. 2009); 1 on the line of sight.
double guth_position_index(double tau_deg, double sigma_deg);

/// A UGR observer: eyes at `eye`, looking along `view` (horizontal).
struct GlareObserver {
  std::string name;
  Vec3 eye{0.f}, view{0.f, 0.f, -1.f};
};
/// CIE 117 / EN 12464-1's observers: seated (eyes `eye_height` over the
/// floor) at the middle of each side of the room, looking across it.
std::vector<GlareObserver> standard_observers(const RoomFrame& room, float eye_height = 1.2f);

/// One luminaire's glare terms at one observer at full output: `glare` =
/// L²·ω/p² (cd²/m⁴·sr), `direct_lux` = its direct illuminance on the eye
/// (vertical, facing the view). `area` is the luminous area (m²); luminance
/// is I/(area·cos γ) of a downward opening. Hidden or behind: zeros.
struct GlareTerms {
  double glare = 0, direct_lux = 0;
};
GlareTerms glare_terms(const RayScene& rays, const Light& full_output, double area, const GlareObserver& observer);

/// UGR = 8·log10(0.25/Lb · Σ L²ω/p²) with Lb = indirect illuminance at the
/// eye / π; NaN when no luminaire is in view (below 10: no glare to speak of).
double unified_glare_rating(double sum_glare, double indirect_lux);

} // namespace hilight
