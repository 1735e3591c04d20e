// IES LM-63 and EULUMDAT: any text gives a profile or an InputError; a
// profile read is evaluated where renderers evaluate it.
#include "fuzz_support.hpp"
#include "hilight/error.hpp"
#include "hilight/io/photometry_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text = fuzz::text(data, size);
  for (int format = 0; format < 2; ++format) {
    try {
      const hilight::Photometry p = format ? hilight::parse_ldt(text, "fuzz.ldt") : hilight::parse_ies(text, "fuzz.ies");
      for (double c : {0.0, 45.0, 181.0, 359.9})
        for (double g : {0.0, 30.0, 90.0, 179.0}) (void)p.intensity(c, g);
      (void)p.peak();
    } catch (const hilight::InputError&) {
    }
  }
  return 0;
}
