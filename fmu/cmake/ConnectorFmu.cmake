# add_connector_fmu(NAME <modelIdentifier> SOURCES <model sources...>)
#
# Builds one connector FMU from a model source that defines
# fmuExport::createModel(), linked with the law <name>Law where that target
# exists (connectors/CMakeLists.txt):
#   <name>          MODULE library <name>.so (no lib prefix, hidden
#                   visibility; a version script exports the fmi2 functions
#                   and nothing else, the static libraries stay hidden).
#                   Self-contained: libstdc++ and SUNDIALS linked in, so
#                   that it needs only the system's C libraries (libc, libm,
#                   libgcc_s, libpthread) of glibc 2.17 or later
#                   (glibcCompat.c), and runs beside any host's C++ runtime;
#                   its copy of libstdc++ frees its heap when the FMU is
#                   unloaded (staticRuntimeUnload.cpp)
#   <name>Generator writes modelDescription.xml and documentation/index.html
#                   from the model's variable table
#   <name>Fmu       (part of `all`) zips the staging directory
#                   ${CMAKE_BINARY_DIR}/fmuStaging/<name>/ into
#                   ${FOAMFMI_FMU_DIR}/<name>.fmu
#   <name>Fmi3      the FMI 3.0 binary <name>.so: the same model objects
#                   with the fmi3 entry points (fmi3Exports.map), built
#                   like <name>
#   <name>Fmu3      (part of `all`) zips ${CMAKE_BINARY_DIR}/fmuStaging/
#                   fmi3/<name>/ (binaries/x86_64-linux/<name>.so,
#                   modelDescription.xml and terminalsAndIcons/ from
#                   `<name>Generator -fmi3`) into
#                   ${FOAMFMI_FMU_DIR}/fmi3/<name>.fmu
# The name is appended to the global property FOAMFMI_CONNECTOR_FMUS.
# _connector_fmu_binary(<target> <name> <entry points> <version script>
#                       <output directory> <law>): the MODULE <name>.so
# of one FMI version, from <name>Model's objects and the entry points
function(_connector_fmu_binary target name entryPoints exportsMap directory
         law)
  add_library(${target} MODULE
    $<TARGET_OBJECTS:${name}Model>
    $<TARGET_OBJECTS:${entryPoints}>
    ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/glibcCompat.c
    ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/staticRuntimeUnload.cpp)
  # libpthread.so.0 (no linker name since glibc 2.34, hence -l:) is needed
  # although nothing resolves to it here: glibcCompat.c binds pthread_once
  # to the version an older glibc has there only
  target_link_libraries(${target} PRIVATE fmuExport ${law}
    -Wl,--push-state,--no-as-needed -l:libpthread.so.0 -Wl,--pop-state)
  set(exports ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/${exportsMap})
  target_link_options(${target} PRIVATE
    -Wl,--version-script=${exports}
    -Wl,--exclude-libs,ALL -Wl,--no-undefined -Wl,--as-needed
    -static-libstdc++
    -Wl,--wrap=hypot,--wrap=pow,--wrap=getentropy,--wrap=arc4random
    -Wl,--wrap=pthread_once)
  set_target_properties(${target} PROPERTIES
    OUTPUT_NAME ${name}
    PREFIX ""
    SUFFIX ".so"
    LIBRARY_OUTPUT_DIRECTORY ${directory}
    LINK_DEPENDS ${exports}
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
endfunction()

function(add_connector_fmu)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "" "NAME" "SOURCES")
  if(NOT ARG_NAME OR NOT ARG_SOURCES)
    message(FATAL_ERROR "add_connector_fmu: NAME and SOURCES are required")
  endif()
  set(name ${ARG_NAME})
  set(staging ${CMAKE_BINARY_DIR}/fmuStaging/${name})
  set(fmu ${FOAMFMI_FMU_DIR}/${name}.fmu)
  set(staging3 ${CMAKE_BINARY_DIR}/fmuStaging/fmi3/${name})
  set(fmu3 ${FOAMFMI_FMU_DIR}/fmi3/${name}.fmu)

  set(law)
  if(TARGET ${name}Law)
    set(law ${name}Law)
  endif()

  add_library(${name}Model OBJECT ${ARG_SOURCES})
  target_link_libraries(${name}Model PUBLIC fmuExport ${law})
  set_target_properties(${name}Model PROPERTIES
    POSITION_INDEPENDENT_CODE ON
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)

  _connector_fmu_binary(${name} ${name} fmuExportEntryPoints fmi2Exports.map
    ${staging}/binaries/linux64 "${law}")
  add_executable(${name}Generator
    $<TARGET_OBJECTS:${name}Model>
    $<TARGET_OBJECTS:fmuExportGenerator>)
  target_link_libraries(${name}Generator PRIVATE fmuExport ${law})

  add_custom_command(
    OUTPUT ${staging}/modelDescription.xml ${staging}/documentation/index.html
    COMMAND ${name}Generator ${staging}
    DEPENDS ${name}Generator
    COMMENT "Generating modelDescription.xml of ${name}")

  add_custom_command(
    OUTPUT ${fmu}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${FOAMFMI_FMU_DIR}
    COMMAND ${CMAKE_COMMAND} -E rm -f ${fmu}
    COMMAND ${CMAKE_COMMAND} -E tar cf ${fmu} --format=zip
            modelDescription.xml binaries documentation
    WORKING_DIRECTORY ${staging}
    DEPENDS ${name}
            ${staging}/modelDescription.xml
            ${staging}/documentation/index.html
    COMMENT "Packaging ${fmu}")
  add_custom_target(${name}Fmu ALL DEPENDS ${fmu})

  # The FMI 3.0 FMU: the same model objects, the fmi3 entry points
  _connector_fmu_binary(${name}Fmi3 ${name} fmuExportEntryPoints3
    fmi3Exports.map ${staging3}/binaries/x86_64-linux "${law}")
  add_custom_command(
    OUTPUT ${staging3}/modelDescription.xml
           ${staging3}/terminalsAndIcons/terminalsAndIcons.xml
    COMMAND ${name}Generator -fmi3 ${staging3}
    DEPENDS ${name}Generator
    COMMENT "Generating the FMI 3.0 modelDescription.xml of ${name}")
  add_custom_command(
    OUTPUT ${fmu3}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${FOAMFMI_FMU_DIR}/fmi3
    COMMAND ${CMAKE_COMMAND} -E rm -f ${fmu3}
    COMMAND ${CMAKE_COMMAND} -E tar cf ${fmu3} --format=zip
            modelDescription.xml binaries terminalsAndIcons
    WORKING_DIRECTORY ${staging3}
    DEPENDS ${name}Fmi3
            ${staging3}/modelDescription.xml
            ${staging3}/terminalsAndIcons/terminalsAndIcons.xml
    COMMENT "Packaging ${fmu3}")
  add_custom_target(${name}Fmu3 ALL DEPENDS ${fmu3})

  set_property(GLOBAL APPEND PROPERTY FOAMFMI_CONNECTOR_FMUS ${name})
endfunction()
