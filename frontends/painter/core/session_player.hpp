#pragma once
/// Applies session actions to a Document and a SolveJob. World-space actions
/// run here; what needs the window — camera moves, screen→world picking,
/// screenshots, tool display — goes through hooks the UI provides (each may
/// be empty: a headless replay then fails clearly on screen coordinates and
/// ignores camera and screenshot actions).
///
/// The UI can drive its own buttons through apply() too, so what it records
/// is exactly what a replay does.
#include "core/actions.hpp"
#include "core/brush.hpp"
#include "core/document.hpp"
#include "core/region_adjust.hpp"
#include "core/scene_objects.hpp"
#include "core/session.hpp"
#include "core/shadow_candidates.hpp"
#include "core/shadow_erase.hpp"
#include "core/solve_job.hpp"
#include "core/spot_region.hpp"
#include "core/view_clip.hpp"
#include "hilight/light_space.hpp"
#include "hilight/regions.hpp"

#include <array>
#include <tuple>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace hilight::painter {

/// The `brush` action that sets every field of `brush`.
Action brush_action(const BrushSettings& brush);

/// How far from the scene (in scene diagonals) a script's points, eyes and
/// camera may be: farther ones are input errors (they would overflow the
/// ray tracer's float arithmetic).
constexpr float kMaxSceneReach = 1e6f;

/// Where the camera is (spot_region without an explicit eye/direction).
struct CameraPose {
  Vec3 eye{0.f, 0.f, 1.f};
  Vec3 direction{0.f, 0.f, -1.f};  ///< unit view direction
  Vec3 target{0.f, 0.f, 0.f};      ///< the point looked at (the cutaway keeps what is around it)
};

struct PlayerHooks {
  /// Applies a `camera` action (orbit / pan / zoom / eye+target+fov).
  std::function<void(const CameraAction&)> camera;
  /// The current camera (spot_region without "eye"/"direction").
  std::function<CameraPose()> camera_pose;
  /// Screen pixel (x right, y down) → surface point under it, nullopt on a miss.
  std::function<std::optional<SurfacePick>(const std::array<float, 2>&)> pick_screen;
  /// Writes a screenshot to the path: the 3D view, or with `panels` the whole window.
  std::function<void(const std::filesystem::path&, bool panels)> screenshot;
  /// Several occluder–light pairs shadow an erase_shadow click and the action
  /// has no "pick": returns the index to erase (default: the first).
  std::function<size_t(const std::vector<ShadowPair>&)> choose_shadow_pair;
  /// Shows the result, the target or their difference (a `view` action; ignored headless).
  std::function<void(ViewShown)> view;
  /// A tool or brush change (the UI updates its panels); after the player's own state changed.
  std::function<void(const Action&)> tool_changed;
  /// Shows or leaves the plan view (a `plan` action; ignored headless).
  std::function<void(bool)> plan;
  /// Walk mode: enter/leave, move, look (a `walk` action; ignored headless).
  std::function<void(const WalkAction&)> walk;
  /// Frames the focused rooms (their boxes' union) after a `focus` action.
  std::function<void(const Bounds&)> frame;
  /// One line per finished action or solve result, for a log panel / stderr.
  std::function<void(const std::string&)> log;
  /// A `place` action's parsed rules as `hilight solve` takes the same
  /// --place text (frontends/common/solve_options.hpp settle_placement): room
  /// and storey names resolved, a region:K that is not a building's room
  /// refused (InputError), a building's ceiling rule added when no rule says
  /// where; returns that default's note ("" when it does not apply).
  /// `regions`: the player's, when found. Unset: the rules as parsed, and the
  /// scene names no rooms.
  std::function<std::string(PlacementRules&, std::shared_ptr<const Regions> regions)> settle_placement;
  /// Why a region may not be focused: "not a room of <building> (<why>)",
  /// as hilight solve refuses `--place region:K` of it (the outside of a
  /// building, the void under a slab); "" when it is a room, or the scene is
  /// no building. Unset: every region may be focused.
  std::function<std::string(const Region&)> not_a_room;
  /// A job's lights went into the document: its report and, for a poor fit,
  /// the painted vertices no allowed place sees (the window says why and marks them).
  std::function<void(const JobResult&)> fit;
  /// An `open_scene` action: the window starts again on that scene (the
  /// path exists; its loading may still fail, and the window says why).
  /// Unset: no window, an input error.
  std::function<void(const std::filesystem::path&)> open_scene;
};

/// A `place` action's text as --place rules: split at spaces, except that a
/// word without ':' (not `anywhere`) continues the region:/not-region: name
/// before it, so a storey's name ('region:0. Erdgeschoss') stays whole.
std::vector<std::string> split_place_rules(const std::string& text);

struct PlayerOptions {
  /// Replays wait for each solve (true); the interactive UI starts them and
  /// calls poll() every frame (false).
  bool wait_for_solves = true;
  /// Relative paths of save/load actions are taken from here.
  std::filesystem::path base_dir = ".";
  /// Name used in error messages ("<source>: action N: ...").
  std::string source = "session";
};

class SessionPlayer {
public:
  SessionPlayer(Document& document, SolveJob& job, PlayerHooks hooks, PlayerOptions options);

  /// Validates every action, then applies them in order (waiting for solves
  /// when wait_for_solves). Errors: InputError("<source>: action N: ...").
  void play(const Session& session);
  /// Applies one action (`index` only names it in errors): validated, typed,
  /// then run by the apply function of its type (the run overloads below).
  void apply(const Action& action, size_t index = 0);
  /// Commits a finished background solve to the document (one undo step
  /// labelled with the job kind); returns it, or nullopt if none is ready.
  /// Failures come back as a JobResult with outcome Failed/Cancelled and
  /// leave the document as it was; so do results of jobs during which the
  /// document changed (outcome Superseded: a stroke, an undo, new lights —
  /// a replay, which waits for each job, could not reproduce them). While
  /// the document has an open edit (a stroke in progress) the result waits
  /// for the next poll.
  std::optional<JobResult> poll();
  /// Starts a solve, fine-tune or add-lights job and returns at once, even in
  /// a replay (the window's --bench draws frames while it runs); poll()
  /// commits it. InputError as the actions give.
  void start_in_background(JobKind kind);

  Tool tool() const { return m_tool; }
  const BrushSettings& brush() const { return m_brush; }
  void set_brush(const BrushSettings& brush) { m_brush = brush; }
  /// The section and cutaway (`section`, `cutaway` actions): view state, like the tool.
  const ViewClip& clip() const { return m_clip; }
  void set_clip(const ViewClip& clip) { m_clip = clip; }
  /// What the view shows now: the clip for the current camera (hooks.camera_pose;
  /// without one the cutaway hides nothing). Recomputed only when either changed.
  const Visibility& visibility() const;
  /// Moves whenever what visibility() returns changed (the window re-uploads then).
  uint64_t visibility_revision() const { return m_visibility_revision; }
  /// The scene's rooms (LightSpace regions, numbered as `hilight info` and
  /// `--place region:K` number them); found on first use.
  const Regions& regions() const;
  /// The focused rooms (`focus` action); empty: none. Solves then fit only
  /// the painted points in them and place lights only in them.
  const std::vector<int>& focus() const { return m_focus; }
  /// The `place` rules with the focused rooms' (the job's placement).
  PlacementRules placement() const;
  /// Where the tools may put a light: free space under placement(), as the
  /// solve sees it (the shadow and spot-region tools ask it).
  LightSpace light_space() const;
  /// The room a surface point looks into (stepped a voxel off the surface
  /// along its normal, so a wall's two faces belong to their own rooms); -1: none.
  int room_of(const Vec3& position, const Vec3& normal) const;
  /// Takes over the view and tool state of `other` (the window's replay
  /// player hands over to its interactive one).
  void continue_from(const SessionPlayer& other);
  const SceneObjects& objects() const { return m_objects; }
  /// Estimate of the last `shadow` action (for drawing candidates).
  const std::optional<ShadowEstimate>& last_shadow_estimate() const { return m_last_estimate; }
  /// Pairs found by the last `erase_shadow` action.
  const std::vector<ShadowPair>& last_shadow_pairs() const { return m_last_pairs; }

private:
  // One apply function per action type (core/actions.hpp); `where` names the
  // action in errors.
  void run(const CameraAction& a, const Action& action, const std::string& where);
  void run(const ToolAction& a, const Action& action, const std::string& where);
  void run(const ViewAction& a, const Action& action, const std::string& where);
  void run(const SectionAction& a, const Action& action, const std::string& where);
  void run(const CutawayAction& a, const Action& action, const std::string& where);
  void run(const PlanAction& a, const Action& action, const std::string& where);
  void run(const FocusAction& a, const Action& action, const std::string& where);
  void run(const WalkAction& a, const Action& action, const std::string& where);
  void run(const BrushAction& a, const Action& action, const std::string& where);
  void run(const StrokeAction& a, const Action& action, const std::string& where);
  void run(const EraseAction& a, const Action& action, const std::string& where);
  void run(const ShadowAction& a, const Action& action, const std::string& where);
  void run(const EraseShadowAction& a, const Action& action, const std::string& where);
  void run(const SpotRegionAction& a, const Action& action, const std::string& where);
  void run(const AdjustRegionAction& a, const Action& action, const std::string& where);
  void run(const SolveAction& a, const Action& action, const std::string& where);
  void run(const FineTuneAction& a, const Action& action, const std::string& where);
  void run(const AddLightsAction& a, const Action& action, const std::string& where);
  void run(const CutAction& a, const Action& action, const std::string& where);
  void run(const PlaceAction& a, const Action& action, const std::string& where);
  void run(const UndoAction& a, const Action& action, const std::string& where);
  void run(const RedoAction& a, const Action& action, const std::string& where);
  void run(const SaveTargetAction& a, const Action& action, const std::string& where);
  void run(const SaveLightsAction& a, const Action& action, const std::string& where);
  void run(const LoadTargetAction& a, const Action& action, const std::string& where);
  void run(const LoadLightsAction& a, const Action& action, const std::string& where);
  void run(const ScreenshotAction& a, const Action& action, const std::string& where);
  void run(const OpenSceneAction& a, const Action& action, const std::string& where);
  void run(const UnitsAction& a, const Action& action, const std::string& where);
  void run(const CriteriaAction& a, const Action& action, const std::string& where);
  /// Gives the job placement().
  void apply_placement();
  /// An InputError when the not_a_room hook says region `region` is no room (`at`: where the action pointed).
  void refuse_not_a_room(int region, const std::string& where, const std::string& at) const;
  /// The painted target, only its points in the focused rooms when there are some.
  Target focused_target(const std::string& where) const;
  /// Starts a job on the focused target (no waiting).
  void launch(JobKind kind, const std::string& where);
  /// Starts a solve, fine-tune or add-lights job (waiting for it in replays).
  void start_job(JobKind kind, const std::string& where);
  /// The path of a save/load action, relative ones from base_dir.
  std::filesystem::path resolve(const std::string& path) const { return m_options.base_dir / path; }

  /// The action's "world" points snapped to surfaces (InputError for one off
  /// every surface) or its "screen" points picked (InputError if none hits).
  std::vector<SurfacePick> surface_picks(const PointSet& points, const std::string& where) const;
  std::vector<Vec3> world_points(const PointSet& points, const std::string& where) const;
  /// InputError unless `p` is within kMaxSceneReach diagonals of the scene's bounds.
  void check_near_scene(const Vec3& p, const std::string& what) const;
  SurfacePick world_point(const Vec3& p, const std::string& where) const;
  SurfacePick screen_point(const Vec2& xy, const std::string& where) const;
  /// Waits for the running job and commits its result (InputError if it failed).
  void finish_solve(const std::string& where);
  /// Done results go into the document, unless it changed since the job
  /// started: then the outcome becomes Superseded and nothing changes.
  void commit(JobResult& result);
  void log(const std::string& line) const;

  Document& m_document;
  SolveJob& m_job;
  PlayerHooks m_hooks;
  PlayerOptions m_options;
  SceneObjects m_objects;
  Tool m_tool = Tool::Brush;
  BrushSettings m_brush;
  ViewClip m_clip;
  std::vector<int> m_focus;
  PlacementRules m_place_rules;  ///< as the `place` actions set them (the focus adds its rooms)
  mutable std::shared_ptr<const Regions> m_regions;
  mutable Visibility m_visibility;  ///< cache of visibility() for:
  mutable std::optional<std::tuple<ViewClip, Vec3, Vec3>> m_visibility_for;  ///< clip, eye, focus
  mutable uint64_t m_visibility_revision = 0;
  std::optional<ShadowEstimate> m_last_estimate;
  std::vector<ShadowPair> m_last_pairs;
  uint64_t m_job_revision = 0;  ///< the document's revision when the running job started
};

} // namespace hilight::painter
