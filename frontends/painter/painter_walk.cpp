// Walk mode (issue 20): a first-person eye at eye height, moved by WASD and
// turned by mouse look, stopped by walls (core/walk.hpp, the scene's ray
// tracer, as LightSpace sees free space). The orbit camera carries it: its
// target a metre ahead of the eye. Replays use `walk` actions; the window
// records where the walk ended as one absolute `camera` action.
#include "core/walk.hpp"
#include "hilight/error.hpp"
#include "painter_app.hpp"

#include <algorithm>
#include <cmath>
#include <imgui.h>

namespace hilight::painter {

namespace {

/// Walking speed, scene units (metres) per second.
constexpr float kWalkSpeed = 1.5f;

/// The horizontal unit direction of `look` (+Z if it looks straight up or down).
Vec3 horizontal(const Vec3& look) {
  const Vec3 h(look.x, 0.f, look.z);
  return glm::length(h) > 1e-6f ? glm::normalize(h) : Vec3(0.f, 0.f, 1.f);
}

} // namespace

void PainterApp::apply_walk(const WalkAction& a) {
  const Camera c = m_camera.to_camera();
  Vec3 eye = c.eye;
  Vec3 look = glm::normalize(c.target - c.eye);
  auto place = [&](const Vec3& at, const Vec3& towards) {
    Camera pose = c;
    pose.eye = at;
    pose.target = at + towards;
    m_camera = ui::OrbitCamera::from_camera(pose, m_scene->diagonal(), m_scene->bounds.center());
  };
  if (a.on && *a.on && !m_building.walking) {
    // Stand on the floor under where the orbit looked (from just above it: a
    // target on the floor itself), looking the same way, level.
    m_plan.reset();
    m_building.walking = true;
    eye = stand_at(*m_rays, c.target + Vec3(0.f, 0.1f, 0.f));
    look = horizontal(look);
  } else if (a.on && !*a.on && m_building.walking) {
    // Back to orbiting, about a point two metres ahead.
    m_building.walking = false;
    place(eye, 2.f * look);
    return;
  }
  if (!m_building.walking && (a.move || a.turn)) throw InputError("walk: not in walk mode (give \"on\": true first)");
  if (a.turn) {
    // Yaw about +Y, pitch within ±80° (the orbit camera's range).
    const float yaw = std::atan2(look.x, look.z) + a.turn->x * float(kPi) / 180.f;
    const float pitch = std::clamp(std::asin(std::clamp(look.y, -1.f, 1.f)) + a.turn->y * float(kPi) / 180.f,
                                   -80.f * float(kPi) / 180.f, 80.f * float(kPi) / 180.f);
    look = Vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
  }
  if (a.move) {
    const Vec3 forward = horizontal(look), right = glm::normalize(glm::cross(forward, Vec3(0.f, 1.f, 0.f)));
    eye = walk_step(*m_rays, eye, a.move->x * forward + a.move->y * right);
  }
  place(eye, look);
}

void PainterApp::handle_walk_input() {
  const ImGuiIO& io = ImGui::GetIO();
  if (!m_building.walking) return;
  WalkAction step;
  if (!io.WantCaptureKeyboard && !io.KeyCtrl) {
    const float d = kWalkSpeed * std::min(io.DeltaTime, 0.1f);
    Vec2 move(0.f);
    if (ImGui::IsKeyDown(GLFW_KEY_W)) move.x += d;
    if (ImGui::IsKeyDown(GLFW_KEY_S)) move.x -= d;
    if (ImGui::IsKeyDown(GLFW_KEY_D)) move.y += d;
    if (ImGui::IsKeyDown(GLFW_KEY_A)) move.y -= d;
    if (move != Vec2(0.f)) step.move = move;
  }
  // Mouse look: the orbit's drag (right, or Alt + left) turns the head.
  const bool look = ImGui::IsMouseDown(ImGuiMouseButton_Right) || (io.KeyAlt && ImGui::IsMouseDown(ImGuiMouseButton_Left));
  if (look && !io.WantCaptureMouse && (io.MouseDelta.x != 0.f || io.MouseDelta.y != 0.f))
    step.turn = Vec2(-0.25f * io.MouseDelta.x, -0.25f * io.MouseDelta.y);
  if (step.move || step.turn) {
    apply_walk(step);
    m_display.last_activity = "camera";
    m_building.walk_unrecorded = true;
  } else if (m_building.walk_unrecorded) {
    m_building.walk_unrecorded = false;
    record_camera();  // where the walk ended, replayable whatever the steps were
  }
}

} // namespace hilight::painter
