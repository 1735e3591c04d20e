// The design's free layouts: the walk down from the program's lights (eq.
// 9's count walk has its own kind here: the fewest luminaires that meet the
// criteria within the energy tolerance), and the count asked for (design_steps.hpp).
#include "design_steps.hpp"

namespace hilight::design {

void walk_free_layouts(DesignContext& ctx) {
  const DesignSettings& settings = ctx.settings;
  DesignReport& report = ctx.report;
  Walker& walker = *ctx.walker;
  const Layout& bound = ctx.bound;
  Layout& free_layout = ctx.free_layout;
  bool& free_found = ctx.free_found;
  // Walk down from the program's lights.
  free_layout = bound;
  free_found = false;
  {
    std::optional<Layout> best, fallback;
    // Layouts of more luminaires than an array may have are walked through, not built.
    constexpr size_t kMostToBuild = 400;
    const auto consider = [&](const Layout& at) {
      if (at.lights.size() > kMostToBuild) return;
      Layout f = ctx.buildable(at);
      if (ctx.acceptable(f)) {
        report.walk.push_back({f.lights.size(), f.flux * ctx.rated});
        if (!best || f.lights.size() < best->lights.size() || (f.lights.size() == best->lights.size() && f.flux < best->flux)) best = f;
      }
      // Else the nearest to it: feasible, within the UGR limit if any is, as met as possible, then the least flux.
      if (walker.feasible(f) && ctx.count_ok(f.lights.size()) &&
          (!fallback || (ctx.ugr_ok(f.ugr) && !ctx.ugr_ok(fallback->ugr)) || (ctx.ugr_ok(f.ugr) == ctx.ugr_ok(fallback->ugr) && f.better_than(*fallback))))
        fallback = f;
    };
    Layout at = bound;
    const size_t least = size_t(std::ceil(bound.flux - 1e-9));
    while (at.lights.size() > 2 * least + 8) {  // coarsely while there are many
      std::vector<size_t> order(at.lights.size());
      std::iota(order.begin(), order.end(), size_t(0));
      std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return at.dimming[a] > at.dimming[b]; });
      std::vector<size_t> kept;
      for (size_t k = 0; k < order.size() - order.size() / 4; ++k) kept.push_back(at.lights[order[k]]);
      Layout next = walker.evaluate(kept);
      if (!ctx.relaxed(next)) break;
      at = std::move(next);
    }
    consider(at);
    int misses = 0;
    while (at.lights.size() > ctx.least_count && misses < 3) {
      at = walker.fewer(at);
      if (ctx.relaxed(at)) {
        consider(at);
        misses = 0;
      } else {
        ++misses;
      }
    }
    if (best) {
      // Move the chosen lights on the lattice, then see whether fewer still do.
      Layout chosen = walker.search(*best);
      if (!ctx.acceptable(chosen)) chosen = *best;
      while (chosen.lights.size() > ctx.least_count) {
        Layout next = ctx.buildable(walker.search(walker.fewer(chosen)));
        if (!ctx.acceptable(next)) break;
        chosen = std::move(next);
        report.walk.push_back({chosen.lights.size(), chosen.flux * ctx.rated});
      }
      free_layout = chosen;
      free_found = true;
      report.fewest_free = chosen.lights.size();
    } else if (fallback) {
      free_layout = *fallback;
      free_found = true;
    } else {  // nothing small enough to build was walked through (criteria far out of reach): the last, spread
      free_layout = walker.spread(at);
      free_found = true;
    }
    if (settings.max_count && free_layout.lights.size() > settings.max_count) {
      while (free_layout.lights.size() > settings.max_count) free_layout = ctx.buildable(walker.search(walker.fewer(free_layout)));
      free_found = true;
    }
  }
  report.free.tried = settings.layout != LayoutChoice::Array || settings.fixed_count;
  report.free.found = free_found;
}

void meet_count(DesignContext& ctx) {
  // --lights N: exactly N, walked down to or filled up to.
  Walker& walker = *ctx.walker;
  const size_t n = ctx.settings.fixed_count;
  Layout at = ctx.free_found && ctx.free_layout.lights.size() >= n ? ctx.free_layout : ctx.bound;
  while (at.lights.size() > n) at = walker.fewer(at);
  walker.set_least_dimming(kLeastDimming);
  at = walker.evaluate(ctx.buildable(at).lights);
  while (at.lights.size() < n) {
    const auto more = walker.farthest(at.lights);
    if (!more)
      throw InputError("--lights " + std::to_string(n) + ": only " + std::to_string(at.lights.size()) +
                       " luminaires fit where --place lets them stand with the spacing asked for (room " + ctx.room_size + ")");
    std::vector<size_t> lights = at.lights;
    lights.push_back(*more);
    at = walker.evaluate(lights);
  }
  ctx.free_layout = walker.search(at);
  ctx.free_found = true;
  walker.set_least_dimming(0);
  ctx.report.free.tried = true;
  ctx.report.free.found = true;
}

} // namespace hilight::design
