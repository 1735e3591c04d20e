// The design's choice: the array where it costs nothing against the free
// layout, the free layout otherwise (design_steps.hpp).
#include "design_steps.hpp"

namespace hilight::design {

void choose_layout(DesignContext& ctx) {
  const DesignSettings& settings = ctx.settings;
  DesignReport& report = ctx.report;
  const Walker& walker = *ctx.walker;
  const Layout& bound = ctx.bound;
  const Layout& free_layout = ctx.free_layout;
  const bool free_found = ctx.free_found;
  const std::optional<ArrayResult>& array = ctx.array;
  const double rated = ctx.rated;
  const Photometry& profile = ctx.profile;
  const glm::vec2 size = ctx.size;
  const std::string& room_size = ctx.room_size;
  const std::vector<Place>& useful = ctx.useful;
  std::vector<Place>& chosen_places = ctx.chosen_places;
  std::vector<double>& chosen_dimming = ctx.chosen_dimming;
  bool& take_array = ctx.take_array;
  // 5. Which: the array where it costs nothing against the free layout.
  const auto summary = [&](LayoutSummary& s, size_t count, double x_flux, double shortfall, double ugr, bool met) {
    s.found = true;
    s.count = count;
    s.flux_lm = x_flux * rated;
    s.power_w = x_flux * profile.input_watts;
    s.shortfall_lux = shortfall;
    s.ugr = ugr;
    s.met = met;
  };
  const bool free_met = free_found && free_layout.as_met_as(bound) && walker.feasible(free_layout) && ctx.ugr_ok(free_layout.ugr) &&
                        (!settings.fixed_count || free_layout.lights.size() == settings.fixed_count);
  if (free_found) summary(report.free, free_layout.lights.size(), free_layout.flux, free_layout.shortfall, free_layout.ugr, free_met);
  if (array) {
    summary(report.array, array->fields.size(), array->flux, array->shortfall, array->ugr, array->met);
    report.array.shape = array->shape.describe();
  }
  take_array = false;
  if (settings.layout == LayoutChoice::Array) {
    if (!array)
      throw InputError(std::string("no array of the luminaire (") + metres(size[0]) + " × " + metres(size[1]) + " m) fits the room (" +
                       room_size + ")" + (settings.fixed_count ? " with " + std::to_string(settings.fixed_count) + " luminaires" : "") +
                       (settings.ceiling_grid > 0 ? " on the " + metres(settings.ceiling_grid) + " m grid" : "") +
                       " with the spacing asked for: --layout free places it freely");
    take_array = true;
    report.why = "--layout array";
  } else if (settings.layout == LayoutChoice::Auto && array) {
    if (!free_met) {
      take_array = array->met || !free_found || array->shortfall < free_layout.shortfall;
      report.why = array->met ? "the free layout does not meet the criteria" : "neither meets the criteria; the array falls less short";
    } else if (array->met && array->fields.size() <= free_layout.lights.size() &&
               array->flux <= free_layout.flux + settings.energy_tolerance * bound.flux + 1e-9) {
      take_array = true;
      report.why = "it costs nothing against the free layout (no more luminaires, flux within the energy tolerance)";
    } else {
      report.why = array->met ? "the array needs more luminaires or flux than the free layout" : "no array meets the criteria";
    }
  } else {
    report.why = settings.layout == LayoutChoice::Free ? "--layout free" : "no array fits the room";
  }
  if (!take_array && !free_found) throw InputError("no layout found");
  if (take_array) {
    report.chosen = "array";
    for (const Vec3& p : array->shape.positions) {
      chosen_places.push_back({p, array->shape.turn});
      chosen_dimming.push_back(array->x);
    }
  } else {
    report.chosen = "free";
    for (size_t j = 0; j < free_layout.lights.size(); ++j) {
      chosen_places.push_back(useful[free_layout.lights[j]]);
      chosen_dimming.push_back(free_layout.dimming[j]);
    }
  }
}

} // namespace hilight::design
