#include "hilight/solve/cuts.hpp"
#include "hilight/solve/judge.hpp"

#include <algorithm>
#include <limits>

namespace hilight {


std::vector<size_t> choose_cuts(const std::vector<double>& initial, const Judge& judge) {
  if (judge.count_fixed()) return {judge.max_lights()};
  // The count bounds (--place count:MIN:MAX): only cuts inside them; when
  // none the automatic choice takes is inside, the nearest bound.
  std::vector<size_t> chosen = choose_cuts_unbounded(initial, judge), bounded;
  for (size_t k : chosen)
    if (judge.clamp_count(k) == k) bounded.push_back(k);
  if (bounded.empty() && !chosen.empty()) bounded.push_back(std::min(judge.clamp_count(chosen.front()), initial.size()));
  return bounded;
}

std::vector<size_t> choose_cuts_unbounded(const std::vector<double>& initial, const Judge& judge) {
  const size_t n = initial.size();
  std::vector<size_t> chosen;
  for (size_t k = 1; k <= n && chosen.size() < judge.n_cut(); ++k)
    if (initial[k - 1] < judge.eps_opt()) chosen.push_back(k);
  if (!chosen.empty() || n == 0) return chosen;
  // The knee: the first cut with which the best one's lights more do not pay.
  const double least = *std::min_element(initial.begin(), initial.end());
  size_t knee = 1;
  while (knee < n && !judge.fewer_will_do(least, initial[knee - 1])) ++knee;
  for (size_t k = knee; k <= n && chosen.size() < judge.n_cut(); ++k) chosen.push_back(k);
  return chosen;
}

namespace {
/// Cut k−1 is worth trying below cut k: a refinement rarely improves a cut
/// by more than ε_impro, so only a cut that may refine below ε_opt.
bool may_walk_down(const std::vector<double>& initial, size_t k, const Judge& judge) {
  return k > 1 && k - 1 >= judge.min_lights() && !judge.ratio_pays(initial[k - 2], judge.eps_opt());
}
} // namespace

FirstNeighbour first_neighbour(const std::vector<double>& initial, const std::vector<size_t>& chosen, const Judge& judge) {
  if (judge.count_fixed() || chosen.empty()) return FirstNeighbour::None;
  if (may_walk_down(initial, chosen.front(), judge)) return FirstNeighbour::Below;
  if (chosen.size() > 1 && chosen[1] == chosen.front() + 1) return FirstNeighbour::Above;
  return FirstNeighbour::None;
}

size_t walk_count(const std::vector<double>& initial, const std::vector<size_t>& chosen, const Judge& judge,
                  const std::function<double(size_t)>& refined) {
  size_t count = chosen.front();
  refined(count);
  if (judge.count_fixed()) return count;
  // Beyond the paper: a cut's D̄ before refinement is pessimistic (its lights
  // sit where merging left them), so cuts just below the first one under
  // ε_opt may still be enough once refined.
  bool walked_down = false;
  while (may_walk_down(initial, count, judge)) {
    const double below = refined(count - 1), here = refined(count);
    // Eq. 9 downward: the smaller cut will do unless the light more paid.
    // (Was `below / here >= ε_impro` to stop: the same but at an exact tie,
    // which now goes to the fewer lights, as in every other count decision.)
    if (!(here > 0) || !judge.fewer_will_do(here, below)) break;
    --count;
    walked_down = true;
  }
  if (walked_down) return count;
  for (size_t q = 1; q < chosen.size() && chosen[q] == count + 1 && judge.clamp_count(count + 1) == count + 1; ++q) {
    const double here = refined(count);
    if (!judge.light_more_visible(here)) break;
    const double above = refined(count + 1);
    if (!(above > 0) || !judge.ratio_pays(here, above)) break;  // the ratio clause alone: cuts differ by one light each
    ++count;
  }
  return count;
}

} // namespace hilight
