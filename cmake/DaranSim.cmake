# The simulated drive as a library for a core of the adopter's options:
#
#   daran_ascii_add_sim(<target> LIBRARY <core target>)
#
# makes the static library <target>: the sources of daran_sim.h (the motor
# and load model, NVM, fault injection, extensions, the multi-drive bus)
# compiled from <root>/port/sim/lib against <core target> (a library of
# daran_ascii_add_library(), or daran_ascii::daran_ascii), whose options
# header and property list decide the model's table (a port's own rows
# included). Linking <target> gives daran_sim.h, the core and libm. <root> is
# the source tree, or <prefix>/share/daran_ascii in the installed package
# (global property DARAN_ASCII_ROOT). The prebuilt daran_ascii::sim is the
# same for the default core.
include_guard(GLOBAL)
include("${CMAKE_CURRENT_LIST_DIR}/DaranAddLibrary.cmake") # the package's helpers

function(daran_ascii_add_sim target)
  cmake_parse_arguments(PARSE_ARGV 1 _sim "" "LIBRARY" "")
  if(_sim_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "daran_ascii_add_sim(${target}): unexpected arguments "
                        "'${_sim_UNPARSED_ARGUMENTS}' (usage: daran_ascii_add_sim(<target> "
                        "LIBRARY <core target>))")
  endif()
  _daran_check_core("daran_ascii_add_sim(${target})" "${_sim_LIBRARY}")
  _daran_package_dir(_dir "daran_ascii_add_sim(${target})" port/sim/lib daran_sim_sources.cmake)
  include("${_dir}/daran_sim_sources.cmake")
  list(TRANSFORM DARAN_SIM_LIBRARY_SOURCES PREPEND "${_dir}/")

  add_library(${target} STATIC ${DARAN_SIM_LIBRARY_SOURCES})
  target_include_directories(${target} PUBLIC "$<BUILD_INTERFACE:${_dir}>")
  target_link_libraries(${target} PUBLIC ${_sim_LIBRARY})
  if(NOT CMAKE_CROSSCOMPILING)
    target_link_libraries(${target} PUBLIC m)
  endif()
  target_compile_features(${target} PUBLIC c_std_99)
  set_target_properties(${target} PROPERTIES C_EXTENSIONS OFF)
  # The same float results under every compiler and optimisation level: no
  # fused multiply-add, so recorded sessions replay bit for bit.
  target_compile_options(${target} PRIVATE
    $<$<C_COMPILER_ID:GNU,Clang,AppleClang>:-ffp-contract=off>)
endfunction()
