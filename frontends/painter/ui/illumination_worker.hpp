#pragma once
/// Computes the result view's per-vertex illumination I(p) off the UI thread:
/// the renderer illuminates every scene vertex under the current lights.
/// Progressive: a list of renderers from quick to exact (e.g. Embree with a
/// few bounce samples, then as the user set it up); each stage's result is
/// shown as it comes. Only the newest request matters: a request made while
/// one runs replaces any that waits and skips the running one's later stages
/// (the exact stage after a quick one stops at its next quarter).
#include "hilight/renderer.hpp"
#include "hilight/scene.hpp"

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace hilight::painter::ui {

struct Illumination {
  uint64_t tag = 0;            ///< the caller's label of the request (e.g. a document revision)
  bool final = true;           ///< from the last (exact) stage
  Lighting lights;             ///< what was rendered
  std::vector<Rgb> radiance;   ///< per scene vertex
  double seconds = 0;
};

class IlluminationWorker {
public:
  using Stages = std::vector<std::unique_ptr<Renderer>>;
  /// `make_stages` returns the renderers (at least one) bound to `scene`,
  /// quick to exact. It runs on the worker's thread, once, after the first
  /// request is answered (a request without lights needs no renderer): a
  /// renderer binding a big scene takes seconds, which the window's first
  /// frame does not wait for. `on_result` (optional) is called from that
  /// thread after each result is ready (the UI wakes its event loop with it).
  IlluminationWorker(std::function<Stages()> make_stages, const Scene& scene, std::function<void()> on_result = {});
  ~IlluminationWorker();
  IlluminationWorker(const IlluminationWorker&) = delete;
  IlluminationWorker& operator=(const IlluminationWorker&) = delete;

  void request(const Lighting& lights, uint64_t tag);
  /// The newest finished result not taken yet.
  std::optional<Illumination> take();
  /// True while a request waits or runs.
  bool busy() const;
  /// Blocks until nothing waits or runs (headless replay, screenshots).
  void wait_idle();
  /// The error of the last failed request ("" if none): shown in the UI.
  std::string error() const;

private:
  void run();
  /// Makes the stages (unlocked) unless made; false if that failed (m_error says why).
  bool make_stages(std::unique_lock<std::mutex>& lock);

  std::function<Stages()> m_make_stages;
  Stages m_stages;  ///< the worker thread's only
  bool m_answered = false;  ///< a first request was answered: the stages may be made ahead
  std::function<void()> m_on_result;
  static constexpr size_t kChunks = 4;
  std::vector<SurfacePoints> m_whole;   ///< all the scene's vertices (one entry)
  std::vector<SurfacePoints> m_chunks;  ///< the same in kChunks pieces, in order
  size_t m_point_count = 0;
  mutable std::mutex m_mutex;
  std::condition_variable m_wake, m_idle;
  std::optional<std::pair<Lighting, uint64_t>> m_pending;
  std::optional<Illumination> m_done;
  bool m_running = false, m_stop = false;
  std::string m_error;
  std::thread m_thread;
};

} // namespace hilight::painter::ui
