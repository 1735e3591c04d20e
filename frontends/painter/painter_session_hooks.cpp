// The window's side of session actions: camera moves, screen picking and
// screenshots for the core's SessionPlayer; applying and recording actions.
#include "hilight/error.hpp"
#include "hilight/io/scene_io.hpp"
#include "ifc_spaces.hpp"
#include "painter_app.hpp"
#include "solve_options.hpp"
#include "ui/screen_pick.hpp"
#include "ui/screenshot.hpp"

#include <cstdio>
#include <cstdlib>
#include <ctime>

namespace hilight::painter {

PlayerHooks PainterApp::make_hooks() {
  PlayerHooks hooks;
  hooks.camera = [this](const CameraAction& action) {
    apply_camera_action(action);
    view_changed();
  };
  hooks.camera_pose = [this] { return camera_pose(); };
  hooks.pick_screen = [this](const std::array<float, 2>& xy) { return pick_window_pixel(xy[0], xy[1]); };
  hooks.plan = [this](bool on) {
    set_plan(on);
    view_changed();
  };
  hooks.walk = [this](const WalkAction& action) {
    apply_walk(action);
    view_changed();
  };
  hooks.frame = [this](const Bounds& box) { frame_room(box); };
  hooks.screenshot = [this](const std::filesystem::path& path, bool panels) { screenshot(path, panels); };
  hooks.view = [this](ViewShown show) {
    m_display.view = show == ViewShown::Target ? ui::ViewMode::Target : show == ViewShown::Difference ? ui::ViewMode::Difference : ui::ViewMode::Result;
    m_display.colours_dirty = true;
  };
  hooks.log = [this](const std::string& line) { status(line); };
  hooks.fit = [this](const JobResult& result) { show_fit(result); };
  hooks.open_scene = [this](const std::filesystem::path& path) {
    // Read before the window closes: a scene that cannot be read is a status
    // line (InputError, the action not recorded), and the painting stays.
    status("opening " + path.string() + "...");
    m_next_scene = std::make_shared<const Scene>(load_scene(path, m_options.scene_options));
    m_open_scene = std::filesystem::absolute(path).lexically_normal();
  };
  hooks.not_a_room = [this](const Region& region) { return not_a_room(region); };
  hooks.settle_placement = [this](PlacementRules& rules, std::shared_ptr<const Regions> regions) {
    // hilight solve's own path, so the same text gives the same rules.
    const cli::PlacementScene scene{m_scene, m_options.ifc_storeys,
                                    [this](const RayScene& rays) {
                                      // Read once, as hilight solve reads them (ifc_spaces.hpp); the command line's rules may have already.
                                      if (!m_solve_panel.named_rooms) m_solve_panel.named_rooms = cli::scene_rooms(m_options.scene, rays);
                                      return *m_solve_panel.named_rooms;
                                    },
                                    std::move(regions)};
    const std::string note = cli::settle_placement(rules, scene, true);
    m_solve_panel.building_note = note;
    m_solve_panel.noted_rules = rules.describe();
    return note;
  };
  return hooks;
}

std::string PainterApp::not_a_room(const Region& region) {
  // What makes the scene a building is asked once per scene (it samples every surface).
  if (!m_building.kind) m_building.kind = cli::building_kind(*m_scene, m_options.ifc_storeys);
  const std::string why = cli::why_not_a_room(region, *m_building.kind);
  return why.empty() ? "" : "not a room of " + *m_building.kind + " (" + why + ")";
}

void PainterApp::show_fit(const JobResult& result) {
  const SolveReport& r = result.report;
  if (m_job->has_criteria()) {  // hilight solve's lines for criteria
    m_solve_panel.fit_line = std::to_string(result.lights.size()) + " luminaire" + (result.lights.size() == 1 ? "" : "s") + ", criteria " +
                             (result.criteria_met ? "met" : "NOT met");
    m_solve_panel.fit_notes = result.criteria_notes;
    for (const FitNote& note : m_solve_panel.fit_notes) status((note.warning ? "warning: " : "") + note.text);
    m_display.unreachable.clear();
    m_display.colours_dirty = true;
    return;
  }
  char line[160];
  std::snprintf(line, sizeof line, "%s: %zu light%s, D̄ %.1f%%", to_string(result.kind), r.chosen, r.chosen == 1 ? "" : "s", 100.0 * r.dbar);
  m_solve_panel.fit_line = line;
  // hilight solve's own words (fit_notes.hpp); the building default counts
  // while the rules are still the ones it noted.
  const SolveSettings& settings = m_job->options().settings;
  const bool building_default = !m_solve_panel.building_note.empty() && settings.placement.describe() == m_solve_panel.noted_rules;
  m_solve_panel.fit_notes = fit_notes(r, {settings.fixed_count, building_default});
  for (const FitNote& note : m_solve_panel.fit_notes) status((note.warning ? "warning: " : "") + note.text);
  m_display.unreachable = result.unreachable_vertices;
  if (const auto it = r.seconds.find("diagnosis"); it != r.seconds.end()) m_timer.add_latency("poor_fit_diagnosis", 1000.0 * it->second);
  m_display.colours_dirty = true;
}

CameraPose PainterApp::camera_pose() const {
  if (m_plan) return CameraPose{m_plan->eye(), Vec3(0.f, -1.f, 0.f), m_plan->target()};
  const Camera camera = m_camera.to_camera();
  // Walking one is inside the room: the cutaway (focus = eye) hides nothing,
  // or a wall would vanish as the eye comes near it.
  return CameraPose{camera.eye, glm::normalize(camera.target - camera.eye), m_building.walking ? camera.eye : camera.target};
}

glm::mat4 PainterApp::view_projection() const {
  if (m_plan) return m_plan->projection(aspect()) * m_plan->view();
  return m_camera.projection(aspect()) * m_camera.view();
}

std::optional<SurfacePick> PainterApp::pick_window_pixel(float x, float y) const {
  int w = 1, h = 1;
  m_window->framebuffer_size(w, h);
  const ui::Ray ray = m_plan ? m_plan->ray_through(x, y, float(w), float(h), aspect()) : m_camera.ray_through(x, y, float(w), float(h));
  return ui::pick_front_face(*m_rays, ray, m_player->visibility());
}

void PainterApp::apply_camera_action(const CameraAction& a) {
  if (a.eye) {
    Camera camera = m_camera.to_camera();
    camera.eye = *a.eye;
    camera.target = *a.target;
    if (glm::length(camera.eye - camera.target) <= 0.f) throw InputError("camera: eye and target coincide");
    m_camera = ui::OrbitCamera::from_camera(camera, m_scene->diagonal(), m_scene->bounds.center());
  }
  if (a.fov) {
    Camera camera = m_camera.to_camera();
    camera.fov_deg = *a.fov;
    m_camera = ui::OrbitCamera::from_camera(camera, m_scene->diagonal(), m_scene->bounds.center());
  }
  if (a.orbit) m_camera.orbit(a.orbit->x, a.orbit->y);
  if (a.pan) m_camera.pan(a.pan->x, a.pan->y);
  if (a.zoom) m_camera.zoom(*a.zoom);
}

bool PainterApp::perform(const Action& action) {
  try {
    m_player->apply(action);
  } catch (const InputError& e) {
    if (m_headless) throw;
    status(e.what());
    return false;
  }
  record(action);
  if (action.type == SolveAction::kType || action.type == FineTuneAction::kType || action.type == AddLightsAction::kType)
    m_job_action = m_recorder.session().actions.size() - 1;
  return true;
}

void PainterApp::unrecord_failed_job() {
  // A job that failed or was cancelled changed nothing: drop its action, so
  // the recording replays (a replay stops at a failing solve).
  if (!m_job_action || *m_job_action >= m_recorder.session().actions.size()) return;
  Session kept = m_recorder.session();
  kept.actions.erase(kept.actions.begin() + std::ptrdiff_t(*m_job_action));
  m_job_action.reset();
  m_recorder.clear();
  for (const Action& a : kept.actions) m_recorder.record(a);
  if (!m_record_path.empty()) m_recorder.save(m_record_path);
}

void PainterApp::record(const Action& action) {
  try {
    m_recorder.record(action);
  } catch (const std::exception& e) {
    // An action the recorder refuses is a bug, but never a reason to lose the session.
    status(std::string("not recorded: ") + e.what());
    return;
  }
  if (action.type == BrushAction::kType) m_tools.recorded_brush = m_player->brush();
  if (m_record_path.empty()) return;
  try {
    m_recorder.save(m_record_path);
  } catch (const std::exception& e) {
    const std::string where = m_record_path.string();
    m_record_path.clear();  // say it once, then stop trying
    status("cannot record the session to " + where + ": " + e.what());
  }
}

std::filesystem::path PainterApp::default_record_path() const {
  // $XDG_STATE_HOME/hilight/sessions/ (the XDG place for "history"), else ~/.local/state/...
  std::filesystem::path base;
  if (const char* state = std::getenv("XDG_STATE_HOME"); state && *state) base = state;
  else if (const char* home = std::getenv("HOME"); home && *home) base = std::filesystem::path(home) / ".local" / "state";
  else return {};
  const std::filesystem::path dir = base / "hilight" / "sessions";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return {};
  char stamp[32];
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
  return dir / (m_options.scene.stem().string() + "-" + stamp + ".json");
}

void PainterApp::screenshot(const std::filesystem::path& path, bool panels) {
  settle();
  if (panels) {
    // ImGui sizes new windows over a frame or two: capture the third.
    frame(false);
    frame(false);
    frame(false, path);
  } else {
    draw_scene();
    int w = 1, h = 1;
    m_window->framebuffer_size(w, h);
    ui::save_screenshot(path, w, h);
  }
  status("screenshot " + path.string());
}

} // namespace hilight::painter
