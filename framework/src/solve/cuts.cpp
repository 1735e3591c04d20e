#include "hilight/solve/cuts.hpp"
#include "hilight/solve/judge.hpp"

#include <algorithm>
#include <limits>

namespace hilight {

namespace {
/// The rule's ε_impro and visibility floor as the Judge: the walk asks it,
/// as every other count decision does.
Judge judge_of(const CountRule& rule) {
  JudgeSettings s;
  s.eps_impro = rule.eps_impro;
  s.eps_opt = rule.eps_opt;
  s.n_cut = rule.n_cut;
  s.fixed_count = rule.fixed_count;
  s.min_count = rule.min_count;
  s.max_count = rule.max_count;
  s.visible_dbar = rule.visible_dbar;
  return Judge(s);
}
} // namespace

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
  // The knee: the first cut with which the best one's lights more do not pay.
  const Judge judge = judge_of(rule);
  const double least = *std::min_element(initial.begin(), initial.end());
  size_t knee = 1;
  while (knee < n && !judge.fewer_will_do(least, initial[knee - 1])) ++knee;
  for (size_t k = knee; k <= n && chosen.size() < rule.n_cut; ++k) chosen.push_back(k);
  return chosen;
}

namespace {
/// Cut k−1 is worth trying below cut k: a refinement rarely improves a cut
/// by more than ε_impro, so only a cut that may refine below ε_opt.
bool may_walk_down(const std::vector<double>& initial, size_t k, const CountRule& rule) {
  return k > 1 && k - 1 >= rule.min_count && !judge_of(rule).ratio_pays(initial[k - 2], rule.eps_opt);
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
  const Judge judge = judge_of(rule);
  // Beyond the paper: a cut's D̄ before refinement is pessimistic (its lights
  // sit where merging left them), so cuts just below the first one under
  // ε_opt may still be enough once refined.
  bool walked_down = false;
  while (may_walk_down(initial, count, rule)) {
    const double below = refined(count - 1), here = refined(count);
    // Eq. 9 downward: the smaller cut will do unless the light more paid.
    // (Was `below / here >= ε_impro` to stop: the same but at an exact tie,
    // which now goes to the fewer lights, as in every other count decision.)
    if (!(here > 0) || !judge.fewer_will_do(here, below)) break;
    --count;
    walked_down = true;
  }
  if (walked_down) return count;
  for (size_t q = 1; q < chosen.size() && chosen[q] == count + 1 && rule.clamp(count + 1) == count + 1; ++q) {
    const double here = refined(count);
    if (!judge.light_more_visible(here)) break;
    const double above = refined(count + 1);
    if (!(above > 0) || !judge.ratio_pays(here, above)) break;  // the ratio clause alone: cuts differ by one light each
    ++count;
  }
  return count;
}

} // namespace hilight
