#pragma once
/// The one C entry point every plugin module exports, and the macro that
/// defines it. The host reads the plain C struct and checks abi_version and
/// build_key *before* any C++ type crosses the module boundary.
#include <cstdint>

#define HILIGHT_ABI_VERSION 8u  // 3: light cache plugins; 4: ModuleRecord::origin and shadowed_by, PluginDir; 5: Scene::size, RayScene::shading_step/shared/own_frame, NodeResponses in blocks of halves, Renderer::release_scratch; 6: RendererTraits::cheap_direct; 7: RendererTraits::max_bounces; 8: LightCache::view over the RayScene

#define HILIGHT_STRINGIFY2(x) #x
#define HILIGHT_STRINGIFY(x) HILIGHT_STRINGIFY2(x)

/// Compiler + standard library: what must match for C++ objects to cross.
#if defined(__clang__)
#define HILIGHT_COMPILER_KEY "clang-" HILIGHT_STRINGIFY(__clang_major__)
#elif defined(__GNUC__)
#define HILIGHT_COMPILER_KEY "gcc-" HILIGHT_STRINGIFY(__GNUC__)
#else
#define HILIGHT_COMPILER_KEY "unknown"
#endif
#if defined(_GLIBCXX_RELEASE)
#define HILIGHT_STDLIB_KEY "libstdc++-" HILIGHT_STRINGIFY(_GLIBCXX_RELEASE)
#elif defined(_LIBCPP_VERSION)
#define HILIGHT_STDLIB_KEY "libc++-" HILIGHT_STRINGIFY(_LIBCPP_VERSION)
#else
#define HILIGHT_STDLIB_KEY "unknown"
#endif
#define HILIGHT_BUILD_KEY HILIGHT_COMPILER_KEY "/" HILIGHT_STDLIB_KEY "/c++" HILIGHT_STRINGIFY(__cplusplus)

extern "C" {

/// Returned by every module's `hilight_plugin_entry()`.
struct HilightPluginEntry {
  uint32_t abi_version;     ///< HILIGHT_ABI_VERSION the module was built against
  const char* build_key;    ///< HILIGHT_BUILD_KEY the module was built with
  const char* kind;         ///< "renderer", "optimizer", "sampler", "cache" or "frontend"
  const char* name;         ///< registered name == folder name
  const char* version;      ///< the module's own version string
  const char* description;  ///< one line for `hilight plugins`
  /// Called only after the checks pass; `registrar` is a hilight::PluginRegistrar*.
  void (*register_plugin)(void* registrar);
};

typedef const HilightPluginEntry* (*HilightPluginEntryFn)(void);
}

#define HILIGHT_PLUGIN_ENTRY_SYMBOL "hilight_plugin_entry"

/// Defines the module's entry point. REGISTER_FN: void(hilight::PluginRegistrar&).
#define HILIGHT_PLUGIN(KIND, NAME, VERSION, DESCRIPTION, REGISTER_FN)                         \
  static void hilight_register_trampoline(void* registrar) {                                   \
    REGISTER_FN(*static_cast<hilight::PluginRegistrar*>(registrar));                           \
  }                                                                                            \
  extern "C" __attribute__((visibility("default"))) const HilightPluginEntry*                  \
  hilight_plugin_entry(void) {                                                                 \
    static const HilightPluginEntry entry = {HILIGHT_ABI_VERSION, HILIGHT_BUILD_KEY, KIND, NAME, \
                                             VERSION, DESCRIPTION, &hilight_register_trampoline}; \
    return &entry;                                                                             \
  }
