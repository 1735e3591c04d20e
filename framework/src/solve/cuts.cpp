#include "hilight/solve/cuts.hpp"

#include <algorithm>
#include <limits>

namespace hilight {

size_t CountRule::clamp(size_t k) const {
  if (min_count) k = std::max(k, min_count);
  if (max_count) k = std::min(k, max_count);
  return k;
}

std::vector<size_t> choose_cuts(const std::vector<double>& initial, const CountRule& rule) {
  if (rule.fixed_count > 0) return {rule.fixed_count};
  // The count bounds (--place count:MIN:MAX): only cuts inside them; when
  // none the automatic choice takes is inside, the nearest bound.
  std::vector<size_t> chosen = choose_cuts_unbounded(initial, rule), bounded;
  for (size_t k : chosen)
    if (rule.clamp(k) == k) bounded.push_back(k);
  if (bounded.empty() && !chosen.empty()) bounded.push_back(std::min(rule.clamp(chosen.front()), initial.size()));
  return bounded;
}

std::vector<size_t> choose_cuts_unbounded(const std::vector<double>& initial, const CountRule& rule) {
  const size_t n = initial.size();
  std::vector<size_t> chosen;
  for (size_t k = 1; k <= n && chosen.size() < rule.n_cut; ++k)
    if (initial[k - 1] < rule.eps_opt) chosen.push_back(k);
  if (!chosen.empty() || n == 0) return chosen;
  const double least = *std::min_element(initial.begin(), initial.end());
  size_t knee = 1;
  while (knee < n && initial[knee - 1] > rule.eps_impro * least) ++knee;
  for (size_t k = knee; k <= n && chosen.size() < rule.n_cut; ++k) chosen.push_back(k);
  return chosen;
}

namespace {
/// Cut k−1 is worth trying below cut k.
bool may_walk_down(const std::vector<double>& initial, size_t k, const CountRule& rule) {
  return k > 1 && k - 1 >= rule.min_count && initial[k - 2] < rule.eps_impro * rule.eps_opt;
}
} // namespace

FirstNeighbour first_neighbour(const std::vector<double>& initial, const std::vector<size_t>& chosen, const CountRule& rule) {
  if (rule.fixed_count > 0 || chosen.empty()) return FirstNeighbour::None;
  if (may_walk_down(initial, chosen.front(), rule)) return FirstNeighbour::Below;
  if (chosen.size() > 1 && chosen[1] == chosen.front() + 1) return FirstNeighbour::Above;
  return FirstNeighbour::None;
}

size_t walk_count(const std::vector<double>& initial, const std::vector<size_t>& chosen, const CountRule& rule,
                  const std::function<double(size_t)>& refined) {
  size_t count = chosen.front();
  refined(count);
  if (rule.fixed_count > 0) return count;
  // Beyond the paper: a cut's D̄ before refinement is pessimistic (its lights
  // sit where merging left them), so cuts just below the first one under
  // ε_opt may still be enough once refined.
  bool walked_down = false;
  while (may_walk_down(initial, count, rule)) {
    const double below = refined(count - 1), here = refined(count);
    if (!(here > 0) || below / here >= rule.eps_impro) break;
    --count;
    walked_down = true;
  }
  if (walked_down) return count;
  for (size_t q = 1; q < chosen.size() && chosen[q] == count + 1 && rule.clamp(count + 1) == count + 1; ++q) {
    const double here = refined(count);
    if (here < rule.visible_dbar) break;
    const double above = refined(count + 1);
    if (!(above > 0) || here / above < rule.eps_impro) break;
    ++count;
  }
  return count;
}

} // namespace hilight
