#include "core/session_player.hpp"

#include "hilight/io/criteria_file.hpp"

#include "hilight/error.hpp"
#include "hilight/scene_origin.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace hilight::painter {

using json = nlohmann::json;

Action brush_action(const BrushSettings& b) {
  BrushAction a;
  a.radius = b.radius;
  a.colour = b.colour;
  a.brightness = b.brightness;
  a.hardness = b.hardness;
  a.meaning = to_string(b.meaning);
  return untyped(a);
}

namespace {

std::string describe(const Vec3& p) {
  std::ostringstream s;
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

} // namespace

SessionPlayer::SessionPlayer(Document& document, SolveJob& job, PlayerHooks hooks, PlayerOptions options)
    : m_document(document), m_job(job), m_hooks(std::move(hooks)), m_options(std::move(options)),
      m_objects(document.scene()), m_place_rules(job.options().settings.placement) {
  // A brush as wide as a small patch of the scene, whatever its units.
  m_brush.radius = 0.03f * document.scene().diagonal();
}

std::vector<std::string> split_place_rules(const std::string& text) {
  std::vector<std::string> rules;
  std::istringstream words(text);
  for (std::string word; words >> word;) {
    const bool named_region = !rules.empty() && (rules.back().starts_with("region:") || rules.back().starts_with("not-region:"));
    if (named_region && word.find(':') == std::string::npos && word != "anywhere") rules.back() += ' ' + word;
    else rules.push_back(word);
  }
  return rules;
}

void SessionPlayer::log(const std::string& line) const {
  if (m_hooks.log) m_hooks.log(line);
}

void SessionPlayer::play(const Session& session) {
  for (size_t i = 0; i < session.actions.size(); ++i) validate_action(session.actions[i], m_options.source, i);
  // Where the script writes is checked before anything runs (not after a long solve).
  for (size_t i = 0; i < session.actions.size(); ++i) {
    const Action& a = session.actions[i];
    if (a.type != SaveTargetAction::kType && a.type != SaveLightsAction::kType && a.type != ScreenshotAction::kType) continue;
    const std::filesystem::path path = resolve(a.params["path"].get<std::string>());
    std::error_code ec;
    const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    if (!std::filesystem::is_directory(folder, ec))
      throw InputError(m_options.source, "action " + std::to_string(i) + " (" + a.type + "): cannot write " + path.string() +
                                             ": folder " + folder.string() + " does not exist");
    if (std::filesystem::is_directory(path, ec))
      throw InputError(m_options.source, "action " + std::to_string(i) + " (" + a.type + "): " + path.string() + " is a folder");
  }
  for (size_t i = 0; i < session.actions.size(); ++i) apply(session.actions[i], i);
  if (m_options.wait_for_solves && m_job.busy()) finish_solve("end of session");
}

void SessionPlayer::check_near_scene(const Vec3& p, const std::string& what) const {
  // Far-off points overflow the ray tracer's arithmetic (Embree asserts on them).
  const Bounds& bounds = m_document.scene().bounds;
  const DVec3 nearest = glm::clamp(DVec3(p), DVec3(bounds.lo), DVec3(bounds.hi));
  const double distance = glm::length(DVec3(p) - nearest);
  const double reach = double(kMaxSceneReach) * std::max(double(m_document.scene().diagonal()), 1e-30);
  if (!is_finite(p) || !(distance <= reach)) {
    std::ostringstream s;
    s << what << " " << describe(p) << " is more than " << kMaxSceneReach << " scene diagonals from the scene";
    throw InputError(s.str());
  }
}

SurfacePick SessionPlayer::world_point(const Vec3& p, const std::string& where) const {
  check_near_scene(p, where + ": point");
  auto pick = pick_near(m_document.rays(), p);
  if (!pick) throw InputError(where + ": " + describe(p) + " is not on any surface (within 1% of the scene diagonal)");
  return *pick;
}

SurfacePick SessionPlayer::screen_point(const Vec2& xy, const std::string& where) const {
  if (!m_hooks.pick_screen) throw InputError(where + ": screen coordinates need the painter's window (give world points)");
  auto pick = m_hooks.pick_screen({xy.x, xy.y});
  if (!pick) {
    std::ostringstream s;
    s << where << ": nothing under the screen point (" << xy.x << ", " << xy.y << ")";
    throw InputError(s.str());
  }
  return *pick;
}

std::vector<SurfacePick> SessionPlayer::surface_picks(const PointSet& points, const std::string& where) const {
  std::vector<SurfacePick> picks;
  if (!points.world.empty()) {
    // Every world point snaps to the nearest surface (within 1% of the
    // diagonal) or is an error; recorded strokes carry their normals.
    for (size_t i = 0; i < points.world.size(); ++i) {
      const Vec3& p = points.world[i];
      check_near_scene(p, where + ": point " + std::to_string(i));
      auto pick = pick_near(m_document.rays(), p);
      if (!pick)
        throw InputError(where + ": point " + std::to_string(i) + " " + describe(p) +
                         " is not on any surface (within 1% of the scene diagonal)");
      // Surfaces the section or cutaway hides take nothing (the view skips them as the mouse does).
      if (!pick_near(m_document.rays(), p, &visibility())) continue;
      picks.push_back(points.normals.empty() ? *pick : SurfacePick{p, glm::normalize(points.normals[i])});
    }
    if (picks.empty()) throw InputError(where + ": every point is on a surface the section or cutaway hides");
    return picks;
  }
  // Screen points: whatever the cursor hit (the window's picking skips hidden
  // surfaces); misses are skipped, as with the mouse.
  if (!m_hooks.pick_screen) throw InputError(where + ": screen coordinates need the painter's window (give world points)");
  for (const Vec2& p : points.screen)
    if (auto pick = m_hooks.pick_screen({p.x, p.y})) picks.push_back(*pick);
  if (picks.empty()) throw InputError(where + ": no screen point hits the scene");
  return picks;
}

std::vector<Vec3> SessionPlayer::world_points(const PointSet& points, const std::string& where) const {
  std::vector<Vec3> out;
  for (const SurfacePick& p : surface_picks(points, where)) out.push_back(p.position);
  return out;
}

void SessionPlayer::apply(const Action& action, size_t index) {
  validate_action(action, m_options.source, index);
  const std::string where = "action " + std::to_string(index) + " (" + action.type + ")";
  try {
    std::visit([&](const auto& a) { run(a, action, where); }, typed(action));
  } catch (const InputError& e) {
    const std::string what = e.what();
    throw InputError(m_options.source, what.rfind("action ", 0) == 0 ? what : where + ": " + what);
  }
}

void SessionPlayer::run(const CameraAction& a, const Action&, const std::string&) {
  if (a.eye) check_near_scene(*a.eye, "camera: eye");
  if (a.target) check_near_scene(*a.target, "camera: target");
  if (m_hooks.camera) m_hooks.camera(a);
}

void SessionPlayer::run(const ViewAction& a, const Action&, const std::string&) {
  if (m_hooks.view) m_hooks.view(a.show);
}

void SessionPlayer::run(const SectionAction& a, const Action&, const std::string&) {
  if (a.height) check_near_scene(Vec3(m_document.scene().bounds.center().x, *a.height, m_document.scene().bounds.center().z),
                                 "section: height");
  m_clip.section = a.height;
}

void SessionPlayer::run(const CutawayAction& a, const Action&, const std::string&) { m_clip.cutaway = a.on; }

const Visibility& SessionPlayer::visibility() const {
  static const Visibility everything;
  if (!m_clip.any()) {
    if (m_visibility_for) ++m_visibility_revision;
    m_visibility_for.reset();
    return everything;
  }
  const CameraPose pose = m_hooks.camera_pose ? m_hooks.camera_pose() : CameraPose{};
  // Without a camera there is nothing in front of anything: the cutaway hides nothing.
  const Vec3 focus = m_hooks.camera_pose ? pose.target : pose.eye;
  auto key = std::make_tuple(m_clip, pose.eye, focus);
  if (m_visibility_for != key) {
    m_visibility = Visibility::compute(m_document.scene(), m_clip, pose.eye, focus);
    m_visibility_for = key;
    ++m_visibility_revision;
  }
  return m_visibility;
}

void SessionPlayer::run(const PlanAction& a, const Action&, const std::string& where) {
  if (m_hooks.plan) m_hooks.plan(a.on);
  else log(where + ": no window, no plan view");
}

void SessionPlayer::run(const WalkAction& a, const Action&, const std::string& where) {
  if (m_hooks.walk) m_hooks.walk(a);
  else log(where + ": no window to walk in");
}

const Regions& SessionPlayer::regions() const {
  if (!m_regions) m_regions = std::make_shared<const Regions>(m_document.rays());
  return *m_regions;
}

int SessionPlayer::room_of(const Vec3& position, const Vec3& normal) const {
  return regions().at(position + regions().voxel_size() * normal);
}

void SessionPlayer::run(const FocusAction& a, const Action&, const std::string& where) {
  std::vector<int> focus;
  const size_t rooms = regions().list().size();
  if (a.world) {
    const SurfacePick at = world_point(*a.world, where);
    const int room = room_of(at.position, at.normal);
    if (room < 0) throw InputError(where + ": no room at " + describe(*a.world) + " (it is outside every region)");
    refuse_not_a_room(room, where, " at " + describe(*a.world));
    focus.push_back(room);
  }
  for (int r : a.regions) {
    if (r < 0 || size_t(r) >= rooms)
      throw InputError(where + ": no region " + std::to_string(r) + " (the scene has " + std::to_string(rooms) + ", 0 to " +
                       std::to_string(int(rooms) - 1) + ")");
    refuse_not_a_room(r, where, "");
    if (std::find(focus.begin(), focus.end(), r) == focus.end()) focus.push_back(r);
  }
  if (m_job.busy()) finish_solve(where);
  m_focus = std::move(focus);
  apply_placement();
  if (m_focus.empty()) {
    log("no room focus");
    return;
  }
  Bounds box;
  std::string names;
  for (int r : m_focus) {
    box.extend(regions().list()[size_t(r)].box.lo);
    box.extend(regions().list()[size_t(r)].box.hi);
    names += (names.empty() ? "" : ", ") + std::to_string(r);
  }
  if (m_hooks.frame) m_hooks.frame(box);
  log("focus on region " + names);
}

void SessionPlayer::refuse_not_a_room(int region, const std::string& where, const std::string& at) const {
  // The rooms a building offers, as hilight solve takes region:K: the focus limits the lights to them.
  if (!m_hooks.not_a_room) return;
  const std::string why = m_hooks.not_a_room(regions().list()[size_t(region)]);
  if (!why.empty()) throw InputError(where + ": region " + std::to_string(region) + at + " is " + why + "; focus a room");
}

PlacementRules SessionPlayer::placement() const {
  PlacementRules rules = m_place_rules;
  if (!m_focus.empty()) rules.regions = m_focus;
  return rules;
}

void SessionPlayer::apply_placement() { m_job.set_placement(placement()); }

LightSpace SessionPlayer::light_space() const {
  regions();  // found once, shared with the focus
  return LightSpace(m_document.rays(), placement(), std::nullopt, m_regions);
}

void SessionPlayer::continue_from(const SessionPlayer& other) {
  m_tool = other.m_tool;
  m_brush = other.m_brush;
  m_clip = other.m_clip;
  m_focus = other.m_focus;
  m_place_rules = other.m_place_rules;
  m_regions = other.m_regions;
}

Target SessionPlayer::focused_target(const std::string& where) const {
  if (m_focus.empty()) return m_document.target();
  const Scene& scene = m_document.scene();
  return m_document.target([&](uint32_t v) {
    const int room = room_of(scene.positions[v], scene.normals[v]);
    return std::find(m_focus.begin(), m_focus.end(), room) != m_focus.end();
  }, where + ": nothing is painted in the focused rooms");
}

void SessionPlayer::run(const ToolAction& a, const Action& action, const std::string&) {
  m_tool = a.tool;
  if (m_hooks.tool_changed) m_hooks.tool_changed(action);
}

void SessionPlayer::run(const BrushAction& a, const Action& action, const std::string&) {
  if (a.radius) m_brush.radius = *a.radius;
  if (a.colour) m_brush.colour = *a.colour;
  if (a.brightness) m_brush.brightness = *a.brightness;
  if (a.hardness) m_brush.hardness = *a.hardness;
  if (a.meaning) m_brush.meaning = *paint_meaning_from_string(*a.meaning);
  if (m_hooks.tool_changed) m_hooks.tool_changed(action);
}

void SessionPlayer::run(const StrokeAction& a, const Action&, const std::string& where) {
  const bool erase = a.erase ? *a.erase : m_tool == Tool::Eraser;
  paint_stroke(m_document, m_brush, erase ? BrushMode::Erase : BrushMode::Paint, surface_picks(a.points, where), &visibility());
}

void SessionPlayer::run(const EraseAction& a, const Action&, const std::string& where) {
  paint_stroke(m_document, m_brush, BrushMode::Erase, surface_picks(a.points, where), &visibility());
}

void SessionPlayer::run(const ShadowAction& a, const Action&, const std::string& where) {
  std::vector<ShadowRequest> requests;
  for (const auto& pair : a.pairs) {
    const SurfacePick at = pair.occluder ? world_point(*pair.occluder, where) : screen_point(*pair.occluder_screen, where);
    Hit hit = m_document.rays().closest_point(at.position, 0.01f * m_document.scene().diagonal());
    if (!hit.valid()) throw InputError(where + ": the occluder point is not on any object");
    PointSet points_only = pair.points;
    points_only.normals.clear();
    requests.push_back({m_objects.object_of_triangle(hit.triangle), world_points(points_only, where)});
  }
  ShadowEstimate estimate = estimate_shadow_lights(m_objects, light_space(), requests);
  if (estimate.lights.empty()) throw InputError(where + ": no light position casts these shadows");
  // The estimate proposes the point lights; the designer's spotlights stay.
  m_document.apply("lights from shadows", [&](PaintState& s) {
    Lighting lights = estimate.lights;
    for (const Light& l : s.lights)
      if (l.type == LightType::Spot) lights.push_back(l);
    s.lights = std::move(lights);
  });
  m_last_estimate = std::move(estimate);
}

void SessionPlayer::run(const EraseShadowAction& a, const Action&, const std::string& where) {
  const SurfacePick click = a.world ? world_point(*a.world, where) : screen_point(*a.screen, where);
  m_last_pairs = find_shadow_pairs(m_objects, m_document.rays(), m_document.state().lights, click);
  if (m_last_pairs.empty()) throw InputError(where + ": no light is blocked at " + describe(click.position));
  size_t pick = 0;
  if (a.pick) pick = *a.pick;
  else if (m_last_pairs.size() > 1 && m_hooks.choose_shadow_pair) pick = m_hooks.choose_shadow_pair(m_last_pairs);
  if (pick >= m_last_pairs.size())
    throw InputError(where + ": pick " + std::to_string(pick) + " but only " + std::to_string(m_last_pairs.size()) +
                     " occluder–light pairs shadow that point");
  if (m_job.busy()) throw InputError(where + ": wait for the running solve to finish");
  const ShadowPair& pair = m_last_pairs[pick];
  erase_shadow(m_document, m_objects, m_job.renderer(), pair);
  log("erased the shadow of object " + std::to_string(pair.occluder) + " (" + m_objects.name(pair.occluder) +
      ") from light " + std::to_string(pair.light));
}

void SessionPlayer::run(const SpotRegionAction& a, const Action&, const std::string& where) {
  CameraPose pose;
  if (a.eye) {
    pose.eye = *a.eye;
    pose.direction = *a.direction;
    check_near_scene(pose.eye, "spot_region: eye");
  } else if (m_hooks.camera_pose) {
    pose = m_hooks.camera_pose();
  } else {
    throw InputError(where + ": give \"eye\" and \"direction\" (no window to take the camera from)");
  }
  const std::vector<Vec3> region = world_points(a.points, where);
  SpotRegionSettings settings;
  if (a.falloff_deg) settings.falloff_deg = *a.falloff_deg;
  Light spot = spot_for_region_in_scene(light_space(), pose.eye, pose.direction, region, settings);
  const float d = glm::length(centroid(region) - spot.position);
  spot.intensity = a.intensity ? *a.intensity : Rgb(d * d);  // about irradiance 1 at the region
  m_document.apply("spotlight for a region", [&](PaintState& s) {
    s.lights.push_back(spot);
    s.spot_hints.push_back(spot);
  });
}

void SessionPlayer::run(const AdjustRegionAction& a, const Action&, const std::string& where) {
  if (m_job.busy()) throw InputError(where + ": wait for the running solve to finish");
  RegionAdjustSettings settings;
  settings.multiplier = a.multiplier;
  if (a.min_share) settings.min_share = *a.min_share;
  const auto region = region_vertices(m_document.rays(), world_points(a.points, where), a.radius ? *a.radius : m_brush.radius);
  RegionAdjustResult result = adjust_region(m_document, m_job.renderer(), region, settings);
  log("adjusted " + std::to_string(result.changed_lights.size()) + " of " + std::to_string(m_document.state().lights.size()) +
      " lights");
}

void SessionPlayer::start_job(JobKind kind, const std::string& where) {
  if (m_job.busy()) {
    if (!m_options.wait_for_solves) throw InputError(where + ": a solve is already running");
    finish_solve(where);
  }
  launch(kind, where);
  if (m_options.wait_for_solves) finish_solve(where);
}

void SessionPlayer::start_in_background(JobKind kind) {
  if (m_job.busy()) throw InputError(std::string(to_string(kind)) + ": a solve is already running");
  launch(kind, to_string(kind));
}

void SessionPlayer::launch(JobKind kind, const std::string& where) {
  if (m_job.has_criteria()) {  // a lux target: nothing painted to read
    if (kind != JobKind::Solve)
      throw InputError(where + ": " + to_string(kind) + " works on painted targets; with lux criteria, solve places the luminaires");
    m_job_revision = m_document.revision();
    m_job.start_solve(Target{});
    return;
  }
  Target target = focused_target(where);
  const PaintState& s = m_document.state();
  if (kind != JobKind::Solve && s.lights.empty()) throw InputError(where + ": there are no lights yet (solve first)");
  // poll() drops the result if the document changes from here on.
  m_job_revision = m_document.revision();
  if (kind == JobKind::Solve) m_job.start_solve(std::move(target), s.spot_hints);
  else if (kind == JobKind::FineTune) m_job.start_fine_tune(std::move(target), s.lights);
  else m_job.start_add_lights(std::move(target), s.lights);
}

void SessionPlayer::run(const SolveAction&, const Action&, const std::string& where) { start_job(JobKind::Solve, where); }
void SessionPlayer::run(const FineTuneAction&, const Action&, const std::string& where) { start_job(JobKind::FineTune, where); }
void SessionPlayer::run(const AddLightsAction&, const Action&, const std::string& where) { start_job(JobKind::AddLights, where); }

void SessionPlayer::run(const CutAction& a, const Action&, const std::string& where) {
  if (m_job.busy()) finish_solve(where);
  if (m_job.cut_count() == 0) throw InputError(where + ": no solve to take light counts from");
  m_document.set_lights(m_job.cut_lights(a.k), "cut with " + std::to_string(a.k) + " lights");
}

void SessionPlayer::run(const PlaceAction& a, const Action&, const std::string& where) {
  // Space-separated --place rules, taken as hilight solve takes the same text
  // ("": none given, so a building's default); a bad rule is an input error
  // naming the action, and the rules stay as they were.
  if (m_job.busy()) finish_solve(where);
  PlacementRules rules;
  std::string building_note;
  try {
    for (const auto& rule : split_place_rules(a.rules)) rules.add(rule);
    // Boxes, heights and the ceiling offset in the scene file's coordinates
    // and unit, as hilight solve --place and the painter's files take them.
    rules = rules_to_local(std::move(rules), m_document.scene().frame);
    if (!rules.regions.empty()) regions();  // found once, shared with the focus and the light space
    if (m_hooks.settle_placement) building_note = m_hooks.settle_placement(rules, m_regions);
    else if (!rules.region_names.empty() || !rules.not_region_names.empty()) rules.resolve_room_names({});  // throws, naming it
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  }
  m_place_rules = std::move(rules);
  apply_placement();
  const std::string given = a.rules.empty() && building_note.empty() ? "anywhere free" : a.rules;
  log(where + ": lights may stand: " + given + (given.empty() || building_note.empty() ? "" : "; ") + building_note +
      (m_focus.empty() ? "" : " (and in the focused rooms)"));
}

void SessionPlayer::run(const UndoAction&, const Action&, const std::string&) { m_document.undo(); }
void SessionPlayer::run(const RedoAction&, const Action&, const std::string&) { m_document.redo(); }

void SessionPlayer::run(const SaveTargetAction& a, const Action&, const std::string&) { m_document.save_target(resolve(a.path)); }
void SessionPlayer::run(const LoadTargetAction& a, const Action&, const std::string&) { m_document.load_target(resolve(a.path)); }
void SessionPlayer::run(const LoadLightsAction& a, const Action&, const std::string&) { m_document.load_lights(resolve(a.path)); }
void SessionPlayer::run(const UnitsAction& a, const Action&, const std::string&) { m_document.set_units(a.units, a.quantity); }
void SessionPlayer::run(const CriteriaAction& a, const Action&, const std::string& where) {
  if (m_job.busy()) finish_solve(where);
  m_job.set_criteria(read_criteria(resolve(a.path)), a.design);
}

void SessionPlayer::run(const SaveLightsAction& a, const Action&, const std::string& where) {
  // The lights are about to change under them (a replay, which waits for
  // each job, would save the job's result): wait for it.
  if (m_job.busy() && !m_options.wait_for_solves) throw InputError(where + ": wait for the running solve to finish");
  m_document.save_lights(resolve(a.path));
}

void SessionPlayer::run(const ScreenshotAction& a, const Action&, const std::string& where) {
  if (m_job.busy() && !m_options.wait_for_solves) throw InputError(where + ": wait for the running solve to finish");
  if (m_hooks.screenshot) m_hooks.screenshot(resolve(a.path), a.panels);
  else log(where + ": no window, no screenshot");
}

void SessionPlayer::run(const OpenSceneAction& a, const Action&, const std::string& where) {
  const std::filesystem::path path = resolve(a.path);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(where + ": " + path.string() + " is not a file");
  if (!m_hooks.open_scene) throw InputError(where + ": no window to open a scene in");
  if (m_job.busy()) m_job.cancel();  // its answer would be for the scene left behind
  m_hooks.open_scene(path);
}

void SessionPlayer::commit(JobResult& result) {
  if (result.outcome != JobOutcome::Done) return;
  if (m_document.revision() != m_job_revision) {
    // The document changed while the job ran (a stroke, an undo, new lights):
    // its lights answer a question no longer asked. Dropped, so the session
    // (whose recording drops the job too) replays the same.
    result.outcome = JobOutcome::Superseded;
    if (result.kind != JobKind::FineTune) m_job.discard_cuts();  // a later `cut` must not use them
    log(std::string(to_string(result.kind)) + " result dropped: the document changed while it ran");
    return;
  }
  std::ostringstream label;
  label << to_string(result.kind) << ": " << result.lights.size() << (result.lights.size() == 1 ? " light" : " lights");
  m_document.set_lights(result.lights, label.str());
  std::ostringstream line;
  line << label.str();
  if (m_job.has_criteria()) line << ", criteria " << (result.criteria_met ? "met" : "not met");
  else line << ", D̄ " << 100.0 * result.report.dbar << "%";
  log(line.str());
  if (m_hooks.fit) m_hooks.fit(result);
}

void SessionPlayer::finish_solve(const std::string& where) {
  std::optional<JobResult> result = m_job.wait();
  if (!result) return;
  commit(*result);
  if (result->outcome == JobOutcome::Failed) throw InputError(where + ": " + result->error);
  if (result->outcome == JobOutcome::Cancelled) throw InputError(where + ": the solve was cancelled");
}

std::optional<JobResult> SessionPlayer::poll() {
  if (m_document.editing()) return std::nullopt;  // mid-stroke: commit the result after it
  std::optional<JobResult> result = m_job.take_result();
  if (result) commit(*result);
  return result;
}

} // namespace hilight::painter
