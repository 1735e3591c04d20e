#pragma once
/// The painter's window application: the document and solve job of the core,
/// a view of the scene with overlays, the tools driven by mouse and keys, the
/// ImGui panels, and headless replay of session scripts. Every action the
/// designer takes goes through the core's SessionPlayer and is recorded, so
/// a session can be replayed exactly.
#include "core/session_player.hpp"
#include "hilight/plan_view.hpp"
#include "building_state.hpp"
#include "display_state.hpp"
#include "files_panel_state.hpp"
#include "paint_options.hpp"
#include "solve_panel_state.hpp"
#include "tool_state.hpp"
#include "ui/frame_timer.hpp"
#include "ui/illumination_worker.hpp"
#include "ui/line_batch.hpp"
#include "ui/orbit_camera.hpp"
#include "ui/plan_camera.hpp"
#include "ui/scene_framebuffer.hpp"
#include "ui/scene_mesh.hpp"
#include "ui/vertex_colours.hpp"
#include "ui/window.hpp"

#include <chrono>
#include <thread>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hilight::painter {

/// Frame interval while only background work runs (a progress bar needs few frames).
constexpr double kBackgroundFrameSeconds = 0.1;

class PainterApp {
public:
  /// Loads the scene and the starting files, opens the window. InputError for
  /// bad input or no display / OpenGL.
  PainterApp(const PaintOptions& options, const Registry& registry, std::shared_ptr<const Scene> scene,
             std::optional<Session> script);
  ~PainterApp();
  PainterApp(const PainterApp&) = delete;
  PainterApp& operator=(const PainterApp&) = delete;

  /// Replays the script (if any), writes the screenshot, runs the bench if
  /// asked, then (without --exit) stays interactive until the window closes
  /// or another scene is opened (next_scene()).
  int run();

  /// What run() ended for when an `open_scene` ended it: the scene, the
  /// script's actions still to replay there, the recording so far and where
  /// it goes. nullopt when the window closed or the script ended.
  struct NextScene {
    std::filesystem::path scene;
    std::shared_ptr<const Scene> loaded;  ///< read already: one that cannot be read never closes the window
    std::optional<Session> rest_of_script;
    Session recorded;
    std::filesystem::path record_path;
  };
  std::optional<NextScene> next_scene() const;

private:
  using Clock = std::chrono::steady_clock;

  // --- frames (painter_app.cpp) ---
  /// One frame: events, results from the workers, input, scene, panels.
  /// `capture`: also save the whole window, panels included, as PNG.
  void frame(bool interactive, const std::filesystem::path& capture = {});
  /// Takes finished work: solve results (into the document) and illumination.
  void poll_workers();
  /// Recomputes vertex colours if the view mode, document or illumination changed.
  void refresh_colours();
  /// The view changed (camera released, plan, walk, room focus): the next
  /// colours pick their exposure again from what this view shows (issue 36).
  void view_changed();
  /// The exposure for what the view shows (ui/view_exposure.hpp); 0: too little to judge.
  float exposure_of_view() const;
  /// Draws the scene and overlays into the back buffer (no panels).
  void draw_scene();
  void build_overlays();
  /// Asks the illumination worker for the lights if they changed.
  void request_illumination();
  /// Blocks until the result view shows the current lights (replay, screenshots).
  void settle();
  float aspect() const;
  /// --timings: frame and latency figures so far.
  void write_timings() const;

  // --- actions (painter_session_hooks.cpp) ---
  PlayerHooks make_hooks();
  void apply_camera_action(const CameraAction& action);
  /// Applies through the player and records it; errors go to the status line
  /// (interactive) — returns false then.
  bool perform(const Action& action);
  bool perform(const TypedAction& action) { return perform(untyped(action)); }
  void record(const Action& action);
  void record(const TypedAction& action) { record(untyped(action)); }
  void unrecord_failed_job();
  std::filesystem::path default_record_path() const;
  /// The 3D view, or with `panels` the whole window (as --window-screenshot).
  void screenshot(const std::filesystem::path& path, bool panels = false);
  void status(const std::string& line);
  /// Why a region is no room to focus ("" when it is one, or the scene is no building).
  std::string not_a_room(const Region& region);
  /// A job's answer went into the document: the Solve panel's line and notes,
  /// the unreachable painted vertices marked (hooks.fit).
  void show_fit(const JobResult& result);

  // --- input (painter_input.cpp) ---
  void handle_input();
  void handle_camera_input();
  void handle_keys();
  /// Records the camera as it is now (after a drag, key moves, framing).
  void record_camera();
  void handle_tool_input();
  std::optional<SurfacePick> pick_at_mouse() const;
  void begin_region_drag();
  void finish_region_drag();
  void finish_stroke();
  /// The shadow tool's requests become a `shadow` action.
  void lights_from_shadows();
  /// Performs a solve, fine-tune or add-lights action unless a job runs.
  void start_job(const TypedAction& job);

  // --- panels (painter_panels.cpp) ---
  void draw_panels();
  void panel_tools();
  void panel_view();
  void panel_solve();
  /// The last answer's light count and D̄, why a poor fit is poor, and what the view marks.
  void panel_fit();
  /// Where lights may stand: the --place rules as one line, applied by a
  /// recorded "place" action.
  void panel_placement();
  void panel_lights();
  void panel_files();
  /// The file browser (painter_files.cpp): opened for a purpose, it lists a
  /// folder; its choice becomes that purpose's recorded action.
  void open_browser(FilePurpose purpose, const std::filesystem::path& current);
  void panel_file_browser();
  /// Performs the purpose's action on `path`; false when it failed (the status line says why).
  bool choose_file(FilePurpose purpose, const std::filesystem::path& path);
  void panel_help();
  void panel_status();
  void popup_shadow_pairs();

  // --- inside buildings (painter_building.cpp, painter_walk.cpp) ---
  void panel_building();
  void handle_building_keys();
  /// The room list: click focuses a room (Ctrl+click adds it), "none" clears.
  void panel_rooms();
  /// Plan view: each light's number, intensity and the lux on the surface below it, beside its marker.
  void draw_plan_readouts();
  /// The view's matrices, the ray through a window pixel and the pose, from
  /// the plan camera while the plan shows, else the orbit (or walk) camera.
  glm::mat4 view_projection() const;
  std::optional<SurfacePick> pick_window_pixel(float x, float y) const;
  CameraPose camera_pose() const;
  void set_plan(bool on);
  /// The plan key and checkbox: in a building, turns the section on at the camera's storey first.
  void toggle_plan(bool on);
  /// Frames a room (a `focus`): the orbit looks down at its floor from above and in front.
  void frame_room(const Bounds& box);
  /// A `walk` action: enter or leave walk mode, move (stopped by walls), look around.
  void apply_walk(const WalkAction& action);
  /// WASD and mouse look while walking; recorded as one camera action when let go.
  void handle_walk_input();
  /// The section height the slider shows (the middle of the scene until chosen).
  float section_height();
  /// Performs a `section` action (nullopt: off), remembering the height.
  void set_section(std::optional<float> height);

  // --- bench (painter_bench.cpp) ---
  /// Scripted orbit, stroke and fine-tune with timings (--bench).
  void run_bench();

  PaintOptions m_options;
  std::shared_ptr<const Scene> m_scene;
  std::shared_ptr<const RayScene> m_rays;
  std::optional<Session> m_script;
  std::unique_ptr<Document> m_document;
  std::unique_ptr<SolveJob> m_job;
  std::unique_ptr<SessionPlayer> m_player;
  SessionRecorder m_recorder;
  std::filesystem::path m_record_path;
  std::optional<size_t> m_job_action;  ///< recorded index of the running job's action
  std::vector<Rgb> m_preview;  ///< albedo under a fixed key light: the view before lights, and the "don't care" backdrop
  std::vector<Rgb> m_albedo;   ///< per vertex (the plan's lux readouts)
  std::vector<PlanSection> m_storeys;  ///< the plan's storeys, found on the first lux readout

  std::unique_ptr<ui::Window> m_window;
  std::unique_ptr<ui::SceneMesh> m_mesh;
  std::unique_ptr<ui::LineBatch> m_lines;
  std::unique_ptr<ui::SceneFramebuffer> m_view_buffer;  ///< the 3D view, redrawn only when it changes
  glm::mat4 m_drawn_view_projection{0.f};
  uint64_t m_colour_uploads = 0, m_drawn_colour_uploads = ~uint64_t(0);
  uint64_t m_shown_visibility = 0;  ///< the player's visibility_revision() the mesh draws
  std::unique_ptr<ui::IlluminationWorker> m_illumination_worker;
  ui::OrbitCamera m_camera;
  ui::FrameTimer m_timer;

  // Each panel's state, in its own header (one job each).
  DisplayState m_display;        ///< View panel: mode, exposure, the illumination shown
  ToolState m_tools;             ///< Tools panel and mouse: drags, strokes, shadow requests
  SolvePanelState m_solve_panel; ///< Solve and Placement panels, stroke → fine-tune latency
  FilesPanelState m_files;       ///< Files panel
  StatusState m_status_panel;    ///< status line, log, help
  BuildingState m_building;      ///< Building panel: section height, walk mode
  std::optional<ui::PlanCamera> m_plan;  ///< the plan view, while it shows
  bool m_headless = false;  ///< replaying: a failing action is an error, not a status line
  std::optional<std::filesystem::path> m_open_scene;  ///< set by an open_scene action: run() ends
  std::shared_ptr<const Scene> m_next_scene;           ///< that scene, loaded
  std::optional<Session> m_script_rest;               ///< the script's actions after it
};

} // namespace hilight::painter
