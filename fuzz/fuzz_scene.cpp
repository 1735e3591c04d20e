// Scene files through load_scene (assimp, then hilight's size guards and
// tessellation): a scene or an InputError. The first byte picks the format.
#include "fuzz_support.hpp"
#include "hilight/error.hpp"
#include "hilight/io/scene_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  static const char* formats[] = {".obj", ".ply", ".off", ".stl", ".gltf"};
  const auto path = fuzz::file(data + 1, size - 1, formats[data[0] % 5]);
  try {
    hilight::load_scene(path, {0.f});
  } catch (const hilight::InputError&) {
  }
  return 0;
}
