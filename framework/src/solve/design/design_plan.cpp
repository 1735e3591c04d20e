// The illuminance design's plan: its steps as data, decided from the
// settings, and the one loop that runs them (design_steps.hpp).
#include "design_steps.hpp"

namespace hilight::design {

std::vector<DesignStep> design_plan(const DesignSettings& settings) {
  std::vector<DesignStep> plan = {{"candidates", place_candidates}, {"program", set_up_program}, {"free layouts", walk_free_layouts}};
  if (settings.fixed_count) plan.push_back({"count asked", meet_count});  // --lights N
  if (settings.layout != LayoutChoice::Free) plan.push_back({"arrays", try_arrays});
  plan.push_back({"choice", choose_layout});
  if (settings.tilt_max_deg > 0) plan.push_back({"tilts", tilt_aims});
  plan.push_back({"measure", measure_lights});
  return plan;
}

} // namespace hilight::design
