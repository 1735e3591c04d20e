// IES LM-63 and EULUMDAT: any text gives a profile or an InputError; a
// profile read is evaluated where renderers evaluate it, and written as IES
// (ies_text, what the Blender add-on gives Cycles) reads back to the same
// candela.
#include "fuzz_support.hpp"
#include "hilight/error.hpp"
#include "hilight/io/photometry_io.hpp"

#include <cmath>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text = fuzz::text(data, size);
  for (int format = 0; format < 2; ++format) {
    try {
      const hilight::Photometry p = format ? hilight::parse_ldt(text, "fuzz.ldt") : hilight::parse_ies(text, "fuzz.ies");
      for (double c : {0.0, 45.0, 181.0, 359.9})
        for (double g : {0.0, 30.0, 90.0, 179.0}) (void)p.intensity(c, g);
      (void)p.peak();
      if (p.type == hilight::Photometry::Type::C) {
        const hilight::Photometry back = hilight::parse_ies(hilight::ies_text(p), "written.ies");
        for (double c : {0.0, 45.0, 181.0, 359.9})
          for (double g : {0.0, 30.0, 90.0, 179.0}) {
            const double a = p.intensity(c, g), b = back.intensity(c, g);
            if (!(std::abs(a - b) <= 1e-6 * std::max(1.0, std::abs(a)))) std::abort();  // the round trip lost candela
          }
      }
    } catch (const hilight::InputError&) {
    }
  }
  return 0;
}
