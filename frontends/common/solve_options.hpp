#pragma once
/// The solve's options as `hilight solve` and `hilight paint` take them: each
/// flag declared once, with its default and its help, and turned into the
/// SolveSpec that SolveSession assembles the solve from.
#include "cli_common.hpp"
#include "hilight/solve/solve_session.hpp"
#include "hilight/units.hpp"

#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hilight::cli {

struct SolveOptions {
  /// --renderer, --bounces, --bounce-samples, --set, --threads.
  RendererOptions renderer;
  /// The plugins and their settings; `spec.settings` holds the solve's own
  /// (samples, evaluation points, the paper's parameters). A frontend sets
  /// its defaults here before add_*() shows them in the help.
  SolveSpec spec;
  std::vector<std::string> place;  ///< --place rules as given
  std::string cache_dir;           ///< --cache-dir ("": default_cache_dir())
  bool no_cache = false;           ///< --no-cache
  std::string units_name = "radiometric", quantity_name = "luminance";  ///< --units, --target-quantity
  std::string luminaire_path, area_light, luminaire_size;  ///< --luminaire, --area-light, --luminaire-size
  float luminaire_spin = 0.f;                              ///< --luminaire-spin

  /// --place: where lights may stand.
  void add_placement(CLI::App& app);
  /// The renderer's options (RendererOptions::add_to), its tuning in `tuning_group`.
  void add_renderer(CLI::App& app, const std::string& tuning_group = "");
  /// --samples, --evaluation-points, the optimizer, sampler and light cache
  /// plugins and their settings, --cache-dir; in `group` ("": the main options).
  void add_plugins(CLI::App& app, const std::string& group = "");
  /// The paper's parameters (N_cut, ε_opt, ε_impro, ε_w, the seeding's),
  /// --seed, --propose-spots, --no-residual-samples, --open-space-dbar.
  void add_paper_parameters(CLI::App& app, const std::string& group);

  /// --luminaire and --area-light: what every light is.
  void add_luminaire(CLI::App& app);
  /// --luminaire-spin and --luminaire-size, in `group`.
  void add_luminaire_tuning(CLI::App& app, const std::string& group);
  /// --units and --target-quantity: what the files' numbers mean.
  void add_units(CLI::App& app);

  /// --place's rules (InputError names a bad one).
  PlacementRules placement() const;
  /// The light every solve places (--luminaire read and sized, or
  /// --area-light), nullopt for point lights; InputError for a bad file or
  /// size, or a tuning without --luminaire. An --area-light's size is in
  /// the scene's unit: scale it by the scene frame's once loaded.
  std::optional<Light> luminaire() const;
  /// --units, --target-quantity (InputError for lux without photometric units).
  Units units() const;
  TargetQuantity target_quantity() const;
  /// The spec to solve with: `spec` with --no-cache, the renderer and its
  /// settings (--bounces within what it carries), the cache folder and cap.
  /// Its placement is `spec.settings.placement`, as the frontend set it from
  /// placement() (and moved into the scene's frame).
  SolveSpec to_spec(const Registry& registry) const;
};

/// Whether `file` is an .ifc file with an IfcBuildingStorey (its text, no
/// IFC reader: what the building default asks of every IFC solve).
bool ifc_has_storeys(const std::filesystem::path& file);

/// What makes `scene` a building (issue 34 §7): "an IFC building with
/// storeys" (`storeys`), "an interior, closed on every side" (no side at
/// kOpenSide), or "" (a product, a stage: open).
std::string building_kind(const Scene& scene, bool storeys);
/// A region a building's frontends offer as a room: not the outside (at the
/// light bounds' border) and tall enough to stand in (1.8 m: not the void
/// under a slab).
bool offered_as_room(const Region& region);
/// Why a building's region is not offered as a room: "it is outside" or "too
/// low to stand in"; "" when it is one, or when the scene is no building
/// (`building` empty). The painter's room focus asks this too.
std::string why_not_a_room(const Region& region, const std::string& building);
/// In a building (`building`: building_kind's answer), `--place region:K`
/// naming a region not offered as a room (the outside, the void under a
/// slab) is an InputError: such regions are not offered (issue 34 §5).
/// `not-region:K` of one stays allowed (it only excludes).
void refuse_regions_not_rooms(const PlacementRules& rules, const Regions& regions, const std::string& building);

/// The building default (issue 34 §7): in a building — an IFC with storeys
/// (`storeys`), or a scene closed on every side (an interior) — lights hang
/// from the ceiling unless a --place rule says where (`anywhere` lifts it).
/// Products and stages (open scenes) keep free placement. Adds the rule to
/// `rules` and returns what the summary says; "" when it does not apply.
std::string apply_building_default(PlacementRules& rules, const Scene& scene, bool storeys);

/// A loaded scene as --place rules meet it (settle_placement).
struct PlacementScene {
  std::shared_ptr<const Scene> scene;
  bool storeys = false;  ///< an IFC with storeys (ifc_has_storeys)
  /// Its rooms by name (ifc_spaces.hpp scene_rooms); asked only when a rule
  /// names one. Unset: the scene names none.
  std::function<std::vector<NamedRoom>(const RayScene&)> named_rooms;
  /// Its regions as hilight info numbers them, when found already (else
  /// found here when a region:K asks).
  std::shared_ptr<const Regions> regions;
};
/// Parsed --place rules (in the scene's frame) as a solve takes them: room
/// and storey names resolved, in a building a region:K that is not a room
/// refused (InputError), and with `building_default` the building's ceiling
/// rule added when no rule says where (apply_building_default; its note
/// returned, "" when it does not apply). The one path of `hilight solve`,
/// `hilight paint --place` and the painter's place action, so the same text
/// gives the same rules in each (issue 34 §5, §7).
std::string settle_placement(PlacementRules& rules, const PlacementScene& where, bool building_default);

} // namespace hilight::cli
