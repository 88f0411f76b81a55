# The docs' flash, stack and RAM figures against the Cortex-M4 build's own
# (tests/docs/check_figures.py), included by tests/target/CMakeLists.txt
# where the budget tests are: the same library, probe object and tools. The
# cortex-m4 preset checks the default build's figures, cortex-m4-seed the
# seed-only build's flash; a build with any other options header lists
# every figure as skipped.
if(NOT DARAN_CONFIG_HEADER AND NOT DARAN_PROPERTY_OMIT)
  set(_daran_docs_kind default)
elseif(DARAN_CONFIG_HEADER MATCHES "tests/config/seed_options\\.h$" AND NOT DARAN_PROPERTY_OMIT)
  set(_daran_docs_kind seed)
else()
  set(_daran_docs_kind other)
endif()
set(_daran_docs_stack)
if(DARAN_STACK_USAGE)
  set(_daran_docs_stack --stack-objdir ${CMAKE_BINARY_DIR}/src/CMakeFiles/daran_ascii.dir
                        --nm ${CMAKE_NM} --objdump ${CMAKE_OBJDUMP})
endif()
add_test(NAME docs_figures_of_the_cortex_m4_build
         COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tests/docs/check_figures.py
                 --root ${PROJECT_SOURCE_DIR} --build-kind ${_daran_docs_kind}
                 --probe-object "cortex-m4=$<TARGET_OBJECTS:daran_target_sizeof>,${CMAKE_NM}"
                 --flash-lib $<TARGET_FILE:daran_ascii> --size ${CMAKE_SIZE}
                 ${_daran_docs_stack})
set_tests_properties(docs_figures_of_the_cortex_m4_build PROPERTIES SKIP_RETURN_CODE 77)
