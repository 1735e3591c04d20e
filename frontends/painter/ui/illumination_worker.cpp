#include "ui/illumination_worker.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <stdexcept>

namespace hilight::painter::ui {

IlluminationWorker::IlluminationWorker(std::function<Stages()> make_stages, const Scene& scene, std::function<void()> on_result)
    : m_make_stages(std::move(make_stages)), m_on_result(std::move(on_result)) {
  if (!m_make_stages) throw std::logic_error("IlluminationWorker: no renderers");
  // Renderers seed each point's bounce samples from the point itself, so
  // illuminating in chunks gives the same values as all at once. Few chunks:
  // Embree keeps the bounce gathers of its last 4 point sets, and more
  // chunks than that would gather again on every pass.
  m_whole.push_back(SurfacePoints::from_vertices(scene));
  const SurfacePoints& all = m_whole.front();
  m_point_count = all.size();
  const size_t chunk_points = std::max<size_t>(1, (all.size() + kChunks - 1) / kChunks);
  for (size_t begin = 0; begin < all.size(); begin += chunk_points) {
    const size_t end = std::min(all.size(), begin + chunk_points);
    SurfacePoints chunk;
    chunk.positions.assign(all.positions.begin() + std::ptrdiff_t(begin), all.positions.begin() + std::ptrdiff_t(end));
    chunk.normals.assign(all.normals.begin() + std::ptrdiff_t(begin), all.normals.begin() + std::ptrdiff_t(end));
    chunk.albedo.assign(all.albedo.begin() + std::ptrdiff_t(begin), all.albedo.begin() + std::ptrdiff_t(end));
    m_chunks.push_back(std::move(chunk));
  }
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

bool IlluminationWorker::make_stages(std::unique_lock<std::mutex>& lock) {
  if (!m_stages.empty()) return true;
  lock.unlock();
  std::string error;
  Stages stages;
  try {
    stages = m_make_stages();
    if (stages.empty()) error = "no display renderer";
  } catch (const std::exception& e) {
    error = e.what();
  }
  lock.lock();
  m_stages = std::move(stages);
  if (!error.empty()) m_error = error;
  return error.empty();
}

void IlluminationWorker::run() {
  std::unique_lock lock(m_mutex);
  for (;;) {
    // Idle after the first answer: make the renderers now, before lights ask for them.
    if (m_answered && m_stages.empty() && m_error.empty() && !m_pending && !m_stop) make_stages(lock);
    m_wake.wait(lock, [this] { return m_stop || m_pending; });
    if (m_stop) return;
    const Lighting lights = std::move(m_pending->first);
    const uint64_t tag = m_pending->second;
    m_pending.reset();
    m_running = true;
    m_answered = true;
    if (!lights.empty() && !make_stages(lock)) {
      m_running = false;
      if (m_on_result) m_on_result();
      if (!m_pending) m_idle.notify_all();
      continue;
    }
    // No lights: darkness at once, without asking a renderer.
    const size_t stages = lights.empty() ? 1 : m_stages.size();
    for (size_t stage = 0; stage < stages; ++stage) {
      lock.unlock();
      Illumination job;
      job.lights = lights;
      job.tag = tag;
      job.final = stage + 1 == stages;
      std::string error;
      bool superseded = false;
      auto start = std::chrono::steady_clock::now();
      try {
        if (lights.empty()) job.radiance.assign(m_point_count, Rgb(0.f));
        // The exact pass after a quick one goes chunk by chunk, so a newer
        // request need not wait for it to end; a single or quick pass goes whole.
        const bool chunked = stages > 1 && stage + 1 == stages;
        for (const SurfacePoints& chunk : chunked ? m_chunks : m_whole) {
          const std::vector<Rgb> part = lights.empty() ? std::vector<Rgb>{} : m_stages[stage]->illuminate(chunk, lights);
          job.radiance.insert(job.radiance.end(), part.begin(), part.end());
          std::lock_guard check(m_mutex);
          if ((superseded = m_pending || m_stop)) break;
        }
      } catch (const std::exception& e) {
        error = e.what();
      }
      job.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      lock.lock();
      m_error = error;
      if (error.empty() && !superseded) m_done = std::move(job);
      if (m_on_result && !superseded) m_on_result();
      if (!error.empty() || m_pending || m_stop) break;  // a newer request makes later stages moot
    }
    m_running = false;
    if (!m_pending) m_idle.notify_all();
  }
}

} // namespace hilight::painter::ui
