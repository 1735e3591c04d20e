#pragma once
/// Where a light may stand (issue 10): free space — inside the scene's light
/// bounds, out of solids — narrowed by the designer's placement rules. The
/// seeder, the refinement, the final polish and the solver's checks all ask
/// this one object. Scenes are +Y up.
#include "hilight/named_room.hpp"
#include "hilight/ray_scene.hpp"
#include "hilight/regions.hpp"

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hilight {

struct PlacementRules {
  /// Mounted this far below a ceiling: the first surface straight above that
  /// faces down and stands at least a quarter of the scene's height above the
  /// floor below (so not under a table). Lights are moved there (vertically).
  std::optional<float> ceiling_offset;
  float min_height = -std::numeric_limits<float>::infinity();  ///< y range
  float max_height = std::numeric_limits<float>::infinity();
  std::vector<Bounds> boxes;     ///< if any: inside one of them
  std::vector<Bounds> excluded;  ///< never inside these
  size_t min_count = 0, max_count = 0;  ///< point lights in the answer (0: no bound)
  std::vector<int> regions;      ///< if any: in one of these regions (hilight/regions.hpp)
  std::vector<int> not_regions;  ///< never in these regions
  /// region:NAME / not-region:NAME as given, until resolve_room_names()
  /// turns them into `rooms` / `not_rooms` (a LightSpace refuses names left).
  std::vector<std::string> region_names, not_region_names;
  std::vector<NamedRoom> rooms;      ///< if any: in one of these named rooms (an IfcSpace)
  std::vector<NamedRoom> not_rooms;  ///< never in these
  /// `anywhere`: the building default (lights on the ceiling, issue 34 §7)
  /// lifted; no rule of its own.
  bool anywhere = false;

  bool any() const;
  /// A rule that says at what height lights stand (ceiling, height, box or
  /// anywhere): a frontend's building default (on the ceiling) applies only
  /// without one; region, exclude and count keep it.
  bool says_where() const;
  /// As the CLI spells them, for messages ("ceiling:0.2 height:1:2.5").
  std::string describe() const;
  /// Parses one `--place` rule: ceiling[:OFFSET], height:MIN:MAX,
  /// box:X0,Y0,Z0,X1,Y1,Z1, exclude:X0,Y0,Z0,X1,Y1,Z1, count:MIN:MAX (or
  /// count:N), region:K, not-region:K (K as `hilight info` lists them, or
  /// a room's or storey's NAME), anywhere. Throws InputError.
  void add(const std::string& rule);
  /// region:NAME rules turned into `rooms` from the scene's named rooms (in
  /// the scene's frame). A name no room has: InputError naming it and the
  /// names there are.
  void resolve_room_names(const std::vector<NamedRoom>& scene_rooms);
};

class LightSpace {
public:
  /// `light_bounds`: where lights may stand before the rules; the scene's
  /// light_bounds() unless given (open_light_bounds() for a scene lit from
  /// outside). `regions`: the scene's rooms if already found (they do not
  /// depend on the bounds or the rules), else found here.
  LightSpace(const RayScene& rays, PlacementRules rules = {}, std::optional<Bounds> light_bounds = {},
             std::shared_ptr<const Regions> regions = nullptr);

  const PlacementRules& rules() const { return m_rules; }
  const RayScene& rays() const { return m_rays; }
  /// Where lights may stand before the rules (the box admissible() checks).
  const Bounds& light_bounds() const { return m_light_bounds; }
  /// Clearance from surfaces a candidate needs (so it lights more than the
  /// patch under it): `wanted`, but never more than half the ceiling offset.
  float clearance(float wanted) const;
  /// The box the seeding spreads candidates over: the light bounds narrowed
  /// by the height range and the allowed boxes.
  const Bounds& bounds() const { return m_bounds; }
  /// Where a light aimed at `p` stands: on the ceiling mount if that rule is
  /// set (moved vertically), else `p`; nothing if it cannot stand there.
  std::optional<Vec3> place(const Vec3& p) const;
  /// The rooms: connected parts of free space in the scene's light bounds.
  const Regions& regions() const { return *m_regions; }
  const std::shared_ptr<const Regions>& shared_regions() const { return m_regions; }
  /// `p` satisfies every rule and is free (in the light bounds, out of solids).
  bool admissible(const Vec3& p) const;
  /// Free space with room to spare, the light bounds and the rules aside:
  /// out of solids, and no surface nearer than `clearance`. What the light
  /// cache's nodes (node_is_free), the bench's probes and the fixtures'
  /// random lights ask; admissible() adds the bounds and the rules.
  static bool free_at(const RayScene& rays, const Vec3& p, float clearance) {
    return !rays.inside_solid(p) && !rays.closest_point(p, clearance).valid();
  }

private:
  bool satisfies_boxes_and_height(const Vec3& p) const;
  const RayScene& m_rays;
  PlacementRules m_rules;
  std::shared_ptr<const Regions> m_regions;
  Bounds m_light_bounds, m_bounds;
};

} // namespace hilight
