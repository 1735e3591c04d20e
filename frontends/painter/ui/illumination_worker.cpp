#include "ui/illumination_worker.hpp"

#include <chrono>
#include <exception>
#include <stdexcept>

namespace hilight::painter::ui {

IlluminationWorker::IlluminationWorker(std::vector<std::unique_ptr<Renderer>> stages, const Scene& scene,
                                       std::function<void()> on_result)
    : m_stages(std::move(stages)), m_on_result(std::move(on_result)), m_points(SurfacePoints::from_vertices(scene)) {
  if (m_stages.empty()) throw std::logic_error("IlluminationWorker: no renderer");
  m_thread = std::thread([this] { run(); });
}

IlluminationWorker::~IlluminationWorker() {
  {
    std::lock_guard lock(m_mutex);
    m_stop = true;
  }
  m_wake.notify_all();
  m_thread.join();
}

void IlluminationWorker::request(const Lighting& lights, uint64_t tag) {
  {
    std::lock_guard lock(m_mutex);
    m_pending = std::make_pair(lights, tag);
  }
  m_wake.notify_all();
}

std::optional<Illumination> IlluminationWorker::take() {
  std::lock_guard lock(m_mutex);
  std::optional<Illumination> out = std::move(m_done);
  m_done.reset();
  return out;
}

bool IlluminationWorker::busy() const {
  std::lock_guard lock(m_mutex);
  return m_running || m_pending.has_value();
}

void IlluminationWorker::wait_idle() {
  std::unique_lock lock(m_mutex);
  m_idle.wait(lock, [this] { return !m_running && !m_pending; });
}

std::string IlluminationWorker::error() const {
  std::lock_guard lock(m_mutex);
  return m_error;
}

void IlluminationWorker::run() {
  std::unique_lock lock(m_mutex);
  for (;;) {
    m_wake.wait(lock, [this] { return m_stop || m_pending; });
    if (m_stop) return;
    const Lighting lights = std::move(m_pending->first);
    const uint64_t tag = m_pending->second;
    m_pending.reset();
    m_running = true;
    // No lights: darkness at once, without asking a renderer.
    const size_t stages = lights.empty() ? 1 : m_stages.size();
    for (size_t stage = 0; stage < stages; ++stage) {
      lock.unlock();
      Illumination job;
      job.lights = lights;
      job.tag = tag;
      job.final = stage + 1 == stages;
      std::string error;
      auto start = std::chrono::steady_clock::now();
      try {
        job.radiance = lights.empty() ? std::vector<Rgb>(m_points.size(), Rgb(0.f)) : m_stages[stage]->illuminate(m_points, lights);
      } catch (const std::exception& e) {
        error = e.what();
      }
      job.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      lock.lock();
      m_error = error;
      if (error.empty()) m_done = std::move(job);
      if (m_on_result) m_on_result();
      if (!error.empty() || m_pending || m_stop) break;  // a newer request makes later stages moot
    }
    m_running = false;
    if (!m_pending) m_idle.notify_all();
  }
}

} // namespace hilight::painter::ui
