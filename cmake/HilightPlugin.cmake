# hilight_add_plugin(KIND NAME SOURCES ... [LIBS ...])
# Builds one plugin = one shared module named hilight-<kind>-<name>.so,
# linked against the framework library (hilight::framework). Its registered
# name must equal NAME: the module's HILIGHT_PLUGIN macro receives it through
# HILIGHT_PLUGIN_NAME, so the two cannot drift apart.
#
# The same file serves the tree's own plugins and, installed beside
# hilightConfig.cmake, plugins built outside it against an installed hilight
# (docs/plugins.md). In the tree, modules land in HILIGHT_PLUGIN_OUTPUT_DIR;
# outside it, in <build>/lib/hilight, a folder to put on HILIGHT_PLUGIN_PATH.
# Either way `cmake --install` puts them in <prefix>/lib/hilight.
function(hilight_add_plugin kind name)
  cmake_parse_arguments(P "" "" "SOURCES;LIBS" ${ARGN})
  set(target hilight-${kind}-${name})
  set(output_dir ${HILIGHT_PLUGIN_OUTPUT_DIR})
  if(NOT output_dir)
    set(output_dir ${CMAKE_BINARY_DIR}/lib/hilight)
  endif()
  add_library(${target} MODULE ${P_SOURCES})
  set_target_properties(${target} PROPERTIES
    PREFIX ""
    LIBRARY_OUTPUT_DIRECTORY ${output_dir}
    CXX_STANDARD 20
    CXX_STANDARD_REQUIRED ON
    CXX_EXTENSIONS OFF
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON
    INSTALL_RPATH "$ORIGIN/..")
  # Built with the install RPATH: a build RPATH is padded with empty entries
  # (for the install to edit in place), which the loader reads as the current
  # folder (framework/CMakeLists.txt). The framework it links is the one the
  # launcher has loaded already; a plugin that needs libraries of its own
  # from elsewhere adds their folder to INSTALL_RPATH.
  set_target_properties(${target} PROPERTIES BUILD_WITH_INSTALL_RPATH ON)
  target_compile_definitions(${target} PRIVATE HILIGHT_PLUGIN_NAME="${name}")
  target_link_libraries(${target} PRIVATE hilight::framework ${P_LIBS})
  if(COMMAND hilight_warnings)
    hilight_warnings(${target})
  endif()
  install(TARGETS ${target} LIBRARY DESTINATION lib/hilight COMPONENT runtime)
  set_property(GLOBAL APPEND PROPERTY HILIGHT_PLUGIN_TARGETS ${target})
endfunction()
