# HILIGHT_SANITIZE=ON: every target (the framework, the plugin modules, the
# launcher, the tests and the test-only modules) is compiled and linked with
# AddressSanitizer and UndefinedBehaviorSanitizer. Any UB report is fatal
# (-fno-sanitize-recover), so a finding fails the process that hit it.
# tools/sanitize.sh builds such a tree (build-asan/) and runs a subset of the
# suite in it (issue 15). Include before the add_subdirectory() calls.
option(HILIGHT_SANITIZE "Build every target with AddressSanitizer + UBSan (tools/sanitize.sh)" OFF)
if(HILIGHT_SANITIZE)
  set(HILIGHT_SANITIZE_FLAGS -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_compile_options(${HILIGHT_SANITIZE_FLAGS})
  add_link_options(${HILIGHT_SANITIZE_FLAGS})
  message(STATUS "hilight: AddressSanitizer + UBSan on every target")
endif()
