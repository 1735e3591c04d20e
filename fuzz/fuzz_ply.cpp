// Target and scene PLY files (ascii and binary): vertices or an InputError.
#include "fuzz_support.hpp"
#include "hilight/error.hpp"
#include "hilight/io/ply_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    hilight::read_ply_vertices(fuzz::file(data, size, ".ply"));
  } catch (const hilight::InputError&) {
  }
  return 0;
}
