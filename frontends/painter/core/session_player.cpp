#include "core/session_player.hpp"

#include "hilight/error.hpp"

#include <sstream>
#include <stdexcept>

namespace hilight::painter {

using json = nlohmann::json;

const char* to_string(Tool tool) {
  switch (tool) {
  case Tool::Brush: return "brush";
  case Tool::Eraser: return "eraser";
  case Tool::Shadow: return "shadow";
  case Tool::EraseShadow: return "erase_shadow";
  case Tool::Spot: return "spot";
  case Tool::Adjust: return "adjust";
  }
  return "?";
}

std::optional<Tool> tool_from_string(const std::string& name) {
  for (Tool t : {Tool::Brush, Tool::Eraser, Tool::Shadow, Tool::EraseShadow, Tool::Spot, Tool::Adjust})
    if (name == to_string(t)) return t;
  return std::nullopt;
}

Action brush_action(const BrushSettings& b) {
  return Action{"brush",
                {{"radius", b.radius}, {"colour", {b.colour.r, b.colour.g, b.colour.b}}, {"brightness", b.brightness}, {"hardness", b.hardness}}};
}

namespace {

Vec3 vec3(const json& v) { return Vec3(v[0].get<float>(), v[1].get<float>(), v[2].get<float>()); }
Rgb colour(const json& v) { return v.is_array() ? vec3(v) : Rgb(v.get<float>()); }

std::string describe(const Vec3& p) {
  std::ostringstream s;
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

} // namespace

SessionPlayer::SessionPlayer(Document& document, SolveJob& job, PlayerHooks hooks, PlayerOptions options)
    : m_document(document), m_job(job), m_hooks(std::move(hooks)), m_options(std::move(options)),
      m_objects(document.scene()) {
  // A brush as wide as a small patch of the scene, whatever its units.
  m_brush.radius = 0.03f * document.scene().diagonal();
}

void SessionPlayer::log(const std::string& line) const {
  if (m_hooks.log) m_hooks.log(line);
}

void SessionPlayer::play(const Session& session) {
  for (size_t i = 0; i < session.actions.size(); ++i) validate_action(session.actions[i], m_options.source, i);
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

SurfacePick SessionPlayer::one_point(const json& value, bool screen, const std::string& where) const {
  if (!screen) {
    const Vec3 p = vec3(value);
    check_near_scene(p, where + ": point");
    auto pick = pick_near(m_document.rays(), p);
    if (!pick) throw InputError(where + ": " + describe(p) + " is not on any surface (within 1% of the scene diagonal)");
    return *pick;
  }
  if (!m_hooks.pick_screen) throw InputError(where + ": screen coordinates need the painter's window (give world points)");
  const std::array<float, 2> xy{value[0].get<float>(), value[1].get<float>()};
  auto pick = m_hooks.pick_screen(xy);
  if (!pick) {
    std::ostringstream s;
    s << where << ": nothing under the screen point (" << xy[0] << ", " << xy[1] << ")";
    throw InputError(s.str());
  }
  return *pick;
}

std::vector<SurfacePick> SessionPlayer::surface_picks(const json& params, const std::string& where) const {
  std::vector<SurfacePick> picks;
  if (params.contains("world")) {
    // Every world point snaps to the nearest surface (within 1% of the
    // diagonal) or is an error; recorded strokes carry their normals.
    const json& world = params["world"];
    for (size_t i = 0; i < world.size(); ++i) {
      const Vec3 p = vec3(world[i]);
      check_near_scene(p, where + ": point " + std::to_string(i));
      if (params.contains("normals")) {
        const Vec3 n = glm::normalize(vec3(params["normals"][i]));
        if (!pick_near(m_document.rays(), p))
          throw InputError(where + ": point " + std::to_string(i) + " " + describe(p) +
                           " is not on any surface (within 1% of the scene diagonal)");
        picks.push_back({p, n});
        continue;
      }
      auto pick = pick_near(m_document.rays(), p);
      if (!pick)
        throw InputError(where + ": point " + std::to_string(i) + " " + describe(p) +
                         " is not on any surface (within 1% of the scene diagonal)");
      picks.push_back(*pick);
    }
    return picks;
  }
  // Screen points: whatever the cursor hit; misses are skipped, as with the mouse.
  if (!m_hooks.pick_screen) throw InputError(where + ": screen coordinates need the painter's window (give world points)");
  for (const auto& p : params["screen"])
    if (auto pick = m_hooks.pick_screen({p[0].get<float>(), p[1].get<float>()})) picks.push_back(*pick);
  if (picks.empty()) throw InputError(where + ": no screen point hits the scene");
  return picks;
}

std::vector<Vec3> SessionPlayer::world_points(const Action& action, const std::string& where) const {
  std::vector<Vec3> points;
  for (const SurfacePick& p : surface_picks(action.params, where)) points.push_back(p.position);
  return points;
}

void SessionPlayer::apply(const Action& action, size_t index) {
  validate_action(action, m_options.source, index);
  const std::string where = "action " + std::to_string(index) + " (" + action.type + ")";
  const json& p = action.params;
  const std::string& type = action.type;
  try {
    if (type == "camera") {
      if (p.contains("eye")) check_near_scene(vec3(p["eye"]), "camera: eye");
      if (p.contains("target")) check_near_scene(vec3(p["target"]), "camera: target");
      if (m_hooks.camera) m_hooks.camera(action);
    } else if (type == "view") {
      if (m_hooks.view) m_hooks.view(p["show"].get<std::string>());
    } else if (type == "tool") {
      m_tool = *tool_from_string(p["tool"].get<std::string>());
      if (m_hooks.tool_changed) m_hooks.tool_changed(action);
    } else if (type == "brush") {
      if (p.contains("radius")) m_brush.radius = p["radius"].get<float>();
      if (p.contains("colour")) m_brush.colour = colour(p["colour"]);
      if (p.contains("brightness")) m_brush.brightness = p["brightness"].get<float>();
      if (p.contains("hardness")) m_brush.hardness = p["hardness"].get<float>();
      if (m_hooks.tool_changed) m_hooks.tool_changed(action);
    } else if (type == "stroke" || type == "erase") {
      const bool erase = type == "erase" || (p.contains("mode") ? p["mode"] == "erase" : m_tool == Tool::Eraser);
      paint_stroke(m_document, m_brush, erase ? BrushMode::Erase : BrushMode::Paint, surface_picks(p, where));
    } else if (type == "shadow") {
      std::vector<ShadowRequest> requests;
      for (const auto& pair : p["pairs"]) {
        const SurfacePick at = pair.contains("occluder") ? one_point(pair["occluder"], false, where)
                                                         : one_point(pair["occluder_screen"], true, where);
        Hit hit = m_document.rays().closest_point(at.position, 0.01f * m_document.scene().diagonal());
        if (!hit.valid()) throw InputError(where + ": the occluder point is not on any object");
        Action points_only{type, json::object()};
        if (pair.contains("world")) points_only.params["world"] = pair["world"];
        else points_only.params["screen"] = pair["screen"];
        requests.push_back({m_objects.object_of_triangle(hit.triangle), world_points(points_only, where)});
      }
      ShadowEstimate estimate = estimate_shadow_lights(m_objects, m_document.rays(), requests);
      if (estimate.lights.empty()) throw InputError(where + ": no light position casts these shadows");
      // The estimate proposes the point lights; the designer's spotlights stay.
      m_document.apply("lights from shadows", [&](PaintState& s) {
        Lighting lights = estimate.lights;
        for (const Light& l : s.lights)
          if (l.type == LightType::Spot) lights.push_back(l);
        s.lights = std::move(lights);
      });
      m_last_estimate = std::move(estimate);
    } else if (type == "erase_shadow") {
      const SurfacePick click = one_point(p.contains("world") ? p["world"] : p["screen"], p.contains("screen"), where);
      m_last_pairs = find_shadow_pairs(m_objects, m_document.rays(), m_document.state().lights, click);
      if (m_last_pairs.empty()) throw InputError(where + ": no light is blocked at " + describe(click.position));
      size_t pick = 0;
      if (p.contains("pick")) pick = p["pick"].get<size_t>();
      else if (m_last_pairs.size() > 1 && m_hooks.choose_shadow_pair) pick = m_hooks.choose_shadow_pair(m_last_pairs);
      if (pick >= m_last_pairs.size())
        throw InputError(where + ": pick " + std::to_string(pick) + " but only " + std::to_string(m_last_pairs.size()) +
                         " occluder–light pairs shadow that point");
      if (m_job.busy()) throw InputError(where + ": wait for the running solve to finish");
      const ShadowPair& pair = m_last_pairs[pick];
      erase_shadow(m_document, m_objects, m_job.renderer(), pair);
      log("erased the shadow of object " + std::to_string(pair.occluder) + " (" + m_objects.name(pair.occluder) +
          ") from light " + std::to_string(pair.light));
    } else if (type == "spot_region") {
      CameraPose pose;
      if (p.contains("eye")) {
        pose.eye = vec3(p["eye"]);
        pose.direction = vec3(p["direction"]);
        check_near_scene(pose.eye, "spot_region: eye");
      } else if (m_hooks.camera_pose) {
        pose = m_hooks.camera_pose();
      } else {
        throw InputError(where + ": give \"eye\" and \"direction\" (no window to take the camera from)");
      }
      const std::vector<Vec3> region = world_points(action, where);
      SpotRegionSettings settings;
      if (p.contains("falloff_deg")) settings.falloff_deg = p["falloff_deg"].get<float>();
      Light spot = spot_for_region_in_scene(m_document.rays(), pose.eye, pose.direction, region, settings);
      const float d = glm::length(centroid(region) - spot.position);
      spot.intensity = p.contains("intensity") ? colour(p["intensity"]) : Rgb(d * d);  // about irradiance 1 at the region
      m_document.apply("spotlight for a region", [&](PaintState& s) {
        s.lights.push_back(spot);
        s.spot_hints.push_back(spot);
      });
    } else if (type == "adjust_region") {
      if (m_job.busy()) throw InputError(where + ": wait for the running solve to finish");
      const float radius = p.contains("radius") ? p["radius"].get<float>() : m_brush.radius;
      RegionAdjustSettings settings;
      settings.multiplier = colour(p["multiplier"]);
      if (p.contains("min_share")) settings.min_share = p["min_share"].get<double>();
      const auto region = region_vertices(m_document.rays(), world_points(action, where), radius);
      RegionAdjustResult result = adjust_region(m_document, m_job.renderer(), region, settings);
      log("adjusted " + std::to_string(result.changed_lights.size()) + " of " +
          std::to_string(m_document.state().lights.size()) + " lights");
    } else if (type == "solve" || type == "fine_tune" || type == "add_lights") {
      if (m_job.busy()) {
        if (!m_options.wait_for_solves) throw InputError(where + ": a solve is already running");
        finish_solve(where);
      }
      Target target = m_document.target();
      const PaintState& s = m_document.state();
      if (type != "solve" && s.lights.empty()) throw InputError(where + ": there are no lights yet (solve first)");
      m_job_revision = m_document.revision();
      if (type == "solve") m_job.start_solve(std::move(target), s.spot_hints);
      else if (type == "fine_tune") m_job.start_fine_tune(std::move(target), s.lights);
      else m_job.start_add_lights(std::move(target), s.lights);
      if (m_options.wait_for_solves) finish_solve(where);
    } else if (type == "cut") {
      if (m_job.busy()) finish_solve(where);
      const size_t k = p["k"].get<size_t>();
      if (m_job.cut_count() == 0) throw InputError(where + ": no solve to take light counts from");
      m_document.set_lights(m_job.cut_lights(k), "cut with " + std::to_string(k) + " lights");
    } else if (type == "place") {
      // Space-separated --place rules ("" clears them); a bad rule is an
      // input error naming the action, and the rules stay as they were.
      if (m_job.busy()) finish_solve(where);
      PlacementRules rules;
      std::istringstream words(p["rules"].get<std::string>());
      std::string rule;
      try {
        while (words >> rule) rules.add(rule);
      } catch (const InputError& e) {
        throw InputError(where + ": " + e.what());
      }
      m_job.set_placement(std::move(rules));
      log(where + ": lights may stand: " + (p["rules"].get<std::string>().empty() ? "anywhere free" : p["rules"].get<std::string>()));
    } else if (type == "undo") {
      m_document.undo();
    } else if (type == "redo") {
      m_document.redo();
    } else {
      // The lights are about to change under them (a replay, which waits for
      // each job, would save the job's result): wait for it.
      if ((type == "save_lights" || type == "screenshot") && m_job.busy() && !m_options.wait_for_solves)
        throw InputError(where + ": wait for the running solve to finish");
      const std::filesystem::path path = m_options.base_dir / p["path"].get<std::string>();
      if (type == "save_target") m_document.save_target(path);
      else if (type == "save_lights") m_document.save_lights(path);
      else if (type == "load_target") m_document.load_target(path);
      else if (type == "load_lights") m_document.load_lights(path);
      else if (type == "screenshot") {
        if (m_hooks.screenshot) m_hooks.screenshot(path);
        else log(where + ": no window, no screenshot");
      }
    }
  } catch (const InputError& e) {
    const std::string what = e.what();
    throw InputError(m_options.source, what.rfind("action ", 0) == 0 ? what : where + ": " + what);
  }
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
  label << to_string(result.kind) << ": " << result.lights.size() << " lights";
  m_document.set_lights(result.lights, label.str());
  std::ostringstream line;
  line << label.str() << ", D̄ " << 100.0 * result.report.dbar << "%";
  log(line.str());
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
