# hilight_add_plugin(KIND NAME SOURCES ... [LIBS ...])
# Builds one plugin = one shared module named hilight-<kind>-<name>.so in
# lib/hilight/, linked against the framework library. Its registered name must
# equal NAME (the folder name); the module's HILIGHT_PLUGIN macro receives it
# through HILIGHT_PLUGIN_NAME so the two cannot drift apart.
function(hilight_add_plugin kind name)
  cmake_parse_arguments(P "" "" "SOURCES;LIBS" ${ARGN})
  set(target hilight-${kind}-${name})
  add_library(${target} MODULE ${P_SOURCES})
  set_target_properties(${target} PROPERTIES
    PREFIX ""
    LIBRARY_OUTPUT_DIRECTORY ${HILIGHT_PLUGIN_OUTPUT_DIR}
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON
    INSTALL_RPATH "$ORIGIN/.."
    BUILD_RPATH "${CMAKE_BINARY_DIR}/lib")
  target_compile_definitions(${target} PRIVATE HILIGHT_PLUGIN_NAME="${name}")
  target_link_libraries(${target} PRIVATE hilight_framework ${P_LIBS})
  hilight_warnings(${target})
  install(TARGETS ${target} LIBRARY DESTINATION lib/hilight)
  set_property(GLOBAL APPEND PROPERTY HILIGHT_PLUGIN_TARGETS ${target})
endfunction()
