#pragma once
/// FNV-1a over raw bytes: cheap content keys for caches (point sets, scenes).
#include <cstddef>
#include <cstdint>

namespace hilight {

constexpr uint64_t kFnvOffset = 1469598103934665603ull;

inline uint64_t fnv1a(uint64_t hash, const void* data, size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < bytes; ++i) {
    hash ^= p[i];
    hash *= 1099511628211ull;
  }
  return hash;
}

} // namespace hilight
