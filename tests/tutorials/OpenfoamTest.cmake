# openfoam_test(<name> <timeout> <tier> <command> [<argument>...])
# A test that runs <command> in the project's OpenFOAM environment
# (tests/run-with-openfoam), labelled openfoam and with its tier (cfd or
# quick: tests/CMakeLists.txt), stopped after <timeout> seconds; a cfd test
# runs alone (run_alone, tests/CMakeLists.txt).
function(openfoam_test name timeout tier)
  add_test(NAME ${name}
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/../run-with-openfoam ${ARGN})
  set_tests_properties(${name} PROPERTIES
    TIMEOUT ${timeout}
    LABELS "openfoam;${tier}")
  if(NOT tier STREQUAL quick)
    set_tests_properties(${name} PROPERTIES RUN_SERIAL TRUE)
  endif()
endfunction()
