// Light cache files (issue 35): the grid's and the adaptive cache's readers
// behind load_light_cache. The checksum is no secret, so the input's header
// gets the right payload size and checksum first, as a forger's would: the
// fuzzer reaches the plugins' readers rather than stopping at the checksum.
// The first byte picks the plugin, the next three the scene's vertex count
// (less one); the file's own key is the one expected.
#include "fuzz_support.hpp"
#include "hilight/hash.hpp"
#include "hilight/light_cache_file.hpp"
#include "hilight/solve/samples.hpp"
#include "hilight/plugin.hpp"
#include "hilight/ray_scene.hpp"
#include "hilight/registry.hpp"

#include <cstring>

// Each plugin's entry point, renamed at compile time (fuzz/CMakeLists.txt) so both fit in one program.
extern "C" const HilightPluginEntry* hilight_plugin_entry_grid(void);
extern "C" const HilightPluginEntry* hilight_plugin_entry_adaptive(void);

// The registry is not linked: its one method a cache plugin calls.
void hilight::PluginRegistrar::cache(CacheFactory create) { m_record.create_cache = std::move(create); }

namespace {

std::unique_ptr<hilight::LightCacheBuilder> builder(const HilightPluginEntry* entry) {
  hilight::ModuleRecord record;
  hilight::PluginRegistrar registrar(record);
  entry->register_plugin(&registrar);
  return record.create_cache(hilight::Properties{});
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  constexpr size_t kHeader = 40;  // magic, format, reserved, key, payload size, checksum
  constexpr size_t kPrefix = 4;
  if (size < kPrefix + kHeader) return 0;
  static const auto grid = builder(hilight_plugin_entry_grid());
  static const auto adaptive = builder(hilight_plugin_entry_adaptive());
  const auto& chosen = data[0] % 2 ? adaptive : grid;
  const size_t vertices = 1 + (size_t(data[1]) | size_t(data[2]) << 8 | size_t(data[3]) << 16) % 100000;
  std::string file(reinterpret_cast<const char*>(data + kPrefix), size - kPrefix);
  const uint64_t payload = file.size() - kHeader;
  const uint64_t sum = hilight::hash_words(hilight::kFnvOffset, file.data() + kHeader, payload);
  std::memcpy(&file[24], &payload, 8);
  std::memcpy(&file[32], &sum, 8);
  uint64_t key = 0;
  std::memcpy(&key, &file[16], 8);
  const auto loaded = hilight::load_light_cache(fuzz::file(reinterpret_cast<const uint8_t*>(file.data()), file.size(), ".bin"), key,
                                                *chosen, vertices);
  if (!loaded.cache) return 0;
  // A cache that was read must also be safe to look up, anywhere.
  hilight::Scene scene;
  scene.positions.assign(vertices, hilight::Vec3(0.f));
  scene.triangles.push_back({0u, uint32_t(vertices - 1), uint32_t(vertices / 2)});
  hilight::SampleSet samples;
  samples.binding = {{0, 0.2f, 0.3f}, {0, 0.f, 1.f}};
  samples.target.assign(samples.binding.size(), hilight::Rgb(1.f));
  const hilight::RayScene rays(scene);  // the view traces which cell corners the light sees
  const auto view = loaded.cache->view(rays, samples);
  std::vector<hilight::Rgb> out(samples.size(), hilight::Rgb(0.f));
  for (const hilight::Vec3 p : {hilight::Vec3(0.f), hilight::Vec3(0.5f, 0.5f, 0.5f), hilight::Vec3(-1e30f, 1e30f, 3.f)})
    if (view) view->add_indirect(p, out.data());
  return 0;
}
