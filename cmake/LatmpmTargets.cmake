# The three kinds of target, so a library, tool or test directory is a few lines.

set(LATMPM_WARNINGS -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor)
set(LATMPM_OPT_FLAGS)
if(LATMPM_NATIVE)
  list(APPEND LATMPM_OPT_FLAGS $<$<CONFIG:Release,RelWithDebInfo>:-march=native>)
endif()

# latmpm_add_library(<name> SOURCES a.cpp ... DEPS <targets>)  ->  latmpm_<name>, latmpm::<name>
# Headers are included as "<name>/<file>.hpp" (include root: libs/).
function(latmpm_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(latmpm_${name} ${ARG_SOURCES})
  add_library(latmpm::${name} ALIAS latmpm_${name})
  target_include_directories(latmpm_${name} PUBLIC ${PROJECT_SOURCE_DIR}/libs)
  target_link_libraries(latmpm_${name} PUBLIC ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  target_compile_options(latmpm_${name} PRIVATE ${LATMPM_WARNINGS} ${LATMPM_OPT_FLAGS})
endfunction()

# latmpm_add_tool(<name> SOURCES main.cpp DEPS <targets>)  ->  build/bin/<name>
# Every sample run in the tool's --help (lines starting with "  $ ") becomes a CTest smoke test.
function(latmpm_add_tool name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS})
  target_compile_options(${name} PRIVATE ${LATMPM_WARNINGS} ${LATMPM_OPT_FLAGS})
  if(LATMPM_BUILD_TESTS)
    add_test(NAME smoke.${name}.help-examples
             COMMAND bash ${PROJECT_SOURCE_DIR}/scripts/run-help-examples.sh
                     $<TARGET_FILE_DIR:${name}> ${name} ${PROJECT_SOURCE_DIR})
    set_tests_properties(smoke.${name}.help-examples PROPERTIES LABELS smoke TIMEOUT 600)
  endif()
endfunction()

# latmpm_add_test(<name> SOURCES a.cpp ... DEPS <targets>)  ->  test_<name>, one CTest per TEST_CASE
function(latmpm_add_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(test_${name} ${ARG_SOURCES})
  target_link_libraries(test_${name} PRIVATE latmpm_catch_main ${ARG_DEPS})
  target_include_directories(test_${name} PRIVATE ${PROJECT_SOURCE_DIR}/tests/support)
  target_compile_options(test_${name} PRIVATE ${LATMPM_WARNINGS} ${LATMPM_OPT_FLAGS})
  target_compile_definitions(test_${name} PRIVATE
    LATMPM_SOURCE_DIR="${PROJECT_SOURCE_DIR}" LATMPM_BIN_DIR="${CMAKE_RUNTIME_OUTPUT_DIRECTORY}")
  catch_discover_tests(test_${name} TEST_PREFIX "${name}."
                       PROPERTIES LABELS ${name} TIMEOUT 900)
endfunction()

# Adds every immediate subdirectory of the current source dir that has a CMakeLists.txt,
# so a new library, tool or test directory needs no edit outside itself.
function(latmpm_add_subdirectories)
  file(GLOB children RELATIVE ${CMAKE_CURRENT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR}/*)
  list(SORT children)
  foreach(child ${children})
    if(IS_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/${child}
       AND EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${child}/CMakeLists.txt)
      add_subdirectory(${child})
    endif()
  endforeach()
endfunction()
