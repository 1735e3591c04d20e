// The ImGui panels: tools and brush, view, solve, lights, files, help, status.
// Buttons call perform() with the same actions a session script holds.
#include "painter_app.hpp"
#include "ui/tooltip.hpp"
#include "hilight/scene_origin.hpp"
#include "hilight/units.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <imgui.h>
#include <imgui_stdlib.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace hilight::painter {

using ui::tip;

namespace {

/// ImGui's built-in font is ASCII: the core's D̄ (D + combining macron), the
/// criteria's Ē and Ēz, ≥ and ≤ spelled out.
std::string ascii(std::string text) {
  static const std::pair<const char*, const char*> spelled[] = {
      {"D\u0304", "D-bar"}, {"\u0112z", "Ez-mean"}, {"\u0112", "E-mean"}, {"\u2265", ">="}, {"\u2264", "<="}};
  for (const auto& [from, to] : spelled)
    for (size_t at; (at = text.find(from)) != std::string::npos;) text.replace(at, std::string(from).size(), to);
  return text;
}

const char* kShortcuts[][2] = {
    {"Right drag / Alt+left drag", "orbit"},
    {"Middle drag / Shift+right drag", "pan"},
    {"Wheel, + / -", "zoom"},
    {"Arrow keys", "orbit"},
    {"F", "frame the whole scene"},
    {"Left drag", "use the tool (paint, erase, mark a region)"},
    {"B / E", "brush / eraser"},
    {"S", "shadow tool: click the occluder, drag its shadow"},
    {"Enter", "shadow tool: lights from the shadows drawn"},
    {"X", "erase-shadow tool: click a shadow"},
    {"P", "spotlight tool: drag the region it should light"},
    {"A", "adjust tool: drag a region to brighten / tint"},
    {"[ / ]", "smaller / larger brush"},
    {"1 / 2 / 3", "view result I(p) / target / |difference|"},
    {"L", "show / hide lights"},
    {"C", "cutaway: hide walls and ceilings in front of the view"},
    {"K, Page Up / Down", "section on / off, raise / lower it"},
    {"T", "plan view (top, orthographic) on / off"},
    {"V, then W A S D + right drag", "walk mode on / off: move and look around"},
    {"double click", "focus on the room under the cursor"},
    {"F5 / F6 / F7", "solve / fine-tune / add lights"},
    {"Esc", "cancel the running solve"},
    {"Ctrl+Z / Ctrl+Y", "undo / redo"},
    {"H or F1", "this help"},
    {"Ctrl+Q", "quit (the session is already recorded)"},
};

} // namespace

void PainterApp::draw_panels() {
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(350, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("hilight paint", nullptr, ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_AlwaysAutoResize);
  panel_tools();
  panel_view();
  panel_building();
  panel_solve();
  panel_placement();
  panel_lights();
  panel_files();
  if (ImGui::Button("Help (H)")) m_status_panel.show_help = !m_status_panel.show_help;
  tip("Keyboard shortcuts and mouse controls");
  ImGui::End();
  panel_help();
  panel_file_browser();
  panel_status();
  draw_plan_readouts();
  popup_shadow_pairs();
}

void PainterApp::panel_tools() {
  if (!ImGui::CollapsingHeader("Tools", ImGuiTreeNodeFlags_DefaultOpen)) return;
  static const struct {
    Tool tool;
    const char* label;
    const char* help;
  } tools[] = {
      {Tool::Brush, "Brush (B)", "Paint the illumination you want (target) onto surfaces"},
      {Tool::Eraser, "Eraser (E)", "Back to \"don't care\": erased surfaces do not constrain the solve"},
      {Tool::Shadow, "Shadow (S)", "Click an object (the occluder), then drag where its shadow should fall; repeat for more pairs"},
      {Tool::EraseShadow, "Erase shadow (X)", "Click a shadow: the occluder-light pair casting it is painted away"},
      {Tool::Spot, "Spotlight (P)", "Drag over the region a spotlight should light; it stands at the camera and looks where you look"},
      {Tool::Adjust, "Adjust (A)", "Drag over a region: only the lights that light it change by the multiplier"},
  };
  for (size_t i = 0; i < std::size(tools); ++i) {
    if (i % 2) ImGui::SameLine(150);
    if (ImGui::RadioButton(tools[i].label, m_player->tool() == tools[i].tool))
      perform(ToolAction{tools[i].tool});
    tip(tools[i].help);
  }
  BrushSettings brush = m_player->brush();
  bool changed = false;
  const float diagonal = m_scene->diagonal();
  // AlwaysClamp: a value typed with Ctrl+click stays in the slider's range (a
  // zero radius would be an invalid brush action).
  changed |= ImGui::SliderFloat("radius", &brush.radius, 0.002f * diagonal, 0.25f * diagonal, "%.3f",
                                ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  tip("Brush radius in scene units ([ and ] change it)");
  changed |= ImGui::ColorEdit3("colour", &brush.colour.r, ImGuiColorEditFlags_Float);
  tip(brush.meaning == PaintMeaning::LampColour ? "The lamp's colour (linear RGB): the surface shows it as its own colour lit by such a lamp"
                                                : "The light the surface should reflect (linear RGB), its own colour included");
  // In the files' unit (--units, --target-quantity): W/(sr m2), cd/m2, or the lux the surface receives.
  const bool photometric = m_document->units() == Units::Photometric, lux = m_document->quantity() == TargetQuantity::Illuminance;
  const char* brightness_label = lux ? "brightness (lux)" : photometric ? "brightness (cd/m2)" : "brightness";
  changed |= ImGui::SliderFloat(brightness_label, &brush.brightness, 0.f, photometric ? 20000.f : 20.f, "%.2f",
                                ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  tip(lux ? "The light the surface should receive, in lux (its colour the lamp's)"
          : photometric ? "How bright the surface should look: its luminance in cd/m2 = that of colour x brightness"
                        : "How bright the surface should look: its luminance in W/(sr m2) = that of colour x brightness");
  int meaning = int(brush.meaning);
  ImGui::TextUnformatted("paint means");
  ImGui::SameLine();
  changed |= ImGui::RadioButton("lamp colour", &meaning, int(PaintMeaning::LampColour));
  tip("White paint asks for a white lamp: a warm floor stays warm (the target takes the surface's own colour)");
  ImGui::SameLine();
  changed |= ImGui::RadioButton("reflected light", &meaning, int(PaintMeaning::Reflected));
  tip("The paint is the light the surface reflects: white paint on a warm floor asks for a bluish lamp");
  brush.meaning = PaintMeaning(meaning);
  changed |= ImGui::SliderFloat("hardness", &brush.hardness, 0.f, 1.f, "%.3f", ImGuiSliderFlags_AlwaysClamp);
  tip("0: soft edge from the centre, 1: a hard disc");
  brush = clamped_brush(brush, diagonal);
  if (changed) {
    // Applied live; recorded as one brush action when the slider is let go.
    m_player->set_brush(brush);
  }
  if (!ImGui::IsAnyItemActive() && !(brush == m_tools.recorded_brush)) {
    // Through perform(), as every other action: an invalid value is a status line.
    if (!perform(brush_action(brush))) m_player->set_brush(m_tools.recorded_brush);
    m_tools.recorded_brush = m_player->brush();
  }
  if (m_player->tool() == Tool::Shadow) {
    ImGui::Text("%zu shadow request(s)", m_tools.shadow_pairs.size());
    if (ImGui::Button("Lights from shadows (Enter)")) lights_from_shadows();
    tip("Estimate one point light per consistent set of occluder-shadow pairs (paper Fig. 5)");
    ImGui::SameLine();
    if (ImGui::Button("Clear requests")) {
      m_tools.shadow_pairs.clear();
      m_tools.occluder_point.reset();
    }
  }
  if (m_player->tool() == Tool::Spot) {
    ImGui::SliderFloat("soft edge", &m_tools.spot_falloff, 0.f, 20.f, "%.1f deg");
    tip("Width of the spotlight's soft edge, inside its cutoff");
  }
  if (m_player->tool() == Tool::Adjust) {
    ImGui::ColorEdit3("multiplier", &m_tools.adjust_multiplier.r, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
    tip("Per channel: 1.2 = 20% brighter, below 1 darker; only lights that light the region change");
  }
}

void PainterApp::panel_view() {
  if (!ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) return;
  int mode = int(m_display.view);
  bool changed = ImGui::RadioButton("result (1)", &mode, int(ui::ViewMode::Result));
  tip("The scene lit by the current lights (the renderer's per-vertex illumination)");
  ImGui::SameLine();
  changed |= ImGui::RadioButton("target (2)", &mode, int(ui::ViewMode::Target));
  tip("What you painted; hatched surfaces are \"don't care\"");
  ImGui::SameLine();
  changed |= ImGui::RadioButton("|diff| (3)", &mode, int(ui::ViewMode::Difference));
  tip("|target - result| as a heat map (black, blue, red, yellow = full white)");
  if (changed) {
    const ui::ViewMode chosen = ui::ViewMode(mode);
    perform(ViewAction{chosen == ui::ViewMode::Target ? ViewShown::Target : chosen == ui::ViewMode::Difference ? ViewShown::Difference : ViewShown::Result});
  }
  if (ImGui::SliderFloat("exposure", &m_display.exposure_stops, -6.f, 6.f, "%+.1f stops")) m_display.colours_dirty = true;
  tip("Display brightness only; does not change lights or target");
  ImGui::SameLine();
  if (ImGui::SmallButton("auto")) {
    m_display.exposure_from_result = false;
    m_display.exposure_stops = 0.f;
    m_display.colours_dirty = true;
  }
  tip("Pick the exposure again from the current result");
  ImGui::Checkbox("lights (L)", &m_display.show_lights);
  tip("Light markers; spotlights show their cone");
  if (m_display.illumination_pending) {
    ImGui::SameLine();
    ImGui::TextDisabled("rendering...");
  }
}

void PainterApp::panel_solve() {
  if (!ImGui::CollapsingHeader("Solve", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const bool busy = m_job->busy(), criteria = m_job->has_criteria();
  if (criteria) {  // a lux target: Solve places the luminaire for it, nothing painted is read
    const std::string luminaire = m_options.job.settings.luminaire ? m_options.job.settings.luminaire->profile_path : "";
    ImGui::TextWrapped("%s", ascii("Lux criteria " + std::filesystem::path(m_job->criteria_source()).filename().string() + ": Solve places " +
                                   std::filesystem::path(luminaire).filename().string() + " for them")
                                 .c_str());
  }
  ImGui::BeginDisabled(busy);
  if (ImGui::Button("Solve (F5)")) start_job(SolveAction{});
  tip(criteria ? "Place the luminaires for the lux criteria, as hilight solve does (runs in the background)"
               : "Find how many lights, where and how bright, for the painted target (runs in the background)");
  ImGui::EndDisabled();
  ImGui::BeginDisabled(busy || criteria);
  ImGui::SameLine();
  if (ImGui::Button("Fine-tune (F6)")) start_job(FineTuneAction{});
  tip("Re-optimize the current lights for the edited target; no light is added or removed");
  ImGui::SameLine();
  if (ImGui::Button("Add lights (F7)")) start_job(AddLightsAction{});
  tip("Solve for what the current lights leave unlit and append the new lights; old lights stay");
  ImGui::Checkbox("fine-tune after each stroke", &m_options.auto_fine_tune);
  tip("When there are lights, every brush stroke starts a fine-tune (paper section 4.2)");
  ImGui::EndDisabled();
  if (busy) {
    // The Solver reports stages, not fractions: a sweeping bar labelled with the stage.
    ImGui::ProgressBar(std::fmod(0.5f * float(ImGui::GetTime()), 1.f), ImVec2(-1, 0), m_job->progress().c_str());
    if (ImGui::Button("Cancel (Esc)")) m_job->cancel();
    tip("Stops the solve at its next stage; the lights stay as they were");
  }
  const size_t cuts = busy ? 0 : m_job->cut_count();
  if (cuts > 0) {
    // The slider shows the total light count: after an add, the kept lights
    // plus the cut's k (the `cut` action's k counts the cut only).
    const int base = int(m_job->cut_base_count());
    const int lights = int(m_document->state().lights.size());
    if (m_solve_panel.cut_k <= base || m_solve_panel.cut_k > base + int(cuts)) m_solve_panel.cut_k = std::clamp(lights, base + 1, base + int(cuts));
    ImGui::SliderInt("light count", &m_solve_panel.cut_k, base + 1, base + int(cuts), "%d", ImGuiSliderFlags_AlwaysClamp);
    tip(base > 0 ? "Lights kept by the add, plus a cut of the light hierarchy (no new solve)"
                 : "Move along the light hierarchy's cuts without a new solve");
    if (ImGui::IsItemDeactivatedAfterEdit() && m_solve_panel.cut_k != lights) perform(CutAction{size_t(m_solve_panel.cut_k - base)});
  }
  ImGui::BeginDisabled(!m_document->can_undo());
  if (ImGui::Button("Undo")) perform(UndoAction{});
  tip(("Ctrl+Z: " + m_document->undo_label()).c_str());
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!m_document->can_redo());
  if (ImGui::Button("Redo")) perform(RedoAction{});
  tip(("Ctrl+Y: " + m_document->redo_label()).c_str());
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::Text("%zu painted vertices", m_document->painted_count());
  panel_fit();
}

void PainterApp::panel_fit() {
  if (m_solve_panel.fit_line.empty()) return;
  ImGui::TextUnformatted(ascii("Last answer: " + m_solve_panel.fit_line).c_str());
  // The reasons hilight solve would give (fit_notes.hpp), wrapped to the panel's width.
  ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 340.f);
  for (const FitNote& note : m_solve_panel.fit_notes) {
    if (note.warning) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.7f, 0.3f, 1.f));
    ImGui::TextWrapped("%s", ascii(note.text).c_str());
    if (note.warning) ImGui::PopStyleColor();
  }
  if (!m_display.unreachable.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.35f, 0.9f, 1.f));
    ImGui::TextWrapped("Magenta stripes: the %zu painted vertices no light may reach.", m_display.unreachable.size());
    ImGui::PopStyleColor();
  }
  ImGui::PopTextWrapPos();
}

void PainterApp::panel_placement() {
  if (!ImGui::CollapsingHeader("Placement")) return;
  const PlacementRules& rules = m_job->options().settings.placement;
  const std::string now = rules.describe();
  // Shown in the file's coordinates, as the rules are given (the job's are hilight's own).
  const std::string shown = rules_to_world(rules, m_scene->frame).describe();
  // Each button is a recorded place action, taken as hilight solve takes the same --place text;
  // one refused (a bad rule, a region that is not a room) says why here.
  auto apply = [this](const std::string& text) { m_solve_panel.place_error = perform(PlaceAction{text}) ? "" : m_status_panel.line; };
  ImGui::SetNextItemWidth(300);
  ImGui::InputTextWithHint("##place", "ceiling:0.2 height:1:2.5 count:1:4", m_solve_panel.place_text, sizeof(m_solve_panel.place_text));
  tip("Where the next solves may put lights, as hilight solve --place: ceiling[:OFFSET], height:MIN:MAX, "
      "box:X0,Y0,Z0,X1,Y1,Z1, exclude:..., count:MIN:MAX, region:K or region:NAME (a room's or storey's name, "
      "as hilight info lists them), anywhere (space-separated; in a building, lights hang from the ceiling "
      "unless a rule says where, as in hilight solve). Boxes and heights are in the scene file's coordinates.");
  ImGui::BeginDisabled(m_job->busy());
  ImGui::SameLine();
  if (ImGui::Button("Apply")) apply(m_solve_panel.place_text);
  ImGui::SameLine();
  if (ImGui::Button("On the ceiling")) {
    // 0.2 m, in the file's unit as the rules are read.
    std::snprintf(m_solve_panel.place_text, sizeof(m_solve_panel.place_text), "ceiling:%g", 0.2 / m_scene->frame.scale);
    apply(m_solve_panel.place_text);
  }
  tip("Ceiling lights only: mounted 0.2 m below the ceiling above each light");
  ImGui::SameLine();
  if (ImGui::Button("Anywhere")) {
    std::snprintf(m_solve_panel.place_text, sizeof(m_solve_panel.place_text), "anywhere");
    apply(m_solve_panel.place_text);
  }
  tip("Anywhere free, a building's ceiling default lifted (--place anywhere)");
  ImGui::EndDisabled();
  ImGui::TextDisabled("lights may stand: %s", shown.empty() ? "anywhere free" : shown.c_str());
  // Why they hang from the ceiling when nobody said so (issue 34 §7), while the rules are still the default's.
  if (!m_solve_panel.building_note.empty() && now == m_solve_panel.noted_rules)
    ImGui::TextWrapped("A building: %s. The Anywhere button lifts it too.", m_solve_panel.building_note.c_str());
  if (!m_solve_panel.place_error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.45f, 0.35f, 1.f));
    ImGui::TextWrapped("%s", m_solve_panel.place_error.c_str());
    ImGui::PopStyleColor();
  }
}

void PainterApp::panel_lights() {
  const Lighting& lights = m_document->state().lights;
  char title[64];
  std::snprintf(title, sizeof title, "Lights (%zu)###lights", lights.size());
  if (!ImGui::CollapsingHeader(title)) return;
  // Intensities in the unit the files use (--units): W/sr, or candela.
  const Units units = m_document->units();
  const Lighting shown = lights_to_units(lights, units);
  const char* unit = units == Units::Photometric ? "cd" : "W/sr";
  for (size_t i = 0; i < lights.size(); ++i) {
    const Light& l = lights[i];
    const Rgb& I = shown[i].intensity;
    // Where the lights file puts it: the scene file's coordinates, as the place rules take them.
    const glm::dvec3 at = to_world(l.position, m_scene->frame);
    if (l.type == LightType::Luminaire && l.profile)
      ImGui::Text("%zu %s (%.2f, %.2f, %.2f)  dimmed to %.0f%%", i, std::filesystem::path(l.profile_path).filename().string().c_str(),
                  at.x, at.y, at.z, 100.0 * luminaire_dimming(l));
    else
      ImGui::Text("%zu %s (%.2f, %.2f, %.2f)  I (%.3g, %.3g, %.3g) %s", i, to_string(l.type), at.x, at.y, at.z, I.r, I.g, I.b, unit);
    if (l.type == LightType::Spot && ImGui::IsItemHovered())
      ImGui::SetTooltip("direction (%.2f, %.2f, %.2f), cutoff %.1f deg, soft edge %.1f deg", l.direction.x, l.direction.y,
                        l.direction.z, l.cutoff_deg, l.falloff_deg);
  }
}

void PainterApp::panel_help() {
  if (!m_status_panel.show_help) return;
  ImGui::SetNextWindowPos(ImVec2(370, 8), ImGuiCond_FirstUseEver);
  ImGui::Begin("Help", &m_status_panel.show_help, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::TextUnformatted("Paint the light you want; hilight finds the lights.");
  ImGui::Separator();
  if (ImGui::BeginTable("shortcuts", 2, ImGuiTableFlags_RowBg)) {
    for (const auto& row : kShortcuts) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(row[0]);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(row[1]);
    }
    ImGui::EndTable();
  }
  ImGui::End();
}

void PainterApp::panel_status() {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x, viewport->WorkPos.y + viewport->WorkSize.y), ImGuiCond_Always, ImVec2(0.f, 1.f));
  ImGui::SetNextWindowSize(ImVec2(viewport->WorkSize.x, 0));
  ImGui::Begin("status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoBringToFrontOnFocus);
  ImGui::Text("%s | %zu light%s | %s", to_string(m_player->tool()), m_document->state().lights.size(), m_document->state().lights.size() == 1 ? "" : "s",
              m_job->busy() ? ("working: " + m_job->progress()).c_str() : m_status_panel.line.c_str());
  if (ImGui::IsItemHovered() && !m_status_panel.log.empty()) {
    ImGui::BeginTooltip();
    for (size_t i = m_status_panel.log.size() > 12 ? m_status_panel.log.size() - 12 : 0; i < m_status_panel.log.size(); ++i) ImGui::TextUnformatted(m_status_panel.log[i].c_str());
    ImGui::EndTooltip();
  }
  ImGui::End();
}

void PainterApp::popup_shadow_pairs() {
  const char* name = "Which shadow?";
  if (!m_tools.pair_choices.empty() && !ImGui::IsPopupOpen(name)) ImGui::OpenPopup(name);
  if (!ImGui::BeginPopupModal(name, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::TextUnformatted("Several occluder-light pairs shadow this point. Erase which?");
  for (size_t i = 0; i < m_tools.pair_choices.size(); ++i) {
    const ShadowPair& pair = m_tools.pair_choices[i];
    char label[160];
    std::snprintf(label, sizeof label, "%s blocking light %zu##%zu", m_player->objects().name(pair.occluder).c_str(), pair.light, i);
    if (ImGui::Button(label)) {
      const Vec3 p = *m_tools.erase_click;
      perform(EraseShadowAction{p, std::nullopt, size_t(i)});
      m_tools.pair_choices.clear();
      ImGui::CloseCurrentPopup();
    }
  }
  if (ImGui::Button("Cancel (Esc)") || ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) {
    m_tools.pair_choices.clear();
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

} // namespace hilight::painter
