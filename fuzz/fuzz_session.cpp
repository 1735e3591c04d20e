// Painter session scripts: parsed, then every action typed and written back.
#include "core/actions.hpp"
#include "fuzz_support.hpp"
#include "hilight/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const hilight::painter::Session session = hilight::painter::parse_session(fuzz::text(data, size), "fuzz.json");
    for (const auto& action : session.actions) (void)hilight::painter::untyped(hilight::painter::typed(action));
    (void)hilight::painter::session_to_json(session);
  } catch (const hilight::InputError&) {
  }
  return 0;
}
