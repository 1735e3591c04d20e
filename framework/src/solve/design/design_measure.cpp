// The design's last step: the lights found, measured as `hilight render`
// would, with the standard's figures and why the criteria are not met
// where they could be (design_steps.hpp).
#include "design_steps.hpp"

namespace hilight::design {

void measure_lights(DesignContext& ctx) {
  const DesignSettings& settings = ctx.settings;
  DesignReport& report = ctx.report;
  const IlluminanceCriteria& criteria = ctx.criteria;
  const Points& pts = ctx.pts;
  const Layout& bound = ctx.bound;
  const std::optional<ArrayResult>& array = ctx.array;
  const RayScene& rays = ctx.rays;
  const RoomFrame& room = ctx.room;
  const std::vector<GlareObserver>& observers = ctx.observers;
  const std::vector<Place>& chosen_places = ctx.chosen_places;
  const std::vector<double>& chosen_dimming = ctx.chosen_dimming;
  const double mf = ctx.mf, margin = ctx.margin, rated = ctx.rated, luminous_area = ctx.luminous_area, ugr_limit = ctx.ugr_limit;
  const size_t lux_points = ctx.lux_points;
  const bool take_array = ctx.take_array;
  const Photometry& profile = ctx.profile;
  Lighting& lights = ctx.lights;
  // 6. The lights found, measured as `hilight render` would.
  for (size_t j = 0; j < chosen_places.size(); ++j) lights.push_back(ctx.light_at(chosen_places[j], chosen_dimming[j]));
  report.dimming = chosen_dimming;
  std::vector<double> lux = lux_from_radiance(ctx.reference.illuminate(pts.all, lights));
  std::vector<double> maintained(lux.begin(), lux.begin() + long(lux_points));
  for (double& v : maintained) v *= mf;
  report.lux.assign(maintained.begin(), maintained.begin() + long(pts.criteria));
  report.met = true;
  size_t first = 0;
  for (size_t g = 0; g < criteria.grids.size(); ++g) {
    const auto& grid = criteria.grids[g];
    GridFigures f = grid_figures(grid, std::span<const double>(report.lux.data() + first, grid.points.size()));
    double low = f.min;
    for (size_t i = 0; i < pts.between[g].second; ++i) low = std::min(low, maintained[pts.between[g].first + i]);
    report.min_whole.push_back(low);
    report.u0_whole.push_back(f.mean > 0 ? low / f.mean : 0);
    // With a margin: clear of the limits by it, Emin over the whole grid.
    f.met = f.mean >= grid.lux * (1 + margin) * (1 - 1e-3) && report.u0_whole.back() >= grid.u0 * (1 + margin) * (1 - 1e-3);
    report.figures.push_back(f);
    report.met = report.met && f.met;
    first += grid.points.size();
  }
  // Cylindrical illuminance at the eyes' height over the work planes' points, and the modelling.
  report.cylindrical.height = settings.eye_height();
  {
    SurfacePoints cyl;
    for (const Vec3& at : cylinder_places(rays, criteria, room.floor_y, float(report.cylindrical.height)))
      for (const Vec3& n : {kCylinderNormals[0], kCylinderNormals[1], kCylinderNormals[2], kCylinderNormals[3], Vec3(0, 1, 0)}) {
        cyl.positions.push_back(at);
        cyl.normals.push_back(n);
      }
    if (!cyl.positions.empty()) {
      cyl.albedo.assign(cyl.positions.size(), Rgb(1.f));
      const std::vector<double> ev = lux_from_radiance(ctx.reference.illuminate(cyl, lights));
      auto& c = report.cylindrical;
      c.points = ev.size() / 5;
      double sum = 0, horizontal = 0;
      c.min = std::numeric_limits<double>::max();
      for (size_t i = 0; i < c.points; ++i) {
        const double ez = mf * 0.25 * (ev[5 * i] + ev[5 * i + 1] + ev[5 * i + 2] + ev[5 * i + 3]);
        sum += ez;
        horizontal += mf * ev[5 * i + 4];
        c.min = std::min(c.min, ez);
      }
      c.mean = sum / double(c.points);
      c.u0 = c.mean > 0 ? c.min / c.mean : 0;
      c.modelling = horizontal > 0 ? sum / horizontal : 0;
    }
    report.cylindrical.wanted = settings.cylindrical_min;
    report.cylindrical.met = !(settings.cylindrical_min > 0) || report.cylindrical.mean >= settings.cylindrical_min * (1 + margin) * (1 - 1e-3);
    report.met = report.met && report.cylindrical.met;
  }
  report.ugr = kNaN;
  for (size_t o = 0; o < observers.size(); ++o) {
    double glare = 0, direct = 0;
    for (const Light& l : lights) {
      const GlareTerms t = glare_terms(rays, l, luminous_area, observers[o]);
      glare += t.glare;
      direct += t.direct_lux;
    }
    const double u = unified_glare_rating(glare, std::max(0.0, lux[pts.eyes_first + o] - direct));
    report.glare.push_back({observers[o], u});
    if (std::isfinite(u) && !(u <= report.ugr)) report.ugr = u;
  }
  if (!ctx.ugr_ok(report.ugr)) report.met = false;
  report.flux_lm = 0;
  report.power_w = 0;
  for (double d : chosen_dimming) {
    report.flux_lm += d * rated;
    report.power_w += d * profile.input_watts;
  }
  // Why not met, when the criteria could be.
  if (!report.met && bound.shortfall <= 1e-6) {
    char text[400];
    if (settings.fixed_count && report.fewest_free > settings.fixed_count)
      std::snprintf(text, sizeof(text), "--lights %zu: %zu luminaires fall short of the criteria (the fewest that meet them: %zu)",
                    settings.fixed_count, settings.fixed_count, report.fewest_free);
    else if (settings.fixed_count)
      std::snprintf(text, sizeof(text), "--lights %zu: %zu luminaires fall short of the criteria where they may stand", settings.fixed_count,
                    settings.fixed_count);
    else if (!report.cylindrical.met)
      std::snprintf(text, sizeof(text), "cylindrical illuminance Ēz %.0f lx is below the %g lx asked%s", report.cylindrical.mean,
                    settings.cylindrical_min, margin > 0 ? " (with the margin)" : "");
    else if (ugr_limit > 0 && !ctx.ugr_ok(report.ugr))
      std::snprintf(text, sizeof(text), "UGR %.1f is above the limit %.1f%s: a luminaire of lower luminance, or other places", report.ugr,
                    ugr_limit, margin > 0 ? " (with the margin)" : "");
    else if (take_array && settings.layout == LayoutChoice::Array)
      std::snprintf(text, sizeof(text), "no array of the luminaire meets the criteria (the nearest: %s): --layout free",
                    array->shape.describe().c_str());
    else
      std::snprintf(text, sizeof(text), "the criteria are not met when the lights found are measured");
    report.unmet = text;
  }
}

} // namespace hilight::design
