#include "hilight/light_cache_file.hpp"

#include "hilight/hash.hpp"
#include "hilight/io/atomic_file.hpp"
#include "hilight/version.hpp"

#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hilight {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[8] = {'H', 'L', 'C', 'A', 'C', 'H', 'E', '2'};
// 9: the cache is a plugin; the file carries a checksum of its contents.
constexpr uint32_t kFileFormat = 9;
// A cache holds rendered responses, so one made under another rendering model
// is stale even for the same scene and settings. Bump this whenever shading
// changes (where points are shaded, ray offsets: docs/rendering-model.md);
// releases are told apart by HILIGHT_VERSION as well.
// 2: tolerances relative to the scene's size (issue 19).
// 3: the bounce's streams and sample frames in the scene's own frame.
// 4: gather hits' barycentrics in 16 bits.
// 5: a crease point's face chosen in the own frame's order, whatever order
//    the triangles were found in.
constexpr uint32_t kRenderingModel = 5;

struct Header {
  char magic[8];
  uint32_t format;
  uint32_t reserved;
  uint64_t key;
  uint64_t payload_bytes;
  uint64_t checksum;  ///< hash_words of the payload
};

} // namespace

uint64_t light_cache_key(const Scene& scene, const std::string& renderer_key, const std::string& cache_settings_key,
                         const Bounds& bounds) {
  uint64_t h = kFnvOffset;
  h = fnv1a(h, &kFileFormat, sizeof(kFileFormat));
  h = fnv1a(h, &kRenderingModel, sizeof(kRenderingModel));
  h = fnv1a(h, HILIGHT_VERSION, sizeof(HILIGHT_VERSION) - 1);
  h = hash_words(h, scene.positions.data(), scene.positions.size() * sizeof(Vec3));
  h = hash_words(h, scene.normals.data(), scene.normals.size() * sizeof(Vec3));
  h = hash_words(h, scene.triangles.data(), scene.triangles.size() * sizeof(scene.triangles[0]));
  h = hash_words(h, scene.triangle_material.data(), scene.triangle_material.size() * sizeof(uint32_t));
  for (const auto& m : scene.materials) h = fnv1a(h, &m.albedo, sizeof(m.albedo));
  for (const std::string* s : {&renderer_key, &cache_settings_key}) {
    const uint64_t size = s->size();
    h = fnv1a(h, &size, sizeof(size));
    h = fnv1a(h, s->data(), s->size());
  }
  h = fnv1a(h, &bounds.lo, sizeof(bounds.lo));
  h = fnv1a(h, &bounds.hi, sizeof(bounds.hi));
  return h;
}

void save_light_cache(const fs::path& file, uint64_t key, const LightCache& cache) {
  std::ostringstream contents(std::ios::binary);
  cache.write(contents);
  if (!contents) throw std::runtime_error("light cache: could not serialize");
  const std::string payload = std::move(contents).str();
  Header header{};
  std::memcpy(header.magic, kMagic, sizeof(kMagic));
  header.format = kFileFormat;
  header.key = key;
  header.payload_bytes = payload.size();
  header.checksum = hash_words(kFnvOffset, payload.data(), payload.size());
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  write_atomically(file, [&](const fs::path& temp) {
    std::ofstream out(temp, std::ios::binary);
    out.write(reinterpret_cast<const char*>(&header), sizeof(header));
    out.write(payload.data(), std::streamsize(payload.size()));
    if (!out) throw std::runtime_error("light cache: write failed");
  });
}

LoadedCache load_light_cache(const fs::path& file, uint64_t key, const LightCacheBuilder& builder, size_t vertex_count) {
  LoadedCache loaded;
  std::ifstream in(file, std::ios::binary);
  if (!in) return loaded;
  Header header{};
  if (!in.read(reinterpret_cast<char*>(&header), sizeof(header)) || std::memcmp(header.magic, kMagic, sizeof(kMagic)) != 0 ||
      header.format != kFileFormat || header.key != key)
    return loaded;  // another scene, setting or format: not ours to judge
  std::error_code ec;
  const uint64_t size = fs::file_size(file, ec);
  if (ec || size != sizeof(header) + header.payload_bytes) {
    loaded.damage = "its size does not match its header (truncated?)";
    return loaded;
  }
  std::string payload(header.payload_bytes, '\0');
  if (!in.read(payload.data(), std::streamsize(payload.size()))) {
    loaded.damage = "it could not be read";
    return loaded;
  }
  if (hash_words(kFnvOffset, payload.data(), payload.size()) != header.checksum) {
    loaded.damage = "its checksum does not match (damaged)";
    return loaded;
  }
  std::istringstream contents(std::move(payload), std::ios::binary);
  loaded.cache = builder.read(contents, vertex_count);
  if (!loaded.cache) loaded.damage = "its contents do not fit this scene";
  return loaded;
}

} // namespace hilight
