#pragma once
/// The smallest ball that holds a set of points (Welzl's randomized
/// incremental algorithm, in doubles). Its diameter is the scene's size: the
/// same however the scene is turned, and for a box-shaped scene the
/// diagonal of its box (docs/rendering-model.md, "Tolerances").
#include "hilight/math.hpp"

#include <vector>

namespace hilight {

struct Ball {
  DVec3 centre{0.0};
  double radius = -1.0;  ///< < 0: empty
};

/// The smallest enclosing ball of `points`; the points are visited in a
/// fixed pseudo-random order, so the result is repeatable.
Ball smallest_enclosing_ball(const std::vector<Vec3>& points);

} // namespace hilight
