#include "painter_app.hpp"

#include "hilight/default_view.hpp"

#include "hilight/error.hpp"
#include "hilight/io/atomic_file.hpp"
#include "ui/gl.hpp"
#include "ui/light_markers.hpp"
#include "ui/screenshot.hpp"
#include "ui/view_exposure.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <imgui.h>
#include <iostream>
#include <stdexcept>

namespace hilight::painter {

namespace {

/// The display renderers, quick to exact. The exact one is the solve job's
/// reference (same renderer, settings and seed), so the result view shows
/// what the solve measures; where the renderer declares a preview (Embree:
/// 16 gather rays, interpolated direct light), a quick stage comes first (a
/// stroke's fine-tune shows in a fraction of the exact render's time).
std::vector<std::unique_ptr<Renderer>> display_renderers(const SolveJob& job) {
  std::vector<std::unique_ptr<Renderer>> stages;
  if (const auto quick = job.session().preview_settings(); !quick.empty()) stages.push_back(job.session().make_renderer(quick));
  stages.push_back(job.make_renderer());
  return stages;
}

/// Shading shown before there are any lights: albedo under a fixed soft key
/// light, dim, so the designer sees the geometry but not "a result".
std::vector<Rgb> preview_radiance(const Scene& scene, const std::vector<Rgb>& albedo) {
  const Vec3 key = glm::normalize(Vec3(0.3f, 1.f, 0.5f));
  std::vector<Rgb> out(scene.positions.size());
  for (size_t i = 0; i < out.size(); ++i)
    out[i] = albedo[i] * (0.12f + 0.18f * std::max(0.f, glm::dot(scene.normals[i], key)));
  return out;
}

} // namespace

PainterApp::PainterApp(const PaintOptions& options, const Registry& registry, std::shared_ptr<const Scene> scene,
                       std::optional<Session> script)
    : m_options(options), m_scene(std::move(scene)), m_script(std::move(script)) {
  m_rays = RayScene::shared(m_scene);
  m_albedo = m_scene->vertex_albedo();
  m_preview = preview_radiance(*m_scene, m_albedo);
  m_document = std::make_unique<Document>(m_scene, m_rays);
  m_document->set_units(m_options.units, m_options.quantity);
  m_job = std::make_unique<SolveJob>(registry, m_scene, m_rays, m_options.job);
  if (m_options.criteria) m_job->set_criteria(*m_options.criteria, m_options.design);
  std::snprintf(m_solve_panel.place_text, sizeof(m_solve_panel.place_text), "%s", m_options.job.settings.placement.describe().c_str());
  m_solve_panel.named_rooms = m_options.named_rooms;
  m_solve_panel.building_note = m_options.building_note;
  m_solve_panel.noted_rules = m_options.job.settings.placement.describe();
  if (m_options.recorded_before)  // after an open_scene: the recording goes on
    for (const Action& a : m_options.recorded_before->actions) m_recorder.record(a);
  if (!m_options.no_record || !m_options.record.empty()) {
    const bool interactive = !m_options.exit_after_script;
    if (!m_options.record.empty()) m_record_path = m_options.record;
    else if (interactive) m_record_path = default_record_path();
  }
  // The starting files are the session's first actions, so a recording replays from the same state.
  auto absolute = [](const std::filesystem::path& p) { return std::filesystem::absolute(p).lexically_normal().string(); };
  // The units first: the files after them are read in them.
  if (!m_options.recorded_before && (m_options.units != Units::Radiometric || m_options.quantity != TargetQuantity::Radiance))
    record(UnitsAction{m_options.units, m_options.quantity});
  if (m_options.criteria) record(CriteriaAction{absolute(m_options.criteria->source), m_options.design});
  // (Loaded by the document directly: its errors name the file, not a script action.)
  if (!m_options.target.empty()) {
    m_document->load_target(m_options.target);
    record(LoadTargetAction{absolute(m_options.target)});
  }
  if (!m_options.lights.empty()) {
    m_document->load_lights(m_options.lights);
    record(LoadLightsAction{absolute(m_options.lights)});
  }

  // The window last: input problems surface first, even without a display.
  m_window = std::make_unique<ui::Window>(m_options.width, m_options.height,
                                          "hilight paint - " + m_options.scene.filename().string(), true);
  m_mesh = std::make_unique<ui::SceneMesh>(*m_scene);
  m_lines = std::make_unique<ui::LineBatch>();
  m_view_buffer = std::make_unique<ui::SceneFramebuffer>();
  // Inside the largest lit room of a building or closed box, else from outside (default_view.hpp).
  m_camera = ui::OrbitCamera::from_camera(default_view(*m_rays, m_document->state().lights, aspect()), m_scene->diagonal(),
                                          m_scene->bounds.center());
  // Background results wake the event loop at once (glfwPostEmptyEvent is thread-safe).
  // The display's renderers are made on the worker's thread: binding a big
  // scene takes seconds the first frame need not wait for.
  m_illumination_worker = std::make_unique<ui::IlluminationWorker>([job = m_job.get()] { return display_renderers(*job); }, *m_scene,
                                                                   [] { glfwPostEmptyEvent(); });
  m_job->set_on_finished([] { glfwPostEmptyEvent(); });  // a finished solve wakes the event loop at once
  m_display.view = m_options.view == "target" ? ui::ViewMode::Target : m_options.view == "difference" ? ui::ViewMode::Difference : ui::ViewMode::Result;
  m_headless = m_options.exit_after_script;
  m_player = std::make_unique<SessionPlayer>(*m_document, *m_job, make_hooks(),
                                             PlayerOptions{true, ".", m_options.script.empty() ? "session" : m_options.script.string()});
  m_tools.recorded_brush = m_player->brush();
  const std::string stem = m_options.scene.stem().string();
  m_files.target_path = m_options.target.empty() ? stem + "-target.ply" : m_options.target.string();
  m_files.lights_path = m_options.lights.empty() ? stem + "-lights.json" : m_options.lights.string();
  m_files.screenshot_path = stem + ".png";
}

PainterApp::~PainterApp() {
  // Stop background work and free GL objects before the context goes.
  m_view_buffer.reset();
  m_illumination_worker.reset();
  m_job.reset();
}

float PainterApp::aspect() const {
  int w = 1, h = 1;
  m_window->framebuffer_size(w, h);
  return float(std::max(w, 1)) / float(std::max(h, 1));
}

int PainterApp::run() {
  frame(false);  // the scene as it opens
  // Issue 20's figure: loading, the ray tracer, the GPU mesh and the first frame.
  m_timer.add_latency("open_to_first_frame", std::chrono::duration<double, std::milli>(Clock::now() - m_options.started).count());
  if (m_script) {
    for (size_t i = 0; i < m_script->actions.size(); ++i) {
      const Action& action = m_script->actions[i];
      m_player->apply(action, i);
      record(action);
      if (m_open_scene) {
        // The rest of the script is the next scene's (paint_command.cpp starts the window again).
        m_script_rest = Session{{m_script->actions.begin() + std::ptrdiff_t(i) + 1, m_script->actions.end()}};
        m_job->cancel();
        return 0;
      }
      if (action.type == CameraAction::kType) m_display.last_activity = "camera";
      frame(false);
      m_display.last_activity = "idle";
    }
  }
  if (!m_options.screenshot.empty()) screenshot(m_options.screenshot);
  if (!m_options.window_screenshot.empty()) screenshot(m_options.window_screenshot, true);
  if (m_options.bench) run_bench();
  if (m_options.exit_after_script) {
    write_timings();
    return 0;
  }

  // Interactive: solves run in the background and the player polls them.
  m_headless = false;
  auto interactive = std::make_unique<SessionPlayer>(*m_document, *m_job, make_hooks(), PlayerOptions{false, ".", "session"});
  interactive->continue_from(*m_player);
  m_player = std::move(interactive);
  m_shown_visibility = ~uint64_t(0);  // a new player counts from 0: upload its visibility
  if (!m_record_path.empty()) status("recording this session to " + m_record_path.string());
  if (!m_options.open_error.empty()) status(m_options.open_error);
  while (!m_window->should_close() && !m_open_scene) {
    try {
      frame(true);
    } catch (const InputError& e) {
      ImGui::EndFrame();  // close the frame the error left open (a no-op if it had ended)
      status(e.what());   // a bad value typed into a panel is a status line, never a lost session
    } catch (const std::logic_error& e) {
      ImGui::EndFrame();
      status(std::string("internal error: ") + e.what());
    }
  }
  m_job->cancel();
  write_timings();  // the interactive frames too: what a designer's hands produced
  return 0;
}

std::optional<PainterApp::NextScene> PainterApp::next_scene() const {
  if (!m_open_scene) return std::nullopt;
  return NextScene{*m_open_scene, m_next_scene, m_script_rest, m_recorder.session(), m_record_path};
}

void PainterApp::write_timings() const {
  if (m_options.timings.empty()) return;
  const std::string text = m_timer.to_json();
  if (m_options.timings == "-") std::cout << text;
  else write_atomically(m_options.timings, text);
}

void PainterApp::frame(bool interactive, const std::filesystem::path& capture) {
  if (interactive) {
    // Dragging: draw as fast as the mouse moves. Background work: wake at
    // 10 Hz to show its progress (and at once when it ends: the workers post
    // an event), leaving the cores to the work. Idle: sleep until an event.
    const bool dragging = m_tools.stroke || m_tools.dragging_camera || m_tools.region_drag;
    if (dragging) glfwPollEvents();
    else if (m_job->busy() || m_display.illumination_pending) glfwWaitEventsTimeout(kBackgroundFrameSeconds);
    else glfwWaitEventsTimeout(0.25);
  } else {
    glfwPollEvents();
  }
  // A frame's time is its work, not the wait for events; the input handlers
  // name what the frame was for.
  const auto start = Clock::now();
  if (interactive) m_display.last_activity = m_tools.stroke || m_tools.region_drag ? "stroke" : "idle";
  poll_workers();
  m_window->begin_frame();
  if (interactive) handle_input();
  request_illumination();
  refresh_colours();
  draw_scene();
  draw_panels();
  m_window->render_imgui();
  if (!capture.empty()) {
    int w = 1, h = 1;
    m_window->framebuffer_size(w, h);
    ui::save_screenshot(capture, w, h);
  }
  m_window->present();
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  if (m_display.last_activity != "idle" || !interactive) m_timer.add_frame(m_display.last_activity, ms);
}

void PainterApp::poll_workers() {
  if (std::optional<JobResult> result = m_player->poll()) {
    if (result->outcome == JobOutcome::Failed) status(std::string(to_string(result->kind)) + " failed: " + result->error);
    else if (result->outcome == JobOutcome::Cancelled) status(std::string(to_string(result->kind)) + " cancelled");
    if (result->outcome != JobOutcome::Done) unrecord_failed_job();
    m_job_action.reset();
    if (result->outcome == JobOutcome::Done && result->kind != JobKind::FineTune) m_solve_panel.cut_k = 0;  // the slider follows the new cuts
    if (result->outcome == JobOutcome::Done && result->kind == JobKind::FineTune)
      m_timer.add_latency("fine_tune_solver", 1000.0 * result->report.seconds["total"]);
    if (result->outcome == JobOutcome::Done && m_solve_panel.fine_tune_after_stroke && m_solve_panel.stroke_released) {
      m_timer.add_latency("stroke_to_fine_tune",
                          std::chrono::duration<double, std::milli>(Clock::now() - *m_solve_panel.stroke_released).count());
    }
    m_solve_panel.fine_tune_after_stroke = false;
    if (m_solve_panel.fine_tune_queued && !m_job->busy()) {
      // A stroke ended while this job ran: its fine-tune starts now.
      m_solve_panel.fine_tune_queued = false;
      m_solve_panel.stroke_released = Clock::now();
      m_solve_panel.fine_tune_after_stroke = perform(FineTuneAction{});
      if (!m_solve_panel.fine_tune_after_stroke) m_solve_panel.stroke_released.reset();
    }
  }
  if (std::optional<ui::Illumination> done = m_illumination_worker->take()) {
    m_display.radiance = std::move(done->radiance);
    m_display.radiance_final = done->final;
    m_display.radiance_lights = std::move(done->lights);
    m_display.colours_dirty = true;
  }
  m_display.illumination_pending = m_illumination_worker->busy();
  // The stroke's fine-tune is over and the view shows its lights.
  if (m_solve_panel.stroke_released && !m_solve_panel.fine_tune_after_stroke && !m_job->busy() &&
      m_display.requested_lights && *m_display.requested_lights == m_document->state().lights &&
      m_display.radiance_lights == m_document->state().lights) {
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - *m_solve_panel.stroke_released).count();
    if (!m_solve_panel.stroke_shown) m_timer.add_latency("stroke_to_display", ms);
    m_solve_panel.stroke_shown = true;
    if (m_display.radiance_final) {
      m_timer.add_latency("stroke_to_exact_display", ms);
      m_solve_panel.stroke_released.reset();
      m_solve_panel.stroke_shown = false;
    }
  }
  if (!m_illumination_worker->error().empty()) status("display renderer: " + m_illumination_worker->error());
}

void PainterApp::request_illumination() {
  const Lighting& lights = m_document->state().lights;
  if (m_display.requested_lights && lights == *m_display.requested_lights) return;
  m_display.requested_lights = lights;
  m_illumination_worker->request(lights, m_document->revision());
  m_display.illumination_pending = true;
}

void PainterApp::settle() {
  request_illumination();
  m_illumination_worker->wait_idle();
  poll_workers();
  refresh_colours();
}

void PainterApp::refresh_colours() {
  const PaintState& s = m_document->state();
  if (!m_display.colours_dirty && m_display.colours_revision == m_document->revision()) return;
  if (m_display.radiance.size() != m_scene->positions.size()) return;  // nothing rendered yet
  const bool no_lights = s.lights.empty();
  if (!m_display.exposure_from_result) {
    // Once per view, from the first lit result (until then from the target):
    // later changes of brightness stay visible instead of being normalized
    // away, and target and result are shown alike. Each view (the opening
    // one, a plan, a walk, another room) is exposed for what it shows
    // (view_changed); the whole scene when it shows too little to judge.
    float from_result = 0.f;
    if (!no_lights && m_display.radiance_final) {
      from_result = exposure_of_view();
      if (from_result <= 0.f) from_result = ui::auto_exposure(m_display.radiance);
    }
    if (from_result > 0.f) {
      m_display.exposure = from_result;
      m_display.exposure_from_result = true;
    } else if (m_document->painted_count() > 0) {
      m_display.exposure = ui::auto_exposure(s.psi, s.weight);
    }
  }
  const float exposure = (m_display.exposure > 0.f ? m_display.exposure : 1.f) * std::exp2(m_display.exposure_stops);
  std::vector<ui::VertexColour> colours;
  switch (m_display.view) {
  case ui::ViewMode::Result:
    colours = no_lights ? ui::result_colours(m_preview, 1.f) : ui::result_colours(m_display.radiance, exposure);
    break;
  case ui::ViewMode::Target: colours = ui::target_colours(s.psi, s.weight, m_preview, exposure); break;
  case ui::ViewMode::Difference: colours = ui::difference_colours(s.psi, s.weight, m_display.radiance, m_preview, exposure); break;
  }
  for (uint32_t v : m_display.unreachable)
    if (v < colours.size()) colours[v].hatch = ui::kUnreachableHatch;
  m_mesh->set_colours(colours);
  ++m_colour_uploads;
  m_display.colours_revision = m_document->revision();
  m_display.colours_dirty = false;
}

void PainterApp::view_changed() {
  m_display.exposure_from_result = false;
  m_display.colours_dirty = true;
}

float PainterApp::exposure_of_view() const {
  int w = 1, h = 1;
  m_window->framebuffer_size(w, h);
  const float width = float(std::max(w, 1)), height = float(std::max(h, 1));
  const auto ray_through = [&](float x, float y) {
    return m_plan ? m_plan->ray_through(x * width, y * height, width, height, aspect())
                  : m_camera.ray_through(x * width, y * height, width, height);
  };
  return ui::view_exposure(*m_rays, m_display.radiance, ray_through, m_player->visibility());
}

void PainterApp::draw_scene() {
  int w = 1, h = 1;
  m_window->framebuffer_size(w, h);
  build_overlays();
  const glm::mat4 view_projection = this->view_projection();
  // The section and cutaway: what the mesh draws follows the player's visibility.
  m_player->visibility();
  const bool clip_changed = m_player->visibility_revision() != m_shown_visibility;
  if (clip_changed) {
    m_mesh->set_shown_triangles(*m_scene, m_player->visibility().triangles());
    m_mesh->set_section(m_player->clip().section);
    m_shown_visibility = m_player->visibility_revision();
  }
  const bool stale = clip_changed || m_view_buffer->resize(w, h) || view_projection != m_drawn_view_projection ||
                     m_drawn_colour_uploads != m_colour_uploads || m_lines->changed_since_draw();
  if (stale) {
    m_view_buffer->bind();
    glViewport(0, 0, w, h);
    glClearColor(0.055f, 0.06f, 0.07f, 1.f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    m_mesh->draw(view_projection);
    m_lines->draw(view_projection);
    m_drawn_view_projection = view_projection;
    m_drawn_colour_uploads = m_colour_uploads;
  }
  m_view_buffer->blit_to_window();
  glViewport(0, 0, w, h);
}

void PainterApp::build_overlays() {
  m_lines->clear();
  const PaintState& s = m_document->state();
  const float diagonal = m_scene->diagonal();
  if (m_display.show_lights) {
    ui::add_light_markers(*m_lines, s.lights, diagonal);
    ui::add_spot_hint_markers(*m_lines, s.spot_hints, diagonal);
  }
  if (const auto& estimate = m_player->last_shadow_estimate(); estimate && m_player->tool() == Tool::Shadow)
    ui::add_shadow_estimate_markers(*m_lines, *estimate);
  if (m_tools.hover && (m_player->tool() == Tool::Brush || m_player->tool() == Tool::Eraser || m_player->tool() == Tool::Adjust)) {
    const glm::vec4 colour = m_player->tool() == Tool::Eraser ? glm::vec4(1.f, 0.35f, 0.3f, 1.f) : glm::vec4(1.f);
    m_lines->circle(m_tools.hover->position + 0.002f * diagonal * m_tools.hover->normal, m_tools.hover->normal, m_player->brush().radius, colour);
  }
  const glm::vec4 region_colour = m_player->tool() == Tool::Spot     ? glm::vec4(1.f, 0.85f, 0.2f, 1.f)
                                  : m_player->tool() == Tool::Adjust ? glm::vec4(0.3f, 0.9f, 1.f, 1.f)
                                                                     : glm::vec4(0.6f, 0.6f, 0.65f, 1.f);
  for (const Vec3& p : m_tools.region) m_lines->point(p, region_colour, 5.f);
  for (const auto& pair : m_tools.shadow_pairs)
    for (const Vec3& p : pair.points.world) m_lines->point(p, glm::vec4(0.45f, 0.45f, 0.5f, 1.f), 5.f);
  if (m_tools.occluder_point && m_player->tool() == Tool::Shadow) {
    Hit hit = m_rays->closest_point(*m_tools.occluder_point, 0.01f * diagonal);
    if (hit.valid()) ui::add_box_marker(*m_lines, m_player->objects().bounds(m_player->objects().object_of_triangle(hit.triangle)),
                                        glm::vec4(0.3f, 1.f, 0.4f, 1.f));
  }
}

void PainterApp::status(const std::string& line) {
  // ImGui's built-in font is ASCII: spell out the core's D̄ (D + combining macron).
  m_status_panel.line = line;
  for (size_t at; (at = m_status_panel.line.find("D\u0304")) != std::string::npos;) m_status_panel.line.replace(at, 3, "D-bar");
  m_status_panel.log.push_back(m_status_panel.line);
  if (m_status_panel.log.size() > 200) m_status_panel.log.erase(m_status_panel.log.begin());
  if (m_headless) std::fprintf(stderr, "hilight: %s\n", line.c_str());
}

} // namespace hilight::painter
