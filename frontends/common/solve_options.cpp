#include "solve_options.hpp"

#include "hilight/error.hpp"
#include "hilight/io/photometry_io.hpp"
#include "hilight/light_bounds.hpp"
#include "hilight/light_cache_store.hpp"
#include "hilight/ray_scene.hpp"
#include "hilight/regions.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <iterator>

namespace hilight::cli {

namespace {

/// Puts each of `options` in `group` (none when it is empty).
void group_all(std::initializer_list<CLI::Option*> options, const std::string& group) {
  if (group.empty()) return;
  for (CLI::Option* o : options) o->group(group);
}

} // namespace

void SolveOptions::add_placement(CLI::App& app) {
  app.add_option("--place", place,
                 "where lights may go (repeatable): ceiling[:OFFSET] (hanging OFFSET below the ceiling, default 0.2), "
                 "height:MIN:MAX, box:X0,Y0,Z0,X1,Y1,Z1 (inside one of the boxes), exclude:X0,Y0,Z0,X1,Y1,Z1, "
                 "region:K (in region K, as hilight info numbers them) or region:NAME (an IFC room or storey), not-region:K, "
                 "count:MIN:MAX or count:N (how many lights), anywhere (lifts a building's default: on the ceiling)");
}

void SolveOptions::add_renderer(CLI::App& app, const std::string& tuning_group) { renderer.add_to(app, tuning_group); }

void SolveOptions::add_luminaire(CLI::App& app) {
  app.add_option("--luminaire", luminaire_path,
                 "every light is this luminaire (an .ies or .ldt file), aimed down: the solve finds how many, where, and their dimming");
  app.add_option("--area-light", area_light,
                 "every light is a flat panel or tube aimed down: rectangle:WxH, disk:D or line:L (in the scene's unit)");
}

void SolveOptions::add_luminaire_tuning(CLI::App& app, const std::string& group) {
  group_all({app.add_option("--luminaire-spin", luminaire_spin, "turn the luminaire's C0 plane about its aim, degrees")->check(CLI::Range(-360.0, 360.0)),
             app.add_option("--luminaire-size", luminaire_size,
                            "auto: the luminaire is its file's luminous opening (a rectangle, disk or line), integrated over it; W,L: a "
                            "rectangle W across and L along its C0 plane, metres")},
            group);
}

void SolveOptions::add_units(CLI::App& app) {
  app.add_option("--units", units_name,
                 "radiometric: intensities in W/sr, painted values in W/(sr m2); photometric: candela, and cd/m2 or lux "
                 "(--target-quantity). A lights file that states its intensity_unit is read in it")
      ->check(CLI::IsMember({"radiometric", "photometric"}))
      ->capture_default_str();
  app.add_option("--target-quantity", quantity_name, "what the painted values are: luminance, or illuminance (lux on the surface; photometric)")
      ->check(CLI::IsMember({"luminance", "radiance", "illuminance"}))
      ->capture_default_str();
}

Units SolveOptions::units() const { return parse_units(units_name); }

TargetQuantity SolveOptions::target_quantity() const {
  const TargetQuantity quantity = parse_target_quantity(quantity_name);
  if (quantity == TargetQuantity::Illuminance && units() != Units::Photometric)
    throw InputError("--target-quantity illuminance is in lux: it needs --units photometric");
  return quantity;
}

namespace {

/// `--area-light rectangle:WxH | disk:D | line:L`: a Lambertian source aimed
/// straight down, its first side (or length) along +X.
Light area_light_template(const std::string& spec) {
  const size_t colon = spec.find(':');
  const std::string shape = spec.substr(0, colon), sizes = colon == std::string::npos ? "" : spec.substr(colon + 1);
  LightType type;
  const bool known = light_type_from_string(shape, type) && is_area(type);
  glm::vec2 size(0.f);
  char* end = nullptr;
  size[0] = std::strtof(sizes.c_str(), &end);
  bool ok = known && end != sizes.c_str();
  if (ok && type == LightType::Rectangle) {
    ok = *end == 'x';
    const char* second = end + 1;
    if (ok) size[1] = std::strtof(second, &end), ok = end != second;
  }
  ok = ok && *end == '\0';
  Light l = Light::area(known ? type : LightType::Rectangle, Vec3(0.f), {0.f, -1.f, 0.f}, {1.f, 0.f, 0.f}, size, Rgb(1.f));
  if (!ok || !area_light_problem(l).empty())
    throw InputError("--area-light " + spec + ": give rectangle:WxH, disk:D or line:L with positive sizes, e.g. rectangle:0.6x0.6");
  return l;
}

} // namespace

std::optional<Light> SolveOptions::luminaire() const {
  std::optional<Light> chosen;
  if (!luminaire_path.empty()) {
    Light luminaire;
    luminaire.type = LightType::Luminaire;
    luminaire.profile = std::make_shared<const Photometry>(read_photometry(luminaire_path));
    luminaire.profile_path = std::filesystem::absolute(luminaire_path).lexically_normal().string();
    luminaire.direction = Vec3(0.f, -1.f, 0.f);
    luminaire.spin_deg = luminaire_spin;
    if (!(luminaire.profile->peak() > 0)) throw InputError(luminaire_path, "the luminaire emits no light (all candela 0)");
    chosen = std::move(luminaire);
  } else if (luminaire_spin != 0.f) {
    throw InputError("--luminaire-spin needs --luminaire");
  }
  if (!luminaire_size.empty()) {
    if (!chosen) throw InputError("--luminaire-size needs --luminaire");
    if (luminaire_size != "auto") {  // W,L: the file's opening and body replaced
      const size_t comma = luminaire_size.find(',');
      char* end = nullptr;
      const double w = std::strtod(luminaire_size.c_str(), &end);
      const bool first = comma != std::string::npos && end == luminaire_size.c_str() + comma;
      const double l = first ? std::strtod(luminaire_size.c_str() + comma + 1, &end) : 0.0;
      if (!first || *end != '\0' || !(w > 0 && w <= 100) || !(l > 0 && l <= 100))
        throw InputError("--luminaire-size " + luminaire_size + ": give auto, or W,L in metres (each in (0, 100]), e.g. 0.6,0.6");
      Photometry sized = *chosen->profile;
      sized.opening_width = w, sized.opening_length = l, sized.opening_round = false;
      sized.body_width = w, sized.body_length = l, sized.body_round = false;
      chosen->profile = std::make_shared<const Photometry>(std::move(sized));
    }
    if (!with_luminous_opening(*chosen))
      throw InputError(luminaire_path, "gives no luminous opening (its width and length are 0): --luminaire-size auto needs one");
  }
  if (!area_light.empty()) {
    if (chosen) throw InputError("--area-light and --luminaire exclude each other (--luminaire-size auto: the luminaire's own opening)");
    chosen = area_light_template(area_light);
  }
  return chosen;
}

void SolveOptions::add_plugins(CLI::App& app, const std::string& group) {
  SolveSettings& s = spec.settings;
  group_all(
      {app.add_option("--evaluation-points", s.evaluation_points,
                      "D̄ is measured on every target point up to this many, else on this many evenly spaced ones (an estimate; 0: every point)")
           ->check(CLI::Range(size_t(0), size_t(100000000)))
           ->capture_default_str(),
       app.add_option("--samples", s.samples, "surface samples used by the solve (default: target points / 14, within 3000-10000)")
           ->check(CLI::Range(10, 10000000)),
       app.add_option("--optimizer", spec.optimizer, "refinement plugin (varpro, nelder-mead)")->capture_default_str(),
       app.add_option("--opt", spec.optimizer_settings, "optimizer setting key=value (repeatable)"),
       app.add_option("--sampler", spec.sampler, "surface sampling plugin (importance, uniform)")->capture_default_str(),
       app.add_option("--cache", spec.cache, "light cache plugin (grid, adaptive) or none: every response from the renderer")
           ->capture_default_str(),
       app.add_option("--cache-setting", spec.cache_settings,
                      "light cache setting key=value (repeatable; grid: cells, adaptive: cells depth tolerance nodes)"),
       app.add_option_function<int>("--cache-cells", [this](int cells) { spec.cache_settings.push_back("cells=" + std::to_string(cells)); },
                                    "the same as --cache-setting cells=N"),
       app.add_flag("--no-cache", no_cache, "the same as --cache none"),
       app.add_option("--cache-dir", cache_dir, "where the light cache is kept (default: ~/.cache/hilight)")},
      group);
}

void SolveOptions::add_paper_parameters(CLI::App& app, const std::string& group) {
  SolveSettings& s = spec.settings;
  group_all(
      {app.add_flag("--propose-spots,!--no-propose-spots", s.propose_spots,
                    "when point lights leave D̄ above 5%, look for spotlights without --spot-hints (default: on)"),
       app.add_flag("--no-residual-samples", [&s](int64_t) { s.residual_samples = false; },
                    "no second polish with the worst-explained target points added as samples"),
       app.add_option("--n-cut", s.n_cut, "N_cut: cuts refined")->check(CLI::Range(1, 1000))->capture_default_str(),
       app.add_option("--eps-opt", s.eps_opt, "ε_opt: refine only cuts with D̄ below")->check(CLI::Range(0.0, 10.0))->capture_default_str(),
       app.add_option("--eps-impro", s.eps_impro, "ε_impro: improvement ratio that justifies one more light")
           ->check(CLI::Range(1.0, 1000.0))
           ->capture_default_str(),
       app.add_option("--weak-threshold", s.seeding.weak_threshold, "ε_w: weak-light deletion threshold")
           ->check(CLI::Range(0.0, 1.0))
           ->capture_default_str(),
       app.add_option("--seed-cells", s.seeding.coarse_cells, "seeding cells along the longest axis")->check(CLI::Range(1, 16))->capture_default_str(),
       app.add_option("--seed-iterations", s.seeding.iterations, "seeding levels")->check(CLI::Range(1, 6))->capture_default_str(),
       app.add_option("--open-space-dbar", s.open_space_dbar,
                      "when lights inside the scene's bounds leave D̄ above this, look again beyond its open sides (0: never)")
           ->check(CLI::Range(0.0, 1e9))
           ->capture_default_str(),
       app.add_option("--seed", s.seed, "seed of sampling and of the renderer's sample streams")->capture_default_str()},
      group);
}

PlacementRules SolveOptions::placement() const {
  PlacementRules rules;
  for (const auto& rule : place) rules.add(rule);
  return rules;
}

bool ifc_has_storeys(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext != ".ifc") return false;
  std::ifstream in(file, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::toupper(c)); });
  return text.find("IFCBUILDINGSTOREY(") != std::string::npos;
}

std::string building_kind(const Scene& scene, bool storeys) {
  if (storeys) return "an IFC building with storeys";
  const auto open = side_openness(scene);
  if (std::all_of(open.begin(), open.end(), [](float side) { return side < kOpenSide; })) return "an interior, closed on every side";
  return "";
}

bool offered_as_room(const Region& region) { return !region.at_border && region.box.extent().y >= 1.8f; }

std::string why_not_a_room(const Region& region, const std::string& building) {
  if (building.empty() || offered_as_room(region)) return "";
  return region.at_border ? "it is outside" : "too low to stand in";
}

void refuse_regions_not_rooms(const PlacementRules& rules, const Regions& regions, const std::string& building) {
  for (int r : rules.regions) {
    if (size_t(r) >= regions.list().size()) continue;
    if (const std::string why = why_not_a_room(regions.list()[size_t(r)], building); !why.empty())
      throw InputError("--place region:" + std::to_string(r) + ": region " + std::to_string(r) + " is not a room of " + building +
                       " (" + why + "; hilight info lists the rooms)");
  }
}

std::string apply_building_default(PlacementRules& rules, const Scene& scene, bool storeys) {
  if (rules.says_where()) return "";
  const std::string why = building_kind(scene, storeys);
  if (why.empty()) return "";
  rules.add("ceiling");
  return "lights on the ceiling (" + why + "; --place anywhere lifts it)";
}

std::string settle_placement(PlacementRules& rules, const PlacementScene& where, bool building_default) {
  // The ray scene only when a rule needs it (RayScene::shared finds the caller's if it holds one).
  std::shared_ptr<const RayScene> rays;
  auto ray_scene = [&]() -> const RayScene& {
    if (!rays) rays = RayScene::shared(where.scene);
    return *rays;
  };
  if (!rules.region_names.empty() || !rules.not_region_names.empty())
    rules.resolve_room_names(where.named_rooms ? where.named_rooms(ray_scene()) : std::vector<NamedRoom>{});
  if (const std::string building = rules.regions.empty() ? "" : building_kind(*where.scene, where.storeys); !building.empty()) {
    const std::shared_ptr<const Regions> regions = where.regions ? where.regions : std::make_shared<const Regions>(ray_scene());
    refuse_regions_not_rooms(rules, *regions, building);
  }
  return building_default ? apply_building_default(rules, *where.scene, where.storeys) : "";
}

SolveSpec SolveOptions::to_spec(const Registry& registry) const {
  SolveSpec out = spec;
  if (no_cache) out.cache = PluginDefaults::no_cache;
  out.renderer = renderer.name;
  out.renderer_settings = renderer.assignments(&registry);
  out.settings.cache_dir = out.cache == PluginDefaults::no_cache ? std::filesystem::path()
                           : cache_dir.empty()                   ? default_cache_dir()
                                                                 : std::filesystem::path(cache_dir);
  out.settings.cache_cap_bytes = default_cache_cap_bytes();
  return out;
}

} // namespace hilight::cli
