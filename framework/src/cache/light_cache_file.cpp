#include "hilight/light_cache_file.hpp"

#include "hilight/hash.hpp"
#include "hilight/io/atomic_file.hpp"
#include "hilight/version.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

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

/// Closes its descriptor when it goes.
struct Fd {
  int fd;
  explicit Fd(int f) : fd(f) {}
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
};

bool read_all(int fd, void* data, size_t size) {
  char* p = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t got = ::read(fd, p, size);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    p += got;
    size -= size_t(got);
  }
  return true;
}

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
  const fs::path dir = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  if (!fs::is_directory(dir, ec) && !fs::create_directories(dir, ec) && ec)
    throw std::runtime_error("cannot create the folder " + dir.string() + ": " + ec.message());
  // Never written in place: a FIFO or device there would hang or take the bytes.
  struct stat st {};
  if (::lstat(file.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) throw std::runtime_error("it is not a regular file");
  write_atomically(file, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(&header), sizeof(header));
    out.write(payload.data(), std::streamsize(payload.size()));
  });
}

LoadedCache load_light_cache(const fs::path& file, uint64_t key, const LightCacheBuilder& builder, size_t vertex_count) {
  LoadedCache loaded;
  // Every number in the file is read as untrusted input: the checksum is no
  // secret, so a forged file passes it.
  const Fd fd(::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));  // O_NONBLOCK: a FIFO must not hang the solve
  if (fd.fd < 0) return loaded;
  struct stat st {};
  if (::fstat(fd.fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    loaded.damage = "it is not a regular file";
    return loaded;
  }
  Header header{};
  if (!read_all(fd.fd, &header, sizeof(header)) || std::memcmp(header.magic, kMagic, sizeof(kMagic)) != 0 ||
      header.format != kFileFormat || header.key != key)
    return loaded;  // another scene, setting or format: not ours to judge
  // Compared without adding to the header's number: a crafted size must not wrap.
  const uint64_t size = uint64_t(st.st_size);
  if (size < sizeof(header) || header.payload_bytes != size - sizeof(header)) {
    loaded.damage = "its size does not match its header (truncated?)";
    return loaded;
  }
  try {
    std::string payload(header.payload_bytes, '\0');
    if (!read_all(fd.fd, payload.data(), payload.size())) {
      loaded.damage = "it could not be read";
      return loaded;
    }
    if (hash_words(kFnvOffset, payload.data(), payload.size()) != header.checksum) {
      loaded.damage = "its checksum does not match (damaged)";
      return loaded;
    }
    std::istringstream contents(std::move(payload), std::ios::binary);
    loaded.cache = builder.read(contents, vertex_count);
  } catch (const std::exception& e) {  // too large to hold, or a reader's refusal
    loaded.cache.reset();
    loaded.damage = std::string("it could not be read (") + e.what() + ")";
    return loaded;
  }
  if (!loaded.cache) loaded.damage = "its contents do not fit this scene";
  return loaded;
}

} // namespace hilight
