// A module the registry must refuse: it claims another ABI version, or another
// build key. If the checks were missing, registering it would succeed and the
// ABI test would fail.
#include "hilight/plugin.hpp"
#include "hilight/registry.hpp"

namespace {
void register_nothing(void*) {}
} // namespace

extern "C" __attribute__((visibility("default"))) const HilightPluginEntry* hilight_plugin_entry(void) {
#if defined(REFUSED_WRONG_ABI)
  static const HilightPluginEntry entry = {HILIGHT_ABI_VERSION + 1, HILIGHT_BUILD_KEY, "renderer", "wrong-abi", "9.9",
                                           "built against a future ABI", &register_nothing};
#else
  static const HilightPluginEntry entry = {HILIGHT_ABI_VERSION, "othercc-99/otherlib/c++1", "renderer", "wrong-key", "9.9",
                                           "built by another compiler", &register_nothing};
#endif
  return &entry;
}
