# Install and export rules: `cmake --install` puts the public headers,
# libdaran_ascii.a, the daran_ascii::daran_ascii CMake package and
# daran_ascii.pc under the prefix, so a firmware project can take the library
# by find_package(), by pkg-config, or (without installing) by add_subdirectory().
include_guard(GLOBAL)

include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

if(NOT DARAN_INSTALL)
  return()
endif()


set(_daran_public_headers)
foreach(_h IN ITEMS daran_ascii.h daran_build.h daran_can.h daran_client.h daran_config.h daran_drive.h daran_hal.h daran_port.h
                    daran_properties.h daran_protocol.h daran_result.h daran_update.h daran_version.h)
  list(APPEND _daran_public_headers "${PROJECT_SOURCE_DIR}/include/${_h}")
endforeach()

# The user options header changes the layout of daran_drive_t, so a consumer
# must compile against the very header the library was built with. It is
# installed next to the public headers, and the installed target names it by
# file name (found through the include directory) instead of by the path it
# had on the build machine.
set(_daran_config_header_name "")
if(DARAN_CONFIG_HEADER)
  # An absolute path here (cmake/DaranOptions.cmake resolved it).
  get_filename_component(_daran_config_header_name "${DARAN_CONFIG_HEADER}" NAME)
  foreach(_h IN LISTS _daran_public_headers)
    get_filename_component(_hn "${_h}" NAME)
    if(_hn STREQUAL _daran_config_header_name)
      message(FATAL_ERROR "DARAN_CONFIG_HEADER: rename ${_daran_config_header_name}; "
                          "the library installs a header of that name")
    endif()
  endforeach()
  # src/CMakeLists.txt defines DARAN_CONFIG_HEADER: the path here, the file
  # name in the installed package.
  install(FILES "${DARAN_CONFIG_HEADER}" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")
endif()

# Options given as plain -D flags are baked into the library but reach no
# consumer of the installed package: its daran_drive_t would have another size.
foreach(_flags IN ITEMS CMAKE_C_FLAGS CMAKE_C_FLAGS_${CMAKE_BUILD_TYPE})
  if("${${_flags}}" MATCHES "-D *DARAN_[A-Z_]+")
    message(WARNING "${_flags} sets ${CMAKE_MATCH_0}...: the installed package does not "
                    "record it, so programs built against it would disagree with the "
                    "library about daran_drive_t. Put the options in a header named by "
                    "-DDARAN_CONFIG_HEADER=... instead.")
  endif()
endforeach()

install(TARGETS daran_ascii EXPORT daran_asciiTargets
  ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
# The master side (client/, docs/client.md): daran_ascii::daran_client.
install(TARGETS daran_client EXPORT daran_asciiTargets
  ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(FILES ${_daran_public_headers} DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")
install(EXPORT daran_asciiTargets
  NAMESPACE daran_ascii::
  DESTINATION "${DARAN_INSTALL_CMAKEDIR}")

configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/daran_asciiConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/daran_asciiConfig.cmake"
  INSTALL_DESTINATION "${DARAN_INSTALL_CMAKEDIR}"
  PATH_VARS DARAN_INSTALL_DATADIR CMAKE_INSTALL_INCLUDEDIR CMAKE_INSTALL_BINDIR)
# 0.x.y: SameMajorVersion accepts any 0.* for a request of 0.*. Any target:
# a firmware project takes the functions that compile the core from the
# installed sources for its own CPU; daran_asciiConfig.cmake gives the
# prebuilt libraries only to a project built for the same system as they were.
write_basic_package_version_file(
  "${PROJECT_BINARY_DIR}/daran_asciiConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMajorVersion
  ARCH_INDEPENDENT)
install(FILES
  "${PROJECT_BINARY_DIR}/daran_asciiConfig.cmake"
  "${PROJECT_BINARY_DIR}/daran_asciiConfigVersion.cmake"
  DESTINATION "${DARAN_INSTALL_CMAKEDIR}")

# What daran_ascii_add_library() compiles for an adopter's options header:
# the core's sources and the property-index generator, in the source tree's
# layout under share/daran_ascii, and the CMake modules with the package's
# functions (each folder installs its own sources: port/sim, testkit).
install(DIRECTORY "${PROJECT_SOURCE_DIR}/src/" DESTINATION "${DARAN_INSTALL_DATADIR}/src"
        FILES_MATCHING PATTERN "*.c" PATTERN "*.h")
install(PROGRAMS "${PROJECT_SOURCE_DIR}/tools/gen_property_index.py"
        DESTINATION "${DARAN_INSTALL_DATADIR}/tools")
set(_daran_modules)
foreach(_module IN ITEMS DaranAddLibrary DaranSim DaranTestSupport DaranConformance DaranFuzzTarget)
  if(EXISTS "${PROJECT_SOURCE_DIR}/cmake/${_module}.cmake")
    list(APPEND _daran_modules "${PROJECT_SOURCE_DIR}/cmake/${_module}.cmake")
  endif()
endforeach()
install(FILES ${_daran_modules} DESTINATION "${DARAN_INSTALL_CMAKEDIR}")
# The toolchain files of the Arm presets, for a firmware project's own
# configure: --toolchain <prefix>/share/daran_ascii/toolchains/cortex-m4.cmake.
file(GLOB _daran_toolchains "${PROJECT_SOURCE_DIR}/cmake/cortex-m*.cmake")
install(FILES "${PROJECT_SOURCE_DIR}/cmake/arm-none-eabi.cmake" ${_daran_toolchains}
        DESTINATION "${DARAN_INSTALL_DATADIR}/toolchains")

# The line recorder and the replay tool (docs/recording.md): daran-record sits
# between a client and a real drive, daran-replay plays a recording into
# daran-sim, a port program or a serial device and compares the replies.
install(PROGRAMS "${PROJECT_SOURCE_DIR}/tools/daran-record" DESTINATION "${CMAKE_INSTALL_BINDIR}")
install(PROGRAMS "${PROJECT_SOURCE_DIR}/tools/replay" DESTINATION "${CMAKE_INSTALL_BINDIR}"
        RENAME daran-replay)
# Recorded sessions of the vendor's clients: replay input and fuzz seeds.
file(GLOB _daran_recordings "${PROJECT_SOURCE_DIR}/examples/recordings/*.txt")
install(FILES ${_daran_recordings} "${PROJECT_SOURCE_DIR}/tests/record/vendor-session.rec"
        DESTINATION "${DARAN_INSTALL_DATADIR}/recordings")

# pkg-config: the prefix is found from the .pc file's own place, so the tree
# can be installed with --prefix or moved after installation.
set(_daran_pc_prefix "${CMAKE_INSTALL_PREFIX}")
if(NOT IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  file(RELATIVE_PATH _daran_pc_up "/r/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/r")
  string(REGEX REPLACE "/$" "" _daran_pc_up "${_daran_pc_up}")
  set(_daran_pc_prefix "\${pcfiledir}/${_daran_pc_up}")
endif()
set(_daran_pc_cflags "")
if(_daran_config_header_name)
  set(_daran_pc_cflags " -DDARAN_CONFIG_HEADER=${_daran_config_header_name}")
endif()
# libm for sqrtf/fabsf where the compiler does not inline them (-O0 on hosts).
set(_daran_pc_libs_private "")
if(NOT CMAKE_CROSSCOMPILING AND DARAN_LIBM)
  set(_daran_pc_libs_private "\nLibs.private: -lm")
endif()
configure_file("${CMAKE_CURRENT_LIST_DIR}/daran_ascii.pc.in"
               "${PROJECT_BINARY_DIR}/daran_ascii.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/daran_ascii.pc"
        DESTINATION "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
# daran_client's own .pc: it needs the core, which pkg-config pulls in.
configure_file("${CMAKE_CURRENT_LIST_DIR}/daran_client.pc.in"
               "${PROJECT_BINARY_DIR}/daran_client.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/daran_client.pc"
        DESTINATION "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
