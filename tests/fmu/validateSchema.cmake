# cmake -DFMU=<x.fmu> -DSCHEMA_DIR=<dir> -DXMLLINT=<xmllint> -DWORK_DIR=<dir>
#       [-DFMI_VERSION=3] -P validateSchema.cmake
# Validates the modelDescription.xml inside an FMU against the FMI 2.0 XSD
# (<shared>/fmi2-schema), or with FMI_VERSION=3 the modelDescription.xml
# and terminalsAndIcons/terminalsAndIcons.xml against the FMI 3.0 XSD
# (<shared>/fmi3/schema).
if(FMI_VERSION STREQUAL "3")
  set(documents modelDescription.xml fmi3ModelDescription.xsd
      terminalsAndIcons/terminalsAndIcons.xml fmi3TerminalsAndIcons.xsd)
  set(shared fmi3/schema)
else()
  set(documents modelDescription.xml fmi2ModelDescription.xsd)
  set(shared fmi2-schema)
endif()
list(GET documents 1 main)
if(NOT EXISTS ${SCHEMA_DIR}/${main})
  message(FATAL_ERROR
    "FMI schema not found: ${SCHEMA_DIR}/${main}. "
    "The tests expect the shared/ folder beside the repository "
    "(<repo>/../shared/${shared}).")
endif()
if(NOT XMLLINT)
  message(FATAL_ERROR "xmllint not found (Debian package libxml2-utils)")
endif()
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} -E tar xf ${FMU}
  WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE unzipped)
if(NOT unzipped EQUAL 0)
  message(FATAL_ERROR "cannot extract ${FMU}")
endif()
while(documents)
  list(POP_FRONT documents document schema)
  if(NOT EXISTS ${WORK_DIR}/${document})
    message(FATAL_ERROR "${FMU} has no ${document}")
  endif()
  execute_process(
    COMMAND ${XMLLINT} --noout --schema ${SCHEMA_DIR}/${schema}
            ${WORK_DIR}/${document}
    RESULT_VARIABLE valid)
  if(NOT valid EQUAL 0)
    message(FATAL_ERROR "${FMU}: ${document} does not validate (xmllint exit ${valid})")
  endif()
endwhile()
