# cmake -P checkNoLeftovers.cmake: fails if an importer's unpack directory,
# $TMPDIR/fmuImport-<pid>-XXXXXX or /tmp/fmuImport-<pid>-XXXXXX, was left
# behind by a process that has ended. A directory of a live process is in
# use (another test or program running now) and is not counted, so the
# check holds whatever else runs on the machine. Directories without a
# process id come from importers older than the cleanup at exit and on
# signals, and are not counted either.
set(folders /tmp)
if(DEFINED ENV{TMPDIR} AND NOT "$ENV{TMPDIR}" STREQUAL "")
  list(APPEND folders "$ENV{TMPDIR}")
endif()
list(REMOVE_DUPLICATES folders)

set(leftovers)
foreach(folder ${folders})
  file(GLOB candidates LIST_DIRECTORIES true "${folder}/fmuImport-*-*")
  foreach(candidate ${candidates})
    get_filename_component(name "${candidate}" NAME)
    if(name MATCHES "^fmuImport-([0-9]+)-[A-Za-z0-9]+$" AND NOT EXISTS "/proc/${CMAKE_MATCH_1}")
      list(APPEND leftovers "  ${candidate} (process ${CMAKE_MATCH_1} has ended)")
    endif()
  endforeach()
endforeach()

if(leftovers)
  list(JOIN leftovers "\n" text)
  message(FATAL_ERROR "unpack directories left behind:\n${text}")
endif()
message(STATUS "no unpack directory left behind in ${folders}")
