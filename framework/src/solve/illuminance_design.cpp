// Lights for illuminance criteria (solve/illuminance_design.hpp): the
// settings checked, then the plan's steps over one context, each timed
// (design/design_plan.cpp; the steps in design/, a file each).
#include "hilight/solve/illuminance_design.hpp"

#include "design/design_steps.hpp"
#include "hilight/error.hpp"

namespace hilight {

const char* to_string(DesignSettings::Posture posture) { return posture == DesignSettings::Posture::Standing ? "standing" : "seated"; }

const char* to_string(LayoutChoice choice) {
  switch (choice) {
    case LayoutChoice::Auto: return "auto";
    case LayoutChoice::Array: return "array";
    case LayoutChoice::Free: return "free";
  }
  return "?";
}

void check_design_settings(const DesignSettings& s) {
  if (!(s.maintenance_factor > 0 && s.maintenance_factor <= 1))
    throw InputError("--maintenance-factor " + std::to_string(s.maintenance_factor) +
                     ": must be in (0, 1] (maintained = MF × new; 0.8 is a clean office's)");
  if (!(s.margin >= 0 && s.margin < 1)) throw InputError("--margin " + std::to_string(s.margin) + ": must be in [0, 1)");
  if (!(s.tilt_max_deg >= 0 && s.tilt_max_deg <= 60))
    throw InputError("--tilt-max " + std::to_string(s.tilt_max_deg) + ": must be in [0, 60] degrees");
}

Lighting design_for_illuminance(Renderer& reference, const LightSpace& space, const Light& luminaire,
                                const IlluminanceCriteria& criteria, const DesignSettings& settings, DesignReport& report) {
  const bool with_profile = luminaire.profile && (luminaire.type == LightType::Luminaire || is_area(luminaire.type));
  if (!with_profile) throw InputError("illuminance criteria need a luminaire (--luminaire FILE)");
  check_design_settings(settings);
  using namespace design;
  DesignContext ctx(reference, space, luminaire, criteria, settings, report);
  report.seconds["set-up"] = since(ctx.started);
  for (const DesignStep& step : design_plan(settings)) {
    const auto start = Clock::now();
    step.run(ctx);
    report.steps.push_back({step.name, since(start)});
    report.seconds[step.name] = report.steps.back().second;
  }
  report.seconds["total"] = since(ctx.started);
  return std::move(ctx.lights);
}

} // namespace hilight
