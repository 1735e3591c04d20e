#pragma once
/// Why a fit is poor, where it can be told (issue 10 §4): painted light that
/// no allowed light position can reach.
#include "hilight/light_space.hpp"
#include "hilight/target.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace hilight {

/// What the diagnosis found: the share of the painted light no allowed place
/// sees, and which of the target points it looked at are those.
struct Unreachable {
  double share = 0;               ///< of the weighted squared radiance of the points looked at
  std::vector<uint32_t> points;   ///< indices into the target, in order
};

/// The target points (up to `max_points`, evenly spaced) that see no place a
/// light may stand (the free points of a 16-cell grid over the light space,
/// and places of their own in rooms that grid misses, under the placement
/// rules): light painted inside closed solids, behind walls the rules keep
/// lights out of.
Unreachable find_unreachable(const Target& target, const LightSpace& space,
                             size_t max_points = std::numeric_limits<size_t>::max());

/// find_unreachable's share over up to `max_points` points (the solve's estimate).
double unreachable_share(const Target& target, const LightSpace& space, size_t max_points = 4000);

} // namespace hilight
