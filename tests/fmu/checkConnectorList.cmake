# Every connector is discovered and built: the folders connectors/<name>/
# (all but common/), the connector FMUs CMake configured (CONFIGURED, comma
# separated), the <name>.fmu files in FMU_DIR and the FMI 3.0 FMUs
# FMU_DIR/fmi3/<name>.fmu are the same names.
#   cmake -DSOURCE_DIR=<repository> -DFMU_DIR=<build>/fmus
#         -DCONFIGURED=a,b,... -P checkConnectorList.cmake
foreach(var SOURCE_DIR FMU_DIR CONFIGURED)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "checkConnectorList: -D${var}= is required")
  endif()
endforeach()

file(GLOB entries LIST_DIRECTORIES true RELATIVE ${SOURCE_DIR}/connectors
     ${SOURCE_DIR}/connectors/*)
set(folders)
foreach(entry IN LISTS entries)
  if(IS_DIRECTORY ${SOURCE_DIR}/connectors/${entry}
     AND NOT entry STREQUAL "common")
    list(APPEND folders ${entry})
  endif()
endforeach()

# The FMI 2.0 FMUs <name>.fmu and the FMI 3.0 FMUs fmi3/<name>.fmu
foreach(list built built3)
  set(dir ${FMU_DIR})
  if(list STREQUAL "built3")
    set(dir ${FMU_DIR}/fmi3)
  endif()
  file(GLOB fmuFiles RELATIVE ${dir} ${dir}/*.fmu)
  set(${list})
  foreach(file IN LISTS fmuFiles)
    string(REGEX REPLACE "\\.fmu$" "" name ${file})
    list(APPEND ${list} ${name})
  endforeach()
endforeach()

string(REPLACE "," ";" configured "${CONFIGURED}")
foreach(list folders built built3 configured)
  list(SORT ${list})
endforeach()
message(STATUS "connector folders: ${folders}")
message(STATUS "configured FMUs:   ${configured}")
message(STATUS "built FMUs:        ${built}")
message(STATUS "built FMI 3.0 FMUs: ${built3}")
if(NOT folders STREQUAL configured)
  message(FATAL_ERROR "the connector FMUs CMake configured (${configured}) "
                      "are not the folders of connectors/ (${folders})")
endif()
if(NOT folders STREQUAL built)
  message(FATAL_ERROR "the FMUs in ${FMU_DIR} (${built}) are not the "
                      "folders of connectors/ (${folders})")
endif()
if(NOT folders STREQUAL built3)
  message(FATAL_ERROR "the FMI 3.0 FMUs in ${FMU_DIR}/fmi3 (${built3}) are "
                      "not the folders of connectors/ (${folders})")
endif()
