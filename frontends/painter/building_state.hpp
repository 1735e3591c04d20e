#pragma once
// The building views' state between frames (the Building panel and its keys):
// the section height the slider and Page Up/Down move, kept while the
// section is off so turning it on again returns to it; walk mode.
#include <optional>
#include <string>

namespace hilight::painter {

struct BuildingState {
  std::optional<float> section_height;  ///< unset until first chosen (then: the middle of the scene's height)
  bool walking = false;                 ///< walk mode: the camera is a first-person eye
  bool walk_unrecorded = false;         ///< walk keys or mouse look moved the eye since the last record
  bool rooms_open = false;              ///< the room list is expanded (its regions are found then)
  std::optional<std::string> kind;      ///< what makes the scene a building (cli::building_kind; "": none), once asked
};

} // namespace hilight::painter
