# cmake -DFMU=<x.fmu> -DGENERATOR=<xGenerator> -DWORK_DIR=<dir>
#       [-DFMI_VERSION=3] -P checkReproducible.cmake
# Running the generator again gives the modelDescription.xml (GUID included)
# and documentation/index.html that are inside the FMU, byte for byte: both
# are functions of the variable table only (no date, no path, no build id).
# FMI_VERSION=3: the FMI 3.0 FMU's modelDescription.xml and
# terminalsAndIcons.xml, from `<generator> -fmi3`.
set(files modelDescription.xml documentation/index.html)
set(options)
if(FMI_VERSION STREQUAL "3")
  set(files modelDescription.xml terminalsAndIcons/terminalsAndIcons.xml)
  set(options -fmi3)
endif()
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/packaged ${WORK_DIR}/regenerated)
execute_process(COMMAND ${CMAKE_COMMAND} -E tar xf ${FMU}
  WORKING_DIRECTORY ${WORK_DIR}/packaged RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "cannot extract ${FMU}")
endif()
execute_process(COMMAND ${GENERATOR} ${options} ${WORK_DIR}/regenerated RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "${GENERATOR} failed")
endif()
foreach(file IN LISTS files)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files
      ${WORK_DIR}/packaged/${file} ${WORK_DIR}/regenerated/${file}
    RESULT_VARIABLE different)
  if(different)
    message(FATAL_ERROR "${file} of ${FMU} differs from a new generator run")
  endif()
endforeach()
