# The installed SDK (docs/plugins.md): the headers a plugin needs, the
# framework library's exported target, hilightConfig.cmake with its version
# file, and hilight_add_plugin() for plugins built outside this tree.

# The SDK's headers: the plugin interfaces and everything they include,
# followed through `#include "hilight/..."`, so the installed set is closed.
set(HILIGHT_SDK_ROOT_HEADERS hilight/plugin.hpp hilight/registry.hpp hilight/error.hpp hilight/threads.hpp hilight/progress.hpp)
function(hilight_header_closure out)
  set(dir ${PROJECT_SOURCE_DIR}/framework/include)
  set(pending ${ARGN})
  set(seen "")
  while(pending)
    list(POP_FRONT pending header)
    if(header IN_LIST seen OR NOT EXISTS ${dir}/${header})
      continue()
    endif()
    list(APPEND seen ${header})
    file(STRINGS ${dir}/${header} lines REGEX "^#include \"hilight/")
    foreach(line IN LISTS lines)
      string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" included "${line}")
      list(APPEND pending ${included})
    endforeach()
  endwhile()
  list(SORT seen)
  set(${out} ${seen} PARENT_SCOPE)
endfunction()
hilight_header_closure(HILIGHT_SDK_HEADERS ${HILIGHT_SDK_ROOT_HEADERS})
# Configure again when a header changes what it includes.
foreach(header IN LISTS HILIGHT_SDK_HEADERS)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/framework/include/${header})
  get_filename_component(subdir ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/framework/include/${header} DESTINATION include/${subdir} COMPONENT dev)
endforeach()
install(FILES ${CMAKE_BINARY_DIR}/include/hilight/version.hpp DESTINATION include/hilight COMPONENT dev)

include(CMakePackageConfigHelpers)
set(HILIGHT_CMAKE_DIR lib/cmake/hilight)
install(EXPORT hilightTargets NAMESPACE hilight:: DESTINATION ${HILIGHT_CMAKE_DIR} COMPONENT dev)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/hilightConfig.cmake.in
  ${CMAKE_BINARY_DIR}/hilightConfig.cmake INSTALL_DESTINATION ${HILIGHT_CMAKE_DIR})
# Before 1.0 a minor release may break plugins: only the same minor version is compatible.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/hilightConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/hilightConfig.cmake ${CMAKE_BINARY_DIR}/hilightConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/HilightPlugin.cmake
  DESTINATION ${HILIGHT_CMAKE_DIR} COMPONENT dev)
