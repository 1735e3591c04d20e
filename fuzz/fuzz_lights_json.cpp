// Lights files: any text gives lights or an InputError, nothing else.
#include "fuzz_support.hpp"
#include "hilight/error.hpp"
#include "hilight/io/lights_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    hilight::parse_lights_json(fuzz::text(data, size), "fuzz.json");
  } catch (const hilight::InputError&) {
  }
  return 0;
}
