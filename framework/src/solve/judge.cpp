#include "hilight/solve/judge.hpp"

#include <algorithm>

namespace hilight {

bool Judge::spots_win(size_t n_spots, double d_spots, size_t n_points, double d_points) const {
  if (n_spots == 0 || !count_allowed(n_spots)) return false;
  if (n_spots == n_points) return d_spots < d_points;
  // Fewer spots than point lights: the extra point lights do not pay. Strict
  // here (fewer_will_do's tie goes to the fewer lights): the competition has
  // always been strict, and the point answer is the one already polished.
  if (n_spots < n_points) return d_spots < m_settings.eps_impro * d_points;
  return ratio_pays(d_points, d_spots);  // the extra lights pay
}

size_t Judge::max_spots() const { return max_lights() ? std::min(kMaxSpots, max_lights()) : kMaxSpots; }

Judge Judge::for_leaves(size_t leaves) const {
  JudgeSettings s = m_settings;
  if (s.fixed_count) s.fixed_count = std::min(s.fixed_count, leaves);
  else s.min_count = std::min(s.min_count, leaves);
  return Judge(s);
}

} // namespace hilight
