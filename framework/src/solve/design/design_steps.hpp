#pragma once
// The illuminance design (solve/illuminance_design.hpp) as a plan of steps
// over one DesignContext: what each step may read is the context's set-up
// and the results of the steps before it; what it writes is its own result
// and its part of the report. The plan is data (design_plan.cpp), decided
// from the settings: a step the settings rule out is not in it.
#include "design_parts.hpp"
#include "walker.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hilight::design {

/// An array tried: its shape, its places' fields, one dimming for all.
struct ArrayResult {
  ArrayLayout shape;
  std::vector<Field> fields;
  double x = 0, flux = 0, shortfall = 0, ugr = kNaN;
  bool met = false;
};

/// What the design's steps share.
struct DesignContext {
  /// The set-up: the area and mount, the room, the points and observers
  /// every place is rendered at. Throws InputError for what cannot fit.
  DesignContext(Renderer& reference, const LightSpace& space, const Light& luminaire, const IlluminanceCriteria& criteria,
                const DesignSettings& settings, DesignReport& report);
  DesignContext(const DesignContext&) = delete;
  DesignContext& operator=(const DesignContext&) = delete;

  // The inputs.
  Renderer& reference;
  const LightSpace& space;
  const Light& luminaire;
  const IlluminanceCriteria& criteria;
  const DesignSettings& settings;
  DesignReport& report;
  const RayScene& rays;
  const Photometry& profile;
  double peak = 0, rated = 0, mf = 1, margin = 0;
  Clock::time_point started;

  // The set-up.
  Bounds area;
  float plane = 0.f, step = 0.f, mount_y = 0.f;
  std::vector<float> layers;
  RoomFrame room;
  glm::vec2 size{0.f};
  double luminous_area = 0;
  std::string room_size;  ///< "L × W m", for messages
  std::vector<GlareObserver> observers;
  Points pts;
  size_t lux_points = 0;  ///< the points lux is kept at (before the eyes)

  /// The luminaire at place `c`, dimmed to `dimming` of full output.
  Light light_at(const Place& c, double dimming) const;
  /// Each place's maintained lux at full output, and its glare.
  std::vector<Field> render(const std::vector<Place>& places) const;
  /// Whether a field lights any of the criteria's points.
  bool lights_some(const Field& f) const;

  // 1. candidates: the places that light some point, and their fields.
  std::vector<float> spins;
  std::vector<Place> useful;
  std::vector<Field> fields;

  // 2. program: its rows, the walk over it, the bound (all places lit as the program wants).
  Program program;
  std::unique_ptr<Walker> walker;
  Layout bound;
  double ugr_limit = 0;
  size_t least_count = 1;
  double allowed = 0;  ///< the most flux a layout may take
  bool ugr_ok(double ugr) const { return !(ugr_limit > 0) || !(ugr > ugr_limit); }
  bool count_ok(size_t n) const { return n >= least_count && (!settings.max_count || n <= settings.max_count); }
  /// Criteria that cannot be met are met as nearly as the bound meets them.
  bool relaxed(const Layout& l) const { return l.as_met_as(bound) && l.flux <= allowed; }
  bool acceptable(const Layout& l) const { return relaxed(l) && count_ok(l.lights.size()) && walker->feasible(l) && ugr_ok(l.ugr); }
  Layout buildable(const Layout& l) const { return walker->feasible(l) ? l : walker->search(walker->spread(l)); }

  // 3. free layouts (and the count asked for).
  Layout free_layout;
  bool free_found = false;

  // 4. arrays.
  std::optional<ArrayResult> array;

  // 5. choice.
  std::vector<Place> chosen_places;
  std::vector<double> chosen_dimming;
  bool take_array = false;

  // 6. measure.
  Lighting lights;
};

/// One step of the design: its name (the report's) and what it does.
struct DesignStep {
  std::string name;
  void (*run)(DesignContext&);
};

void place_candidates(DesignContext& ctx);   ///< design_candidates.cpp
void set_up_program(DesignContext& ctx);     ///< design_candidates.cpp
void walk_free_layouts(DesignContext& ctx);  ///< design_free_layouts.cpp
void meet_count(DesignContext& ctx);         ///< design_free_layouts.cpp: --lights N
void try_arrays(DesignContext& ctx);         ///< design_arrays.cpp
void choose_layout(DesignContext& ctx);      ///< design_choice.cpp
void tilt_aims(DesignContext& ctx);          ///< design_tilts.cpp: --tilt-max
void measure_lights(DesignContext& ctx);     ///< design_measure.cpp

/// The steps for `settings`, in order (design_plan.cpp).
std::vector<DesignStep> design_plan(const DesignSettings& settings);

} // namespace hilight::design
