// --bench: the interactive figures of docs/benchmarks.md, measured through
// the same frame loop a designer drives — camera orbit frames, brush-stroke
// frames (a dab per frame, as the mouse gives them), and the time from
// releasing a stroke to the fine-tuned lights and to their display, while
// frames keep being drawn.
#include "painter_app.hpp"
#include "ui/screen_pick.hpp"

namespace hilight::painter {

void PainterApp::run_bench() {
  int w = 1, h = 1;
  m_window->framebuffer_size(w, h);
  settle();
  m_display.last_activity = "camera";
  for (int i = 0; i < 60; ++i) {
    m_camera.orbit(1.f, i < 30 ? 0.3f : -0.3f);
    frame(false);
  }
  const BrushSettings brush = m_player->brush();
  for (int round = 0; round < 5; ++round) {
    // A horizontal stroke across the middle of the view, 40 mouse moves.
    m_display.last_activity = "stroke";
    Stroke stroke(*m_document, brush, BrushMode::Paint, &m_player->visibility());
    const float y = float(h) * (0.55f + 0.04f * float(round));
    for (int i = 0; i < 40; ++i) {
      const float x = float(w) * (0.3f + 0.4f * float(i) / 39.f);
      if (auto pick = pick_window_pixel(x, y)) {
        if (stroke.points().empty()) stroke.dab(*pick);
        else stroke.drag_to(*pick);
      }
      frame(false);
    }
    stroke.finish();
    if (m_document->state().lights.empty() || m_document->painted_count() == 0) continue;
    // Release: fine-tune in the background while frames go on.
    m_display.last_activity = "fine_tune_running";
    m_solve_panel.stroke_released = Clock::now();
    m_solve_panel.fine_tune_after_stroke = true;
    // Through the player, as a stroke's fine-tune starts (a job it did not
    // start would be dropped as superseded when it ends).
    m_player->start_in_background(JobKind::FineTune);
    const auto give_up = Clock::now() + std::chrono::seconds(30);
    // As the interactive loop does while work runs in the background: a frame
    // every kBackgroundFrameSeconds, or at once when the job or a display pass ends.
    while ((m_job->busy() || m_solve_panel.fine_tune_after_stroke || m_solve_panel.stroke_released) && Clock::now() < give_up) {
      const auto next = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(kBackgroundFrameSeconds));
      frame(false);
      glfwWaitEventsTimeout(std::max(0.0, std::chrono::duration<double>(next - Clock::now()).count()));
    }
  }
  m_display.last_activity = "idle";
}

} // namespace hilight::painter
