#pragma once
/// Cuts of the light hierarchy and the light count (paper §3.3, eq. 9), as
/// pure functions of tables of D̄: which cuts to refine, and the walk that
/// picks the count. Cut k (1-based) holds k point lights; `initial[k-1]` is
/// its D̄ before refinement. Every decision is the Judge's (judge.hpp; a
/// hierarchy's own: Judge::for_leaves). Tested on tables (tests/test_cuts.cpp).
#include "hilight/solve/judge.hpp"

#include <cstddef>
#include <functional>
#include <vector>

namespace hilight {

/// The cuts to refine, in increasing count: the fixed one; else the first
/// N_cut with initial D̄ below ε_opt; else, when none is, N_cut from the
/// knee — the smallest cut within ε_impro of the best one (beyond it more
/// lights explain little more). Always within the count bounds.
std::vector<size_t> choose_cuts(const std::vector<double>& initial, const Judge& judge);
/// The same without the count bounds.
std::vector<size_t> choose_cuts_unbounded(const std::vector<double>& initial, const Judge& judge);

/// Whether the walk needs cut `count − 1` (true) or `count + 1` (false)
/// first, or neither: so the caller can refine it beside the first chosen cut.
enum class FirstNeighbour { None, Below, Above };
FirstNeighbour first_neighbour(const std::vector<double>& initial, const std::vector<size_t>& chosen, const Judge& judge);

/// The count, by eq. 9: start at the first chosen cut; walk down while the
/// smaller cut's refined D̄ is within ε_impro of the larger (only to cuts
/// whose initial D̄ is below ε_impro·ε_opt: a refinement rarely gains more);
/// if it did not walk down, walk up the chosen cuts while the next one
/// improves D̄ by ε_impro, never from below `visible_dbar`. `refined(k)`
/// refines cut k (once; the caller caches) and returns its D̄.
size_t walk_count(const std::vector<double>& initial, const std::vector<size_t>& chosen, const Judge& judge,
                  const std::function<double(size_t)>& refined);

} // namespace hilight
