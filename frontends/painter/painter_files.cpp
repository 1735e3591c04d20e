// The Files panel: the paths of the target, lights and screenshot, and a
// file browser (a panel of its own, built with ImGui as the rest) to open a
// scene, open and save targets and lights, and save screenshots. What it
// chooses becomes the same recorded action a typed path does.
#include "painter_app.hpp"
#include "ui/tooltip.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace hilight::painter {

using ui::tip;

namespace {

/// Files-panel paths are recorded absolute: a replay from another folder
/// reads and writes the same files.
std::string absolute_path(const std::string& path) {
  if (path.empty()) return path;
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
  return ec ? path : absolute.lexically_normal().string();
}

bool saving(FilePurpose purpose) {
  return purpose == FilePurpose::SaveTarget || purpose == FilePurpose::SaveLights || purpose == FilePurpose::Screenshot;
}

const char* title_of(FilePurpose purpose) {
  switch (purpose) {
  case FilePurpose::OpenScene: return "Open a scene";
  case FilePurpose::OpenTarget: return "Open a target";
  case FilePurpose::SaveTarget: return "Save the target";
  case FilePurpose::OpenLights: return "Open lights";
  case FilePurpose::SaveLights: return "Save the lights";
  case FilePurpose::Screenshot: return "Save a screenshot";
  }
  return "";
}

FileKinds kinds_of(FilePurpose purpose) {
  switch (purpose) {
  case FilePurpose::OpenScene: return scene_kinds();
  case FilePurpose::OpenTarget:
  case FilePurpose::SaveTarget: return target_kinds();
  case FilePurpose::OpenLights:
  case FilePurpose::SaveLights: return lights_kinds();
  case FilePurpose::Screenshot: return image_kinds();
  }
  return {};
}

} // namespace

void PainterApp::panel_files() {
  if (!ImGui::CollapsingHeader("Files")) return;
  if (ImGui::Button("Open scene...")) open_browser(FilePurpose::OpenScene, m_options.scene);
  tip("Paint another scene: the target, lights and undo history of this one are left behind (save them first)");
  ImGui::TextDisabled("%s", m_options.scene.filename().string().c_str());
  ImGui::InputText("target", &m_files.target_path);
  tip("Target PLY (or glTF with vertex colours), the format `hilight solve --target` reads");
  if (ImGui::Button("Open target")) perform(LoadTargetAction{absolute_path(m_files.target_path)});
  ImGui::SameLine();
  if (ImGui::Button("Save target")) perform(SaveTargetAction{absolute_path(m_files.target_path)});
  ImGui::SameLine();
  if (ImGui::Button("...##target")) open_browser(FilePurpose::OpenTarget, m_files.target_path);
  tip("Choose a target file to open");
  ImGui::SameLine();
  if (ImGui::Button("Save as...##target")) open_browser(FilePurpose::SaveTarget, m_files.target_path);
  ImGui::InputText("lights", &m_files.lights_path);
  tip("Lights JSON (or glTF), as `hilight render --lights` and `hilight solve -o` use");
  if (ImGui::Button("Load lights")) perform(LoadLightsAction{absolute_path(m_files.lights_path)});
  ImGui::SameLine();
  if (ImGui::Button("Save lights")) perform(SaveLightsAction{absolute_path(m_files.lights_path)});
  ImGui::SameLine();
  if (ImGui::Button("...##lights")) open_browser(FilePurpose::OpenLights, m_files.lights_path);
  tip("Choose a lights file to load");
  ImGui::SameLine();
  if (ImGui::Button("Save as...##lights")) open_browser(FilePurpose::SaveLights, m_files.lights_path);
  ImGui::InputText("image", &m_files.screenshot_path);
  if (ImGui::Button("Screenshot")) perform(ScreenshotAction{absolute_path(m_files.screenshot_path)});
  tip("The scene view as PNG (without these panels)");
  ImGui::SameLine();
  if (ImGui::Button("Save as...##image")) open_browser(FilePurpose::Screenshot, m_files.screenshot_path);
  if (!m_record_path.empty()) ImGui::TextWrapped("Recording to %s", m_record_path.c_str());
}

void PainterApp::open_browser(FilePurpose purpose, const std::filesystem::path& current) {
  FileBrowserState& b = m_files.browser;
  b.purpose = purpose;
  const std::filesystem::path absolute = std::filesystem::absolute(current.empty() ? "." : current).lexically_normal();
  std::error_code ec;
  // The folder of the path in the field, when it exists; else the one last shown.
  if (!current.empty() && std::filesystem::is_directory(absolute.parent_path(), ec)) b.folder = absolute.parent_path();
  else if (b.folder.empty()) b.folder = std::filesystem::current_path(ec);
  b.name = saving(purpose) && !current.empty() ? absolute.filename().string() : "";
  b.stale = true;
}

void PainterApp::panel_file_browser() {
  FileBrowserState& b = m_files.browser;
  if (!b.purpose) return;
  const FilePurpose purpose = *b.purpose;
  const FileKinds kinds = kinds_of(purpose);
  if (b.stale) {
    b.listing = list_folder(b.folder, kinds);
    b.folder = b.listing.folder;
    b.folder_text = b.folder.string();
    b.stale = false;
  }
  ImGui::SetNextWindowSize(ImVec2(520, 420), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowPos(ImVec2(380, 40), ImGuiCond_FirstUseEver);
  bool open = true;
  if (!ImGui::Begin((std::string(title_of(purpose)) + "###file browser").c_str(), &open)) {
    ImGui::End();
    if (!open) b.purpose.reset();
    return;
  }
  if (ImGui::Button("Up")) {
    b.folder = b.folder.parent_path();
    b.stale = true;
  }
  tip("The folder above");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1);
  if (ImGui::InputText("##folder", &b.folder_text, ImGuiInputTextFlags_EnterReturnsTrue)) {
    b.folder = b.folder_text;
    b.stale = true;
  }
  tip("Type a folder and press Enter");
  if (!b.listing.error.empty()) ImGui::TextColored(ImVec4(1.f, 0.45f, 0.35f, 1.f), "%s", b.listing.error.c_str());
  ImGui::TextDisabled("%s", kinds.name.c_str());
  // Folders open with a click; a file is chosen with a click, and opened with a double click.
  bool chosen = false;
  const float footer = ImGui::GetFrameHeightWithSpacing() * 2.f;
  if (ImGui::BeginChild("entries", ImVec2(0, -footer), true)) {
    for (const FolderEntry& entry : b.listing.entries) {
      const std::string label = entry.folder ? entry.name + "/" : entry.name;
      if (ImGui::Selectable(label.c_str(), !entry.folder && entry.name == b.name, ImGuiSelectableFlags_AllowDoubleClick)) {
        if (entry.folder) {
          b.folder /= entry.name;
          b.stale = true;
        } else {
          b.name = entry.name;
          chosen = ImGui::IsMouseDoubleClicked(0);
        }
      }
    }
  }
  ImGui::EndChild();
  ImGui::SetNextItemWidth(300);
  chosen |= ImGui::InputText("file name", &b.name, ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  chosen |= ImGui::Button(saving(purpose) ? "Save" : "Open");
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) open = false;
  ImGui::End();
  if (chosen && !b.name.empty()) {
    std::filesystem::path path = b.folder / b.name;
    // Saving without a known extension: the kind's first one ("lights" → "lights.json").
    if (saving(purpose) && !kinds.accepts(path)) path += kinds.extensions.front();
    if (choose_file(purpose, path.lexically_normal())) open = false;
  }
  if (!open) b.purpose.reset();
}

bool PainterApp::choose_file(FilePurpose purpose, const std::filesystem::path& path) {
  const std::string p = path.string();
  switch (purpose) {
  case FilePurpose::OpenScene: return perform(OpenSceneAction{p});
  case FilePurpose::OpenTarget:
    if (!perform(LoadTargetAction{p})) return false;
    m_files.target_path = p;
    return true;
  case FilePurpose::SaveTarget:
    if (!perform(SaveTargetAction{p})) return false;
    m_files.target_path = p;
    return true;
  case FilePurpose::OpenLights:
    if (!perform(LoadLightsAction{p})) return false;
    m_files.lights_path = p;
    return true;
  case FilePurpose::SaveLights:
    if (!perform(SaveLightsAction{p})) return false;
    m_files.lights_path = p;
    return true;
  case FilePurpose::Screenshot:
    if (!perform(ScreenshotAction{p})) return false;
    m_files.screenshot_path = p;
    return true;
  }
  return false;
}

} // namespace hilight::painter
