#pragma once
// The tools' state between frames (the Tools panel and the mouse): a stroke
// or region drag in progress, the shadow tool's requests, the brush and tool
// as last recorded (so only changes are recorded).
#include "core/actions.hpp"
#include "core/brush.hpp"
#include "core/shadow_erase.hpp"
#include "core/region.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace hilight::painter {

struct ToolState {
  bool dragging_camera = false;
  bool camera_keys_unrecorded = false;  ///< arrow/zoom keys moved the camera since the last record
  std::unique_ptr<Stroke> stroke;       ///< brush/eraser stroke in progress
  uint64_t stroke_start_revision = 0;   ///< the document's revision when the stroke began
  /// The revision right after a one-dab stroke that painted: a double click
  /// that follows (nothing changed in between) takes that dab back.
  std::optional<uint64_t> click_revision;
  BrushSettings recorded_brush;         ///< brush as last recorded
  Tool recorded_tool = Tool::Brush;
  std::vector<Vec3> region;             ///< points of a shadow/spot/adjust drag
  bool region_drag = false;
  std::optional<Vec3> occluder_point;   ///< shadow tool: the selected occluder (a point on it)
  std::vector<ShadowAction::Pair> shadow_pairs;  ///< shadow tool: requests collected so far
  std::optional<Vec3> erase_click;      ///< erase-shadow click awaiting a pick
  std::vector<ShadowPair> pair_choices;
  Rgb adjust_multiplier{1.2f};
  float spot_falloff = 2.f;
  std::optional<SurfacePick> hover;
};

} // namespace hilight::painter
