#pragma once
/// What `hilight paint` was asked to do (parsed by paint_command.cpp).
#include "core/session.hpp"
#include "core/solve_job.hpp"
#include "hilight/illuminance_criteria.hpp"
#include "hilight/solve/criteria_in_scene.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/named_room.hpp"
#include "hilight/units.hpp"

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace hilight::painter {

struct PaintOptions {
  std::filesystem::path scene;
  /// --unit, --max-edge, --max-vertices, as hilight solve takes them (the
  /// file's length unit; the tessellation in it, 0: diagonal/40).
  SceneLoadOptions scene_options;
  std::filesystem::path target;      ///< target PLY to start from
  /// A lux target (`--target C.json`, hilight target workplane's): Solve
  /// places the --luminaire for it as `hilight solve` does, with `design`
  /// (the criteria options); nothing painted is read, and fine-tune, add
  /// lights and the fine-tune after a stroke do not apply.
  std::optional<IlluminanceCriteria> criteria;  ///< its `source`: the file
  CriteriaDesign design;
  std::filesystem::path lights;      ///< lights JSON to start from
  std::filesystem::path script;      ///< session to replay
  std::filesystem::path screenshot;  ///< final frame, written after the script
  std::filesystem::path window_screenshot;  ///< the same with the panels (what the designer saw)
  std::filesystem::path record;      ///< where this session is recorded ("" = the default place)
  bool no_record = false;            ///< record nothing (an explicit --record still wins)
  std::filesystem::path timings;     ///< frame/latency figures as JSON ("-": stdout)
  bool bench = false;                ///< after the script: scripted orbit + stroke + fine-tune, timed
  bool exit_after_script = false;
  int width = 1280, height = 800;
  std::string view = "result";       ///< the view to start in: result, target, difference
  bool auto_fine_tune = true;        ///< fine-tune after each stroke when there are lights
  SolveJobOptions job;               ///< renderer, optimizer, sampler and solve settings (--luminaire: its settings.luminaire)
  Units units = Units::Radiometric;  ///< --units: the lights and target files' numbers
  TargetQuantity quantity = TargetQuantity::Radiance;  ///< --target-quantity: what a target file's values are
  /// The building default's note ("lights on the ceiling (an IFC building
  /// with storeys; --place anywhere lifts it)", solve_options.hpp); "" when
  /// it did not apply. The Placement panel says it while the rules are these.
  std::string building_note;
  /// The scene is an IFC with storeys (a building: cli::ifc_has_storeys), for
  /// the place action's rules as hilight solve takes them.
  bool ifc_storeys = false;
  /// The scene's named rooms, when the command line's rules named one (read once).
  std::optional<std::vector<NamedRoom>> named_rooms;
  /// After an `open_scene`: the session recorded so far (the new scene's
  /// actions follow it, so the recording replays from the first scene), and
  /// why the scene asked for could not be opened ("" when it was).
  std::optional<Session> recorded_before;
  std::string open_error;
  /// When `hilight paint` began loading (--timings: open_to_first_frame).
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
};

} // namespace hilight::painter
