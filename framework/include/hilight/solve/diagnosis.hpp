#pragma once
/// Why a fit is poor, where it can be told (issue 10 §4): painted light that
/// no allowed light position can reach.
#include "hilight/light_space.hpp"
#include "hilight/target.hpp"

namespace hilight {

/// Share of the target's weighted squared radiance on points that see no
/// place a light may stand (the free points of a 16-cell grid over the light
/// space, and places of their own in rooms that grid misses, under the
/// placement rules): light painted inside closed solids,
/// behind walls the rules keep lights out of. Up to `max_points` target
/// points, evenly spaced.
double unreachable_share(const Target& target, const LightSpace& space, size_t max_points = 4000);

} // namespace hilight
