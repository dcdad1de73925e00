# cmake -DFMU=<x.fmu> -DSCHEMA_DIR=<dir> -DXMLLINT=<xmllint> -DWORK_DIR=<dir>
#       -P validateSchema.cmake
# Validates the modelDescription.xml inside an FMU against the FMI 2.0 XSD.
if(NOT EXISTS ${SCHEMA_DIR}/fmi2ModelDescription.xsd)
  message(FATAL_ERROR
    "FMI 2.0 schema not found: ${SCHEMA_DIR}/fmi2ModelDescription.xsd. "
    "The tests expect the shared/ folder beside the repository "
    "(<repo>/../shared/fmi2-schema).")
endif()
if(NOT XMLLINT)
  message(FATAL_ERROR "xmllint not found (Debian package libxml2-utils)")
endif()
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} -E tar xf ${FMU}
  WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE unzipped)
if(NOT unzipped EQUAL 0 OR NOT EXISTS ${WORK_DIR}/modelDescription.xml)
  message(FATAL_ERROR "cannot extract modelDescription.xml from ${FMU}")
endif()
execute_process(
  COMMAND ${XMLLINT} --noout --schema ${SCHEMA_DIR}/fmi2ModelDescription.xsd
          ${WORK_DIR}/modelDescription.xml
  RESULT_VARIABLE valid)
if(NOT valid EQUAL 0)
  message(FATAL_ERROR "${FMU}: modelDescription.xml does not validate (xmllint exit ${valid})")
endif()
