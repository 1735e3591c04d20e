#pragma once
// The panels' tooltips: the last item's help text while the mouse is over it.
#include <imgui.h>

namespace hilight::painter::ui {

inline void tip(const char* text) {
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

} // namespace hilight::painter::ui
