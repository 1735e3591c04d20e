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

/// A fast word-at-a-time hash for large arrays (point sets hashed on every
/// renderer call): 8 bytes per step, multiply-rotate mixing.
inline uint64_t hash_words(uint64_t hash, const void* data, size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  size_t i = 0;
  for (; i + 8 <= bytes; i += 8) {
    uint64_t w;
    __builtin_memcpy(&w, p + i, 8);
    hash = (hash ^ (w * 0x9E3779B97F4A7C15ull));
    hash = ((hash << 27) | (hash >> 37)) * 0xBF58476D1CE4E5B9ull;
  }
  return fnv1a(hash, p + i, bytes - i);  // the tail
}

} // namespace hilight
