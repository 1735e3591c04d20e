#pragma once
/// First-bounce gathers shared by every Embree renderer in the process. A
/// solve's reference and its fast twin cast the same gather rays from the
/// same points (the same count and seed; bounce_direct only changes how the
/// hits are read), and each kept its own: 141 MB twice over the bench
/// building's vertices, and the second built in vain. Held weakly: a gather
/// lives while some renderer keeps it (its KeyedLru), and every holder also
/// holds the RayScene the gather refers to.
#include "first_bounce.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace hilight::embree {

class SharedGathers {
public:
  struct Key {
    const RayScene* scene = nullptr;
    uint64_t points = 0;  ///< SurfacePoints::content_key()
    int samples = 0;
    uint64_t seed = 0;
    bool operator==(const Key&) const = default;
  };

  /// The live gather another renderer made for `key`; null if none.
  static std::shared_ptr<const BounceGather> find(const Key& key) {
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    for (const auto& [k, gather] : r.entries)
      if (k == key)
        if (auto live = gather.lock()) return live;
    return nullptr;
  }
  /// Offers `gather` (made for `key`) to the other renderers.
  static void add(const Key& key, const std::shared_ptr<const BounceGather>& gather) {
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    std::erase_if(r.entries, [&](const auto& e) { return e.second.expired() || e.first == key; });
    r.entries.emplace_back(key, gather);
  }

private:
  struct Registry {
    std::mutex mutex;
    std::vector<std::pair<Key, std::weak_ptr<const BounceGather>>> entries;
  };
  static Registry& registry() {
    static Registry r;
    return r;
  }
};

} // namespace hilight::embree
