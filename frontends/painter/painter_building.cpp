// Inside buildings (issue 20): the Building panel and keys for the cutaway,
// the section, the plan view, walk mode and the room focus. Each change is a
// recorded action (`cutaway`, `section`, `plan`, `walk`, `focus`), so a
// replay sees what the designer saw and paints where they could.
#include "hilight/plan_view.hpp"
#include "painter_app.hpp"
#include "ui/tooltip.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <imgui.h>

namespace hilight::painter {

using ui::tip;

float PainterApp::section_height() {
  if (!m_building.section_height) {
    const Bounds& b = m_scene->bounds;
    m_building.section_height = 0.5f * (b.lo.y + b.hi.y);
  }
  return *m_building.section_height;
}

void PainterApp::set_section(std::optional<float> height) {
  if (height) m_building.section_height = *height;
  perform(SectionAction{height});
}

void PainterApp::handle_building_keys() {
  auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (pressed(GLFW_KEY_C)) perform(CutawayAction{!m_player->clip().cutaway});
  if (pressed(GLFW_KEY_K)) set_section(m_player->clip().section ? std::nullopt : std::optional<float>(section_height()));
  // Page Up / Down move the section by 2% of the scene's height (turning it on).
  const float step = 0.02f * (m_scene->bounds.hi.y - m_scene->bounds.lo.y);
  if (ImGui::IsKeyPressed(GLFW_KEY_PAGE_UP)) set_section(section_height() + step);
  if (ImGui::IsKeyPressed(GLFW_KEY_PAGE_DOWN)) set_section(section_height() - step);
  if (pressed(GLFW_KEY_T)) toggle_plan(!m_plan.has_value());
  if (pressed(GLFW_KEY_V)) perform(WalkAction{!m_building.walking, std::nullopt, std::nullopt});
}

void PainterApp::toggle_plan(bool on) {
  // A building's plan from above its roof shows the roof: with no section,
  // cut first at the storey the camera stands in (recorded, so replays agree).
  if (on && !m_player->clip().section) {
    if (m_storeys.empty()) m_storeys = plan_sections(*m_scene);
    const Vec3 eye = m_camera.to_camera().eye;
    const PlanSection* storey = &m_storeys.front();
    for (const PlanSection& s : m_storeys)
      if (s.floor <= eye.y) storey = &s;
    // (A scene with no floors gets one section over everything: nothing to cut.)
    if (storey->section < m_scene->bounds.hi.y) set_section(storey->section);
  }
  perform(PlanAction{on});
}

void PainterApp::set_plan(bool on) {
  if (!on) {
    m_plan.reset();
    return;
  }
  // The focused rooms, or the whole scene; below the section when there is one.
  Bounds area;
  for (int r : m_player->focus()) {
    area.extend(m_player->regions().list()[size_t(r)].box.lo);
    area.extend(m_player->regions().list()[size_t(r)].box.hi);
  }
  if (area.empty()) area = m_scene->bounds;
  if (const auto section = m_player->clip().section) area.hi.y = std::max(area.lo.y, std::min(area.hi.y, *section));
  m_building.walking = false;
  m_plan.emplace(area, m_scene->diagonal());
}

void PainterApp::frame_room(const Bounds& box) {
  // From above and in front (+Z), far enough for the room's diagonal to fit the view.
  Camera c = m_camera.to_camera();
  const Vec3 centre = box.center();
  c.target = Vec3(centre.x, box.lo.y, centre.z);
  const float half_fov = 0.5f * c.fov_deg * float(kPi) / 180.f;
  const float distance = 0.6f * box.diagonal() / std::max(std::tan(half_fov), 0.05f);
  c.eye = c.target + distance * glm::normalize(Vec3(0.f, 1.2f, 1.f));
  m_building.walking = false;
  m_camera = ui::OrbitCamera::from_camera(c, m_scene->diagonal(), m_scene->bounds.center());
  if (m_plan) set_plan(true);  // the plan shows the focused rooms too
  view_changed();
}

void PainterApp::panel_rooms() {
  // The rooms are found (a voxel flood fill) only once the list is opened.
  m_building.rooms_open = ImGui::TreeNode("Rooms");
  tip("The scene's rooms (LightSpace regions, numbered as hilight info lists them). Click: focus on a room "
      "(Ctrl+click: add it); double-click a floor in the view does the same. Solves then fit only what is "
      "painted in the focused rooms and put lights only there.");
  if (!m_building.rooms_open) return;
  const std::vector<int>& focus = m_player->focus();
  if (ImGui::Selectable("none", focus.empty())) perform(FocusAction{{}, std::nullopt, true});
  for (const Region& r : m_player->regions().list()) {
    const Vec3 size = r.box.extent();
    char label[96];
    std::snprintf(label, sizeof label, "region %d: %.1f x %.1f m, %.0f m3", r.id, size.x, size.z, r.volume);
    const bool focused = std::find(focus.begin(), focus.end(), r.id) != focus.end();
    // A building's outside and the voids under its slabs are listed, not offered (as hilight info lists them).
    if (const std::string why = not_a_room(r); !why.empty()) {
      ImGui::TextDisabled("%s: %s", label, why.c_str());
      continue;
    }
    if (ImGui::Selectable(label, focused)) {
      std::vector<int> rooms = ImGui::GetIO().KeyCtrl ? focus : std::vector<int>{};
      if (!focused || !ImGui::GetIO().KeyCtrl) rooms.push_back(r.id);
      else rooms.erase(std::find(rooms.begin(), rooms.end(), r.id));
      perform(rooms.empty() ? FocusAction{{}, std::nullopt, true} : FocusAction{rooms, std::nullopt, false});
    }
  }
  ImGui::TreePop();
}

void PainterApp::draw_plan_readouts() {
  if (!m_plan || !m_display.show_lights) return;
  // Each light's number, intensity (luminance of its RGB intensity, W/sr) and the lux on the floor below it, beside its marker.
  int w = 1, h = 1;
  m_window->framebuffer_size(w, h);
  const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
  const glm::mat4 vp = view_projection();
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const Lighting& lights = m_document->state().lights;
  for (size_t i = 0; i < lights.size(); ++i) {
    const glm::vec4 clip = vp * glm::vec4(lights[i].position, 1.f);
    if (!(clip.w > 0.f)) continue;
    const float x = (0.5f + 0.5f * clip.x / clip.w) * float(w) / std::max(scale.x, 1e-3f);
    const float y = (0.5f - 0.5f * clip.y / clip.w) * float(h) / std::max(scale.y, 1e-3f);
    const Rgb& I = lights[i].intensity;
    char text[128];
    // Every number with its unit; the lux on the floor of the light's storey, not on the first thing below it.
    const int n = std::snprintf(text, sizeof text, "%zu: I %.3g W/sr", i, 0.2126 * I.r + 0.7152 * I.g + 0.0722 * I.b);
    // The lux below it once the result view shows these lights.
    if (m_display.radiance_lights == lights) {
      if (m_storeys.empty()) m_storeys = plan_sections(*m_scene);
      const float floor = storey_floor(m_storeys, lights[i].position);
      if (const auto lux = lux_on_floor(*m_rays, m_display.radiance, m_albedo, lights[i].position, floor))
        std::snprintf(text + n, sizeof text - size_t(n), ", %.0f lx on the floor", *lux);
    }
    draw->AddText(ImVec2(x + 6.f, y - 6.f), IM_COL32(255, 240, 160, 255), text);
  }
}

void PainterApp::panel_building() {
  if (!ImGui::CollapsingHeader("Building", ImGuiTreeNodeFlags_DefaultOpen)) return;
  bool cutaway = m_player->clip().cutaway;
  if (ImGui::Checkbox("cutaway (C)", &cutaway)) perform(CutawayAction{cutaway});
  tip("Hide the walls and ceilings in front of what the camera looks at (the doll's house view). "
      "They still cast shadows and bounce light; they only take no paint.");
  bool section = m_player->clip().section.has_value();
  ImGui::SameLine();
  if (ImGui::Checkbox("section (K)", &section)) set_section(section ? std::optional<float>(section_height()) : std::nullopt);
  tip("Hide everything above a height, to see one storey from above");
  float height = section_height();
  const Bounds& b = m_scene->bounds;
  if (ImGui::SliderFloat("section height", &height, b.lo.y, b.hi.y, "%.2f")) {
    // Live while dragging (view only); recorded once, when released.
    m_building.section_height = height;
    ViewClip clip = m_player->clip();
    clip.section = height;
    m_player->set_clip(clip);
  }
  if (ImGui::IsItemDeactivatedAfterEdit()) set_section(height);
  tip("World height (+Y) of the section; Page Up / Page Down move it");
  bool plan = m_plan.has_value();
  if (ImGui::Checkbox("plan (T)", &plan)) toggle_plan(plan);
  tip("An orthographic top view of the section (or of the focused rooms), with the lights' numbers, intensities (W/sr) "
      "and the lux on the floor straight below each");
  ImGui::SameLine();
  bool walking = m_building.walking;
  if (ImGui::Checkbox("walk (V)", &walking)) perform(WalkAction{walking, std::nullopt, std::nullopt});
  tip("First person at eye height: W A S D move, right drag looks around; walls stop you. V returns to orbiting.");
  panel_rooms();
}

} // namespace hilight::painter
