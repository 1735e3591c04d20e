// The design's arrays: rows × columns aligned with the room (or on a ceiling
// grid), the fewest first, one dimming for all (design_steps.hpp).
#include "design_steps.hpp"

namespace hilight::design {

void try_arrays(DesignContext& ctx) {
  const DesignSettings& settings = ctx.settings;
  const IlluminanceCriteria& criteria = ctx.criteria;
  const Points& pts = ctx.pts;
  const Program& program = ctx.program;
  const Layout& bound = ctx.bound;
  const RoomFrame& room = ctx.room;
  const Light& luminaire = ctx.luminaire;
  const glm::vec2 size = ctx.size;
  const std::vector<float>& spins = ctx.spins;
  const double margin = ctx.margin;
  const size_t lux_points = ctx.lux_points;
  const LightSpace& space = ctx.space;
  const size_t observer_count = ctx.observers.size();
  std::optional<ArrayResult>& array = ctx.array;
  ArrayRules rules;
  rules.size = size;
  rules.spacing = settings.spacing;
  rules.height_over_plane = ctx.mount_y - ctx.plane;
  rules.tile = settings.ceiling_grid;
  rules.grid_origin = settings.grid_origin;
  rules.exact_count = settings.fixed_count;
  // Turns that line the luminaire up with the room, as its symmetry tells them apart (and its outline).
  const Vec3 axis = length_axis(luminaire), nadir = glm::normalize(luminaire.direction);
  const float to_u = float(std::atan2(double(glm::dot(room.u, glm::cross(axis, nadir))), double(glm::dot(room.u, axis))) * 180.0 / kPi);
  std::vector<float> turns;
  for (int k = 0; k < 4; ++k)
    if (size_t(k) < spins.size() || (k == 1 && std::abs(size[0] - size[1]) > 1e-4f)) turns.push_back(to_u + 90.f * float(k));
  const auto evaluate = [&](ArrayResult& r) {
    // One dimming for all: Ē rows need x ≥ b/col; U0 rows need col ≥ 0 whatever x.
    const size_t rows = program.rows();
    Field sum;
    sum.lux.assign(lux_points, 0.0);
    for (const auto& f : r.fields) {
      for (size_t i = 0; i < sum.lux.size(); ++i) sum.lux[i] += f.lux[i];
      sum.cylindrical += f.cylindrical;
    }
    const std::vector<double> col = program_column(criteria, pts, margin, sum);
    double x = 0;
    for (size_t k = 0; k < rows; ++k)
      if (program.b[k] > 0) x = std::max(x, col[k] > 0 ? program.b[k] / col[k] : std::numeric_limits<double>::infinity());
    r.x = std::min(x, 1.0);
    if (settings.fixed_count) r.x = std::max(r.x, kLeastDimming);
    r.shortfall = 0;
    for (size_t k = 0; k < rows; ++k) r.shortfall += std::max(0.0, program.b[k] - r.x * col[k]);
    r.flux = r.x * double(r.fields.size());
    std::vector<const Field*> f;
    for (const auto& field : r.fields) f.push_back(&field);
    r.ugr = layout_ugr(f, std::vector<double>(r.fields.size(), r.x), observer_count);
    r.met = r.shortfall <= bound.shortfall * (1 + 1e-3) + 1e-6 && ctx.ugr_ok(r.ugr);
  };
  std::vector<ArrayResult> results;
  // Arrays of up to 400 luminaires (20 × 20) unless a count asks for more.
  constexpr size_t kMostInArray = 400;
  const size_t first = settings.fixed_count
                           ? settings.fixed_count
                           : std::clamp<size_t>(size_t(std::floor(0.85 * bound.flux)), ctx.least_count, std::max(ctx.least_count, kMostInArray));
  const size_t last = settings.fixed_count ? settings.fixed_count
                      : settings.max_count ? settings.max_count
                                           : std::min(std::max(first, kMostInArray), std::max<size_t>(first + 12, 3 * size_t(std::ceil(bound.flux)) + 8));
  size_t met_at = 0;
  ArrayFitCache fits;
  for (size_t n = std::max<size_t>(first, 1); n <= last && n <= 2000; ++n) {
    if (met_at && n > met_at + 4) break;
    std::vector<ArrayLayout> shapes = room_arrays(space, room, luminaire, rules, turns, n, &fits);
    if (shapes.empty()) continue;
    std::vector<Place> places;
    for (const auto& s : shapes)
      for (const Vec3& p : s.positions) places.push_back({p, s.turn});
    std::vector<Field> rendered = ctx.render(places);
    size_t at = 0;
    for (auto& s : shapes) {
      ArrayResult r;
      r.fields.assign(std::make_move_iterator(rendered.begin() + long(at)), std::make_move_iterator(rendered.begin() + long(at + s.positions.size())));
      at += s.positions.size();
      r.shape = std::move(s);
      evaluate(r);
      if (r.met && !met_at) met_at = n;
      results.push_back(std::move(r));
    }
  }
  // The fewest met whose flux is within the tolerance of the best met array's; else the least short.
  double least_met = std::numeric_limits<double>::infinity();
  for (const auto& r : results)
    if (r.met) least_met = std::min(least_met, r.flux);
  for (auto& r : results) {
    const bool pick = std::isfinite(least_met)
                          ? r.met && r.flux <= least_met * (1 + settings.energy_tolerance) &&
                                (!array || r.fields.size() < array->fields.size() ||
                                 (r.fields.size() == array->fields.size() && r.flux < array->flux))
                          : !array || r.shortfall < array->shortfall * (1 - 1e-9) ||
                                (r.shortfall <= array->shortfall * (1 + 1e-9) && r.flux < array->flux);
    if (pick) array = r;
  }
  ctx.report.array.tried = true;
}

} // namespace hilight::design
