#pragma once
/// Which points see a point-like light standing at a given place. A spot
/// turned or widened at the same place, or a light at another intensity,
/// sees the same points: its direct light needs no new shadow rays. The
/// spot search re-renders a third of its lights at places it has already
/// tried (the curved models: 19,000 of 57,000 direct renders), so the
/// answers are kept per (point set, exact position), a few dozen places.
/// An entry per point: 0 not yet asked, 1 seen, 2 hidden. Renders that
/// share an entry (parallel calls) only ever write the same answer to it.
#include "hilight/math.hpp"

#include <atomic>
#include <cstdint>
#include <cstring>
#include <list>
#include <memory>
#include <mutex>
#include <vector>

namespace hilight::embree {

class VisibilityMemo {
public:
  enum : uint8_t { kUnknown = 0, kSeen = 1, kHidden = 2 };
  using Answers = std::vector<std::atomic<uint8_t>>;

  /// The answers for `count` points of the set `points_key` from a light at
  /// `position` (all unknown when new; the least recently used place is
  /// dropped). Null for a point set too large to keep.
  std::shared_ptr<Answers> get(uint64_t points_key, size_t count, const Vec3& position) {
    if (count == 0 || count > kMaxPoints) return nullptr;
    uint32_t bits[3];
    std::memcpy(bits, &position, sizeof bits);
    std::lock_guard<std::mutex> lock(m_mutex);
    for (auto it = m_places.begin(); it != m_places.end(); ++it)
      if (it->points_key == points_key && it->count == count && std::memcmp(it->bits, bits, sizeof bits) == 0) {
        m_places.splice(m_places.begin(), m_places, it);
        return it->answers;
      }
    if (m_places.size() >= kPlaces) m_places.pop_back();
    m_places.push_front(Place{points_key, count, {bits[0], bits[1], bits[2]}, std::make_shared<Answers>(count)});
    return m_places.front().answers;
  }
  void clear() {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_places.clear();
  }

private:
  /// Enough for a solve's samples and a building's vertices (64 places of
  /// 300k points: 19 MB at most).
  static constexpr size_t kPlaces = 64, kMaxPoints = 300000;
  struct Place {
    uint64_t points_key;
    size_t count;
    uint32_t bits[3];
    std::shared_ptr<Answers> answers;
  };
  std::mutex m_mutex;
  std::list<Place> m_places;
};

} // namespace hilight::embree
