#pragma once
/// The painter's document: the scene, the painted target Ψ per scene vertex,
/// the current lights and an undo/redo history of complete snapshots.
///
/// Every edit is one undoable step: call begin_edit(), change the state it
/// returns (live: the UI shows it at once), then commit_edit(label) — or
/// cancel_edit() to restore. apply() does all three for one-shot edits.
#include "hilight/lighting.hpp"
#include "hilight/ray_scene.hpp"
#include "hilight/target.hpp"
#include "hilight/units.hpp"
#include "core/paint_meaning.hpp"

#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace hilight::painter {

/// Everything an undo step restores.
struct PaintState {
  std::vector<Rgb> psi;       ///< painted Ψ per scene vertex, linear RGB radiance
  std::vector<float> weight;  ///< per scene vertex; 0 = "don't care"
  Lighting lights;            ///< the current lights (point and spot)
  Lighting spot_hints;        ///< spotlights the designer asked for (join every full solve)

  bool operator==(const PaintState& other) const;
};

class Document {
public:
  Document(std::shared_ptr<const Scene> scene, std::shared_ptr<const RayScene> rays);

  const Scene& scene() const { return *m_scene; }
  const RayScene& rays() const { return *m_rays; }
  /// Per scene vertex (Scene::vertex_albedo, read once): what the brush's paint meaning reads.
  const std::vector<Rgb>& albedo() const { return m_albedo; }

  const PaintState& state() const { return m_state; }
  /// Increases on every change of state() (edits, undo, redo): the UI
  /// re-uploads colours or re-renders when it moves.
  uint64_t revision() const { return m_revision; }

  // --- Editing -----------------------------------------------------------
  /// Starts an undoable edit (a no-op if one is open) and returns the state to
  /// change. The edit is visible at once; bump() after live changes.
  PaintState& begin_edit();
  /// Marks a live change inside an open edit (raises revision()).
  void bump() { ++m_revision; }
  bool editing() const { return m_editing; }
  /// Closes the open edit as one undo step named `label`. An edit that
  /// changed nothing leaves no step. Clears the redo list.
  void commit_edit(const std::string& label);
  /// Closes the open edit and restores the state from before it.
  void cancel_edit();
  /// One-shot edit: begin_edit, edit(state), commit_edit(label). An edit left
  /// open (a stroke) is committed first as its own step. If `edit` throws,
  /// the state is restored and the exception continues.
  void apply(const std::string& label, const std::function<void(PaintState&)>& edit);
  /// Replaces the lights (a solve's result, a cut, a loaded file) as one step.
  void set_lights(const Lighting& lights, const std::string& label);

  // --- History -----------------------------------------------------------
  bool can_undo() const { return !m_undo.empty(); }
  bool can_redo() const { return !m_redo.empty(); }
  /// Label of the step undo() / redo() would revert / re-apply ("" if none).
  std::string undo_label() const;
  std::string redo_label() const;
  /// Restores the state before the last step (commits an open edit first).
  void undo();
  void redo();

  // --- Target and files --------------------------------------------------
  /// Number of vertices with weight > 0.
  size_t painted_count() const;
  /// Ψ of the painted vertices bound to the surface (bind_target with the
  /// vertex positions and normals): what the solver takes. InputError when
  /// nothing is painted.
  Target target() const;
  /// Only the painted vertices `keep` accepts (a room focus); InputError(`if_none`) if none is.
  Target target(const std::function<bool(uint32_t)>& keep, const std::string& if_none) const;
  /// What the files' numbers mean (--units, --target-quantity): lights files
  /// read and written in `units` (W/sr or cd), targets read as `hilight
  /// solve` reads them with the same options and written so that it reads
  /// them back the same. Radiometric radiance until set.
  void set_units(Units units, TargetQuantity quantity);
  Units units() const { return m_units; }
  TargetQuantity quantity() const { return m_quantity; }
  /// The Ψ that `paint` (colour × brightness, in the files' units: W/(sr m²),
  /// cd/m², or lux with an illuminance quantity) asks of vertex `v`, read
  /// as `meaning` says (core/paint_meaning.hpp). Lux is the light the
  /// surface receives, its colour the lamp's: Ψ = ρ ⊙ E / π, either meaning.
  Rgb painted_target(const Rgb& paint, PaintMeaning meaning, size_t v) const;
  /// Ψ per vertex in the files' units (set_units).
  std::vector<Rgb> psi_in_file_units() const;
  /// Writes the painted vertices as a target PLY `hilight solve --target` reads.
  void save_target(const std::filesystem::path& path) const;
  /// Reads a target PLY (any `hilight solve` accepts): each point goes to the
  /// nearest vertex of the triangle it binds to; vertices that several points
  /// reach get their weighted mean. Replaces the painted target (one step).
  void load_target(const std::filesystem::path& path);
  void save_lights(const std::filesystem::path& path) const;
  /// Replaces the lights with a lights JSON file (one step).
  void load_lights(const std::filesystem::path& path);

private:
  struct Step {
    PaintState before;
    std::string label;
  };
  void trim_history();

  std::shared_ptr<const Scene> m_scene;
  std::shared_ptr<const RayScene> m_rays;
  std::vector<Rgb> m_albedo;
  Units m_units = Units::Radiometric;
  TargetQuantity m_quantity = TargetQuantity::Radiance;
  PaintState m_state;
  PaintState m_edit_start;
  bool m_editing = false;
  std::deque<Step> m_undo;
  std::vector<Step> m_redo;  ///< each holds the state to restore on redo
  static constexpr size_t kHistoryLimit = 200;  ///< steps kept; the oldest are dropped beyond it (snapshots are whole states)
  uint64_t m_revision = 1;
};

} // namespace hilight::painter
