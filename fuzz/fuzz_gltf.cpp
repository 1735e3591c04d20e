// glTF (text and binary): lights and vertex colours, or an InputError.
#include "fuzz_support.hpp"
#include "hilight/error.hpp"
#include "hilight/io/gltf.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto path = fuzz::file(data, size, size >= 4 && data[0] == 'g' && data[1] == 'l' ? ".glb" : ".gltf");
  try {
    hilight::read_gltf_lights(path);
  } catch (const hilight::InputError&) {
  }
  try {
    hilight::read_gltf_colours(path);
  } catch (const hilight::InputError&) {
  }
  return 0;
}
