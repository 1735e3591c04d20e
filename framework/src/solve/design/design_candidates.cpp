// The design's first steps: the places a luminaire may stand, and the
// linear program over them with its bound (design_steps.hpp).
#include "design_steps.hpp"

namespace hilight::design {

void place_candidates(DesignContext& ctx) {
  // The lattice over the area and the room, where a luminaire may stand and its outline clears the walls.
  const RoomFrame& room = ctx.room;
  const float step = ctx.step;
  Bounds lattice = ctx.area;
  for (float a : {room.u_lo, room.u_hi})
    for (float b : {room.v_lo, room.v_hi}) lattice.extend(room.at(a, b, ctx.plane));
  const Vec3 lo = lattice.lo - Vec3(step), e = lattice.extent() + Vec3(2.f * step);
  const int nx = int(std::floor(e.x / step)) + 1, nz = int(std::floor(e.z / step)) + 1;
  if (double(nx) * nz > 4e4) throw InputError("--candidate-spacing " + std::to_string(step) + " makes over 40,000 places: give a larger one");
  ctx.spins = distinct_spins(ctx.profile);
  if (ctx.spins.size() == 1 && std::abs(ctx.size[0] - ctx.size[1]) > 1e-4f) ctx.spins.push_back(90.f);  // an oblong outline fits either way
  std::vector<Place> candidates;
  for (int iz = 0; iz < nz; ++iz)
    for (size_t iy = 0; iy < ctx.layers.size(); ++iy)
      for (int ix = 0; ix < nx; ++ix) {
        const auto at = ctx.space.place(Vec3(lo.x + float(ix) * step, ctx.layers[iy], lo.z + float(iz) * step));
        if (!at || !ctx.space.admissible(*at)) continue;
        for (size_t s = 0; s < ctx.spins.size(); ++s) {
          const Place c{*at, ctx.spins[s], glm::ivec4(ix, int(iy), iz, int(s))};
          if (clear_of_walls(ctx.rays, footprint_of(ctx.light_at(c, 1.0), ctx.size))) candidates.push_back(c);
        }
      }
  if (candidates.empty())
    throw InputError("no place for a luminaire over the criteria's area (" + ctx.space.rules().describe() +
                     "): give --place rules that leave room");
  std::vector<Field> all_fields = ctx.render(candidates);
  for (size_t j = 0; j < candidates.size(); ++j)
    if (ctx.lights_some(all_fields[j])) {
      ctx.useful.push_back(candidates[j]);
      ctx.fields.push_back(std::move(all_fields[j]));
    }
  ctx.report.candidates = ctx.useful.size();
  if (ctx.useful.empty()) throw InputError("no place a luminaire may stand lights any of the criteria's points");
}

void set_up_program(DesignContext& ctx) {
  const DesignSettings& settings = ctx.settings;
  ctx.program.b = program_bounds(ctx.criteria, ctx.pts, ctx.margin, settings.cylindrical_min);
  for (const auto& f : ctx.fields) ctx.program.column.push_back(program_column(ctx.criteria, ctx.pts, ctx.margin, f));
  std::vector<Footprint> outlines;
  for (const auto& c : ctx.useful) outlines.push_back(footprint_of(ctx.light_at(c, 1.0), ctx.size));
  ctx.walker = std::make_unique<Walker>(ctx.program, ctx.useful, ctx.fields, std::move(outlines), settings.spacing, ctx.plane,
                                        ctx.observers.size());
  std::vector<size_t> all(ctx.useful.size());
  std::iota(all.begin(), all.end(), size_t(0));
  ctx.bound = ctx.walker->evaluate(all);
  ctx.report.least_flux_lm = ctx.bound.flux * ctx.rated;
  ctx.report.shortfall_lux = ctx.bound.shortfall;
  ctx.ugr_limit = settings.ugr_max > 0 ? settings.ugr_max * (1 - ctx.margin) : 0;
  ctx.least_count = std::max<size_t>(settings.min_count, 1);
  ctx.allowed = ctx.bound.flux * (1.0 + settings.energy_tolerance);
}

} // namespace hilight::design
