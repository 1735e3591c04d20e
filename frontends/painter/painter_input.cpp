// Mouse and keyboard: camera moves, the tools, shortcuts. Everything that
// changes the document goes through perform() (applied by the player and
// recorded); brush strokes paint live and are recorded when released.
#include "painter_app.hpp"
#include "ui/screen_pick.hpp"

#include <algorithm>
#include <cmath>
#include <imgui.h>

namespace hilight::painter {

namespace {

/// At most `limit` points, evenly thinned (a long drag samples every frame).
std::vector<Vec3> thinned(const std::vector<Vec3>& points, size_t limit) {
  if (points.size() <= limit) return points;
  std::vector<Vec3> out;
  for (size_t i = 0; i < limit; ++i) out.push_back(points[i * (points.size() - 1) / (limit - 1)]);
  return out;
}

constexpr float kClickPixels = 4.f;

} // namespace

std::optional<SurfacePick> PainterApp::pick_at_mouse() const {
  const ImGuiIO& io = ImGui::GetIO();
  return pick_window_pixel(io.MousePos.x * io.DisplayFramebufferScale.x, io.MousePos.y * io.DisplayFramebufferScale.y);
}

void PainterApp::handle_input() {
  handle_keys();
  // Walking, the mouse and WASD move the eye instead of the orbit; the plan is fixed by its area.
  if (m_building.walking) handle_walk_input();
  else if (!m_plan) handle_camera_input();
  handle_tool_input();
}

void PainterApp::handle_camera_input() {
  const ImGuiIO& io = ImGui::GetIO();
  const bool over_ui = io.WantCaptureMouse && !m_tools.dragging_camera;
  const ImVec2 delta = io.MouseDelta;
  const float height = std::max(io.DisplaySize.y, 1.f);
  // Right drag (or Alt + left) orbits; middle drag (or Shift + right) pans; the wheel zooms.
  const bool orbit = !io.KeyShift && (ImGui::IsMouseDown(ImGuiMouseButton_Right) || (io.KeyAlt && ImGui::IsMouseDown(ImGuiMouseButton_Left)));
  const bool pan = ImGui::IsMouseDown(ImGuiMouseButton_Middle) || (io.KeyShift && ImGui::IsMouseDown(ImGuiMouseButton_Right));
  const bool start = ImGui::IsMouseClicked(ImGuiMouseButton_Right) || ImGui::IsMouseClicked(ImGuiMouseButton_Middle) ||
                     (io.KeyAlt && ImGui::IsMouseClicked(ImGuiMouseButton_Left));
  if (start && !over_ui) m_tools.dragging_camera = true;
  if (m_tools.dragging_camera && !orbit && !pan) {
    m_tools.dragging_camera = false;
    record_camera();  // one action per drag: where the camera ended
  }
  if (m_tools.dragging_camera && (delta.x != 0.f || delta.y != 0.f)) {
    if (orbit) m_camera.orbit(-0.4f * delta.x, 0.4f * delta.y);
    else if (pan) m_camera.pan(-delta.x / height, delta.y / height);
    m_display.last_activity = "camera";
  }
  if (!io.WantCaptureMouse && io.MouseWheel != 0.f) {
    m_camera.zoom(std::pow(0.9f, io.MouseWheel));
    m_display.last_activity = "camera";
    CameraAction zoom;
    zoom.zoom = std::pow(0.9f, io.MouseWheel);
    record(zoom);
  }
}

void PainterApp::handle_keys() {
  const ImGuiIO& io = ImGui::GetIO();
  auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (io.KeyCtrl && pressed(GLFW_KEY_Q)) m_window->request_close();  // even with a dialog open
  if (io.WantCaptureKeyboard) return;
  if (io.KeyCtrl) {
    if (pressed(GLFW_KEY_Z) && !io.KeyShift) perform(UndoAction{});
    if (pressed(GLFW_KEY_Y) || (pressed(GLFW_KEY_Z) && io.KeyShift)) perform(RedoAction{});
    return;
  }
  auto select = [&](Tool tool) { perform(ToolAction{tool}); };
  if (pressed(GLFW_KEY_B)) select(Tool::Brush);
  if (pressed(GLFW_KEY_E)) select(Tool::Eraser);
  if (pressed(GLFW_KEY_S) && !m_building.walking) select(Tool::Shadow);  // walking, WASD move
  if (pressed(GLFW_KEY_X)) select(Tool::EraseShadow);
  if (pressed(GLFW_KEY_P)) select(Tool::Spot);
  if (pressed(GLFW_KEY_A) && !m_building.walking) select(Tool::Adjust);
  // Views are recorded actions, so a replay's screenshots show what the designer saw.
  if (pressed(GLFW_KEY_1)) perform(ViewAction{ViewShown::Result});
  if (pressed(GLFW_KEY_2)) perform(ViewAction{ViewShown::Target});
  if (pressed(GLFW_KEY_3)) perform(ViewAction{ViewShown::Difference});
  if (pressed(GLFW_KEY_L)) m_display.show_lights = !m_display.show_lights;
  handle_building_keys();
  if (pressed(GLFW_KEY_F1) || pressed(GLFW_KEY_H)) m_status_panel.show_help = !m_status_panel.show_help;
  if ((pressed(GLFW_KEY_ENTER) || pressed(GLFW_KEY_KP_ENTER)) && m_player->tool() == Tool::Shadow) lights_from_shadows();
  if (pressed(GLFW_KEY_F5)) start_job(SolveAction{});
  if (pressed(GLFW_KEY_F6)) start_job(FineTuneAction{});
  if (pressed(GLFW_KEY_F7)) start_job(AddLightsAction{});
  if (pressed(GLFW_KEY_ESCAPE) && m_job->busy()) m_job->cancel();
  if (pressed(GLFW_KEY_F) && !m_building.walking) {
    m_camera = ui::OrbitCamera::framing(m_scene->bounds, aspect());
    record_camera();
  }
  if (pressed(GLFW_KEY_LEFT_BRACKET) || pressed(GLFW_KEY_RIGHT_BRACKET)) {
    BrushSettings brush = m_player->brush();
    brush.radius *= pressed(GLFW_KEY_LEFT_BRACKET) ? 0.8f : 1.25f;
    // Within the radius slider's range, as a typed-in value would be.
    brush.radius = std::clamp(brush.radius, 0.002f * m_scene->diagonal(), 0.25f * m_scene->diagonal());
    BrushAction radius;
    radius.radius = brush.radius;
    perform(radius);
  }
  if (m_building.walking || m_plan) return;
  // Arrow keys orbit, +/- zoom: the camera without a mouse.
  const float step = 3.f;
  bool moved = false;
  if (ImGui::IsKeyDown(GLFW_KEY_LEFT)) { m_camera.orbit(step, 0.f); moved = true; }
  if (ImGui::IsKeyDown(GLFW_KEY_RIGHT)) { m_camera.orbit(-step, 0.f); moved = true; }
  if (ImGui::IsKeyDown(GLFW_KEY_UP)) { m_camera.orbit(0.f, step); moved = true; }
  if (ImGui::IsKeyDown(GLFW_KEY_DOWN)) { m_camera.orbit(0.f, -step); moved = true; }
  if (ImGui::IsKeyDown(GLFW_KEY_EQUAL) || ImGui::IsKeyDown(GLFW_KEY_KP_ADD)) { m_camera.zoom(0.97f); moved = true; }
  if (ImGui::IsKeyDown(GLFW_KEY_MINUS) || ImGui::IsKeyDown(GLFW_KEY_KP_SUBTRACT)) { m_camera.zoom(1.03f); moved = true; }
  if (moved) {
    m_display.last_activity = "camera";
    m_tools.camera_keys_unrecorded = true;
  } else if (m_tools.camera_keys_unrecorded) {
    m_tools.camera_keys_unrecorded = false;
    record_camera();  // the keys were let go
  }
}

void PainterApp::record_camera() {
  // Absolute (eye, target, fov): replays see the same view whatever came before.
  const Camera c = m_camera.to_camera();
  CameraAction pose;
  pose.eye = c.eye;
  pose.target = c.target;
  pose.fov = c.fov_deg;
  record(pose);
  view_changed();
}

void PainterApp::start_job(const TypedAction& job) {
  if (m_job->busy()) {
    status("a " + std::string(std::holds_alternative<SolveAction>(job) ? "solve" : "job") + " is already running (Esc cancels it)");
    return;
  }
  perform(job);
}

void PainterApp::handle_tool_input() {
  const ImGuiIO& io = ImGui::GetIO();
  const bool over_ui = io.WantCaptureMouse;
  m_tools.hover = over_ui || m_tools.dragging_camera ? std::nullopt : pick_at_mouse();
  if (m_tools.dragging_camera || io.KeyAlt) return;
  const Tool tool = m_player->tool();
  // A double click focuses the room of the surface under it. Its first click
  // was a one-dab stroke (already recorded): undone, so it only focuses.
  if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && !over_ui && m_tools.hover && !m_tools.stroke) {
    if (m_tools.click_revision == m_document->revision()) perform(UndoAction{});
    m_tools.click_revision.reset();
    FocusAction focus;
    focus.world = m_tools.hover->position;
    perform(focus);
    return;
  }
  const bool pressed = ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !over_ui;
  const bool down = ImGui::IsMouseDown(ImGuiMouseButton_Left);
  const bool released = ImGui::IsMouseReleased(ImGuiMouseButton_Left);

  if (tool == Tool::Brush || tool == Tool::Eraser) {
    if (pressed) {
      m_tools.stroke_start_revision = m_document->revision();
      // Hidden surfaces (section, cutaway) take no paint; the camera does not move during a stroke.
      m_tools.stroke = std::make_unique<Stroke>(*m_document, m_player->brush(), tool == Tool::Eraser ? BrushMode::Erase : BrushMode::Paint,
                                                &m_player->visibility());
      if (m_display.view == ui::ViewMode::Result) perform(ViewAction{ViewShown::Target});  // paint is seen in the target view
      if (m_tools.hover) m_tools.stroke->dab(*m_tools.hover);
    } else if (m_tools.stroke && down && m_tools.hover && (io.MouseDelta.x != 0.f || io.MouseDelta.y != 0.f)) {
      if (m_tools.stroke->points().empty()) m_tools.stroke->dab(*m_tools.hover);
      else m_tools.stroke->drag_to(*m_tools.hover);
    }
    if (m_tools.stroke) m_display.last_activity = "stroke";
    if (m_tools.stroke && released) finish_stroke();
    return;
  }
  if (tool == Tool::EraseShadow) {
    if (pressed && m_tools.hover) {
      auto pairs = find_shadow_pairs(m_player->objects(), *m_rays, m_document->state().lights, *m_tools.hover);
      const Vec3 p = m_tools.hover->position;
      if (pairs.empty()) status("no light is blocked here: nothing to erase");
      else if (pairs.size() == 1) perform(EraseShadowAction{p, std::nullopt, std::nullopt});
      else {
        m_tools.erase_click = p;
        m_tools.pair_choices = pairs;  // the "Which shadow?" popup asks which to erase
      }
    }
    return;
  }
  // Shadow, spot and adjust take a dragged region; a click in the shadow tool selects the occluder.
  if (pressed) begin_region_drag();
  if (m_tools.region_drag && down && m_tools.hover) {
    if (m_tools.region.empty() || glm::length(m_tools.region.back() - m_tools.hover->position) > 0.005f * m_scene->diagonal())
      m_tools.region.push_back(m_tools.hover->position);
  }
  if (m_tools.region_drag) m_display.last_activity = "stroke";
  if (m_tools.region_drag && released) finish_region_drag();
}

void PainterApp::lights_from_shadows() {
  if (m_tools.shadow_pairs.empty()) {
    status("no shadow requests yet: click an occluder, then drag where its shadow falls");
    return;
  }
  if (perform(ShadowAction{m_tools.shadow_pairs})) m_tools.shadow_pairs.clear();
}

void PainterApp::finish_stroke() {
  const BrushMode mode = m_player->tool() == Tool::Eraser ? BrushMode::Erase : BrushMode::Paint;
  std::vector<Vec3> points = m_tools.stroke->points();
  std::vector<Vec3> normals = m_tools.stroke->normals();
  m_tools.stroke->finish();
  m_tools.stroke.reset();
  m_tools.click_revision.reset();
  if (points.size() == 1 && m_document->revision() != m_tools.stroke_start_revision) m_tools.click_revision = m_document->revision();
  if (points.empty()) return;
  // With the normals: a replay paints the same faces (pick_near may choose the other one at a crease).
  record(StrokeAction{PointSet{points, {}, normals}, mode == BrushMode::Erase});
  // §4.2 fine-tune: the lights follow the edit at once when there are any.
  if (m_options.auto_fine_tune && !m_document->state().lights.empty()) {
    if (m_job->busy()) {
      m_solve_panel.fine_tune_queued = true;  // after the running job (poll_workers starts it)
      return;
    }
    m_solve_panel.stroke_released = Clock::now();
    m_solve_panel.fine_tune_after_stroke = perform(Action{"fine_tune", nlohmann::json::object()});
    if (!m_solve_panel.fine_tune_after_stroke) m_solve_panel.stroke_released.reset();
  }
}

void PainterApp::begin_region_drag() {
  m_tools.region.clear();
  m_tools.region_drag = true;
}

void PainterApp::finish_region_drag() {
  m_tools.region_drag = false;
  const Tool tool = m_player->tool();
  const ImVec2 drag = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.f);
  const bool click = std::hypot(drag.x, drag.y) < kClickPixels;
  std::vector<Vec3> region = thinned(m_tools.region, 256);
  m_tools.region.clear();
  if (tool == Tool::Shadow && click) {
    if (m_tools.hover) {
      m_tools.occluder_point = m_tools.hover->position;
      const Hit hit = m_rays->closest_point(m_tools.hover->position, 0.01f * m_scene->diagonal());
      if (hit.valid())
        status("occluder: " + m_player->objects().name(m_player->objects().object_of_triangle(hit.triangle)) +
               " - now drag where its shadow should fall");
    }
    return;
  }
  if (region.empty()) return;
  if (tool == Tool::Shadow) {
    if (!m_tools.occluder_point) {
      status("click the object that casts the shadow first");
      return;
    }
    const Vec3 o = *m_tools.occluder_point;
    m_tools.shadow_pairs.push_back(ShadowAction::Pair{o, std::nullopt, PointSet{region, {}, {}}});
    status(std::to_string(m_tools.shadow_pairs.size()) + " shadow request(s): press 'Lights from shadows', or add more");
  } else if (tool == Tool::Spot) {
    const CameraPose pose = camera_pose();
    SpotRegionAction spot;
    spot.points.world = region;
    spot.eye = pose.eye;
    spot.direction = pose.direction;
    spot.falloff_deg = m_tools.spot_falloff;
    perform(spot);
  } else if (tool == Tool::Adjust) {
    const Rgb& m = m_tools.adjust_multiplier;
    AdjustRegionAction adjust;
    adjust.points.world = region;
    adjust.multiplier = m;
    adjust.radius = m_player->brush().radius;
    perform(adjust);
  }
}

} // namespace hilight::painter
