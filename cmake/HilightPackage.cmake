# Debian packages by CPack (docs/plugins.md "Installing"): `cpack -G DEB` in
# the build folder makes
#   hilight_<version>_amd64.deb      the launcher, the framework library and the plugins
#   hilight-dev_<version>_amd64.deb  the SDK: headers, CMake package, hilight_add_plugin()
# Run-time dependencies come from dpkg-shlibdeps.
set(CPACK_PACKAGE_NAME hilight)
set(CPACK_PACKAGE_VENDOR "hilight")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "inverse lighting design: find the lights that give painted or stated illumination")
set(CPACK_PACKAGE_CONTACT "hilight developers <hilight@localhost>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL runtime dev)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
# The plugins' NEEDED libhilight_framework is in the same package.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${CMAKE_BINARY_DIR}/lib)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME hilight)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_RECOMMENDS "povray")
# IfcPlusPlus (IFC out, frontends/cli/ifc_luminaires.cpp) ships no shlibs
# file, so dpkg-shlibdeps cannot name it: the CLI plugin needs it, said here.
if(TARGET hilight_ifcpp)
  set(CPACK_DEBIAN_RUNTIME_PACKAGE_DEPENDS "libifcplusplus")
endif()
set(CPACK_DEBIAN_DEV_PACKAGE_NAME hilight-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_SHLIBDEPS OFF)
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS
  "hilight (= ${PROJECT_VERSION}), cmake (>= 3.22), libglm-dev, libembree-dev, libtbb-dev, libeigen3-dev")
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION "hilight: the launcher, the framework library and the plugins")
set(CPACK_COMPONENT_DEV_DESCRIPTION "hilight SDK: headers and CMake package to build plugins")
include(CPack)
