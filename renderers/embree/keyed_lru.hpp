#pragma once
/// A small thread-safe most-recently-used store of per-point-set data, keyed
/// by SurfacePoints::content_key(): a solve alternates between its samples
/// and the whole target, an editing session between targets.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace hilight::embree {

template <class T>
class KeyedLru {
public:
  explicit KeyedLru(size_t capacity) : m_capacity(capacity) {}

  /// The entry for `key`, made by `make()` if absent. Shared ownership: another
  /// thread may evict it while this one still reads it.
  std::shared_ptr<const T> get(uint64_t key, const std::function<std::shared_ptr<const T>()>& make) {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      if (auto found = find_and_touch(key)) return found;
    }
    // Built without the lock: make() runs parallel loops, and a thread
    // waiting in one may be handed another task that comes here (TBB work
    // stealing) — holding the lock then would deadlock. Two threads may both
    // build the same entry; the first stored wins, both results are equal.
    std::shared_ptr<const T> made = make();
    std::lock_guard<std::mutex> lock(m_mutex);
    if (auto found = find_and_touch(key)) return found;
    if (m_items.size() >= m_capacity) m_items.pop_back();
    m_items.emplace(m_items.begin(), key, std::move(made));
    return m_items.front().second;
  }
  /// Whether `key` has an entry now (another thread may change that at once).
  bool contains(uint64_t key) {
    std::lock_guard<std::mutex> lock(m_mutex);
    return std::any_of(m_items.begin(), m_items.end(), [&](const auto& e) { return e.first == key; });
  }
  void clear() {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_items.clear();
  }

private:
  /// The entry for `key`, moved to the front; null if absent. Lock held.
  std::shared_ptr<const T> find_and_touch(uint64_t key) {
    auto it = std::find_if(m_items.begin(), m_items.end(), [&](const auto& e) { return e.first == key; });
    if (it == m_items.end()) return nullptr;
    std::rotate(m_items.begin(), it, it + 1);
    return m_items.front().second;
  }

  size_t m_capacity;
  std::mutex m_mutex;
  std::vector<std::pair<uint64_t, std::shared_ptr<const T>>> m_items;
};

} // namespace hilight::embree
