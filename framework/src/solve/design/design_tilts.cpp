// The design's tilts (--tilt-max): a free layout's luminaires tried tilted
// from their aim toward the room's four sides, by half and all of the
// largest tilt; a tilt is kept where the program then meets the criteria
// with fewer luminaires or less flux, the spacing and the UGR limit kept
// (coordinate descent, a light at a time; design_steps.hpp). A luminaire
// aimed straight down wastes light on the floor when a wall or a far
// corner is what the criteria ask for.
#include "design_steps.hpp"

namespace hilight::design {

namespace {

/// The aims a luminaire aimed along `aim` is tried at: its own first, then
/// tilted by half and all of `most` degrees toward ±u and ±v.
std::vector<Vec3> tilted_aims(const Vec3& aim, const RoomFrame& room, double most) {
  const Vec3 n = glm::normalize(aim);
  std::vector<Vec3> out = {n};
  for (const double degrees : {most / 2, most})
    for (const Vec3& side : {room.u, -room.u, room.v, -room.v}) {
      const Vec3 across = side - glm::dot(side, n) * n;
      if (glm::length(across) < 1e-3f) continue;  // aimed along that side already
      const float t = float(degrees * kPi / 180.0);
      out.push_back(glm::normalize(std::cos(t) * n + std::sin(t) * glm::normalize(across)));
    }
  return out;
}

} // namespace

void tilt_aims(DesignContext& ctx) {
  if (ctx.take_array || ctx.chosen_places.empty()) return;  // an array keeps its aims
  const size_t n = ctx.chosen_places.size();
  // Every luminaire's options, its own aim first (the layout as chosen).
  std::vector<Place> options;
  std::vector<size_t> first(n);
  for (size_t j = 0; j < n; ++j) {
    first[j] = options.size();
    const Place& at = ctx.chosen_places[j];
    for (const Vec3& aim : tilted_aims(ctx.light_at(at, 1.0).direction, ctx.room, ctx.settings.tilt_max_deg)) {
      Place p = at;
      p.aim = options.size() == first[j] ? Vec3(0.f) : aim;
      options.push_back(p);
    }
  }
  const std::vector<Field> fields = ctx.render(options);
  Program program;
  program.b = ctx.program.b;
  std::vector<Footprint> outlines;
  for (size_t k = 0; k < options.size(); ++k) {
    program.column.push_back(program_column(ctx.criteria, ctx.pts, ctx.margin, fields[k]));
    outlines.push_back(footprint_of(ctx.light_at(options[k], 1.0), ctx.size));
  }
  Walker walker(program, options, fields, std::move(outlines), ctx.settings.spacing, ctx.plane, ctx.observers.size());
  if (ctx.settings.fixed_count) walker.set_least_dimming(kLeastDimming);
  std::vector<size_t> choice = first;
  Layout best = walker.evaluate(choice);
  const auto better = [&](const Layout& l) {
    if (!l.as_met_as(best) || !walker.feasible(l) || !ctx.ugr_ok(l.ugr) || !ctx.count_ok(l.lights.size())) return false;
    return l.lights.size() < best.lights.size() || (l.lights.size() == best.lights.size() && l.flux < best.flux * (1 - 1e-4));
  };
  for (int pass = 0; pass < 2; ++pass) {
    bool changed = false;
    for (size_t j = 0; j < n; ++j) {
      const size_t options_of_j = (j + 1 < n ? first[j + 1] : options.size()) - first[j];
      for (size_t o = 0; o < options_of_j; ++o) {
        if (first[j] + o == choice[j]) continue;
        std::vector<size_t> trial = choice;
        trial[j] = first[j] + o;
        Layout l = walker.evaluate(trial);
        if (!better(l)) continue;
        choice = std::move(trial), best = std::move(l), changed = true;
      }
    }
    if (!changed) break;
  }
  ctx.report.tilted = 0;
  if (choice == first) return;  // no tilt paid
  // The program's layout: the lights it keeps lit, at its dimming.
  ctx.chosen_places.clear();
  ctx.chosen_dimming.clear();
  for (size_t k = 0; k < best.lights.size(); ++k) {
    ctx.chosen_places.push_back(options[best.lights[k]]);
    ctx.chosen_dimming.push_back(best.dimming[k]);
    ctx.report.tilted += options[best.lights[k]].aim != Vec3(0.f);
  }
  ctx.report.free.count = best.lights.size();
  ctx.report.free.flux_lm = best.flux * ctx.rated;
  ctx.report.free.power_w = best.flux * ctx.profile.input_watts;
  ctx.report.free.ugr = best.ugr;
}

} // namespace hilight::design
