# cmake -DFMU=<x.fmu> -DNAME=<modelIdentifier> -DWORK_DIR=<dir>
#       -DMAX_GLIBC=<2.xx> [-DFMI_VERSION=3] -P checkBinary.cmake
# The binary of an FMU exports exactly the 44 fmi2 functions of the standard
# (FMI_VERSION=3: the 75 fmi3 functions, binaries/x86_64-linux/) and is
# self-contained: it needs only the C libraries every Linux x86-64
# system has (no libstdc++, no SUNDIALS), of glibc MAX_GLIBC at most, and
# loads with nothing else on the library path.
cmake_minimum_required(VERSION 3.25)
if(FMI_VERSION STREQUAL "3")
  set(prefix fmi3)
  set(functions 75)
  set(platform x86_64-linux)
  set(version 3.0)
else()
  set(prefix fmi2)
  set(functions 44)
  set(platform linux64)
  set(version 2.0)
endif()
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} -E tar xf ${FMU} WORKING_DIRECTORY ${WORK_DIR})
set(so ${WORK_DIR}/binaries/${platform}/${NAME}.so)
if(NOT EXISTS ${so})
  message(FATAL_ERROR "${FMU} has no binaries/${platform}/${NAME}.so")
endif()

execute_process(COMMAND nm -D --defined-only --format=posix ${so}
  OUTPUT_VARIABLE symbols RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "nm failed on ${so}")
endif()
string(REGEX MATCHALL "[^\n]+" lines "${symbols}")
set(count 0)
foreach(line IN LISTS lines)
  string(REGEX REPLACE " .*" "" symbol "${line}")
  if(NOT symbol MATCHES "^${prefix}[A-Za-z0-9]+$")
    message(FATAL_ERROR "${so} exports ${symbol}: only ${prefix} functions may be visible")
  endif()
  math(EXPR count "${count} + 1")
endforeach()
if(NOT count EQUAL functions)
  message(FATAL_ERROR "${so} exports ${count} ${prefix} functions, FMI ${version} has ${functions}")
endif()

execute_process(COMMAND ldd ${so} OUTPUT_VARIABLE deps RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "ldd failed on ${so}")
endif()
string(REGEX MATCHALL "[^\n]+" lines "${deps}")
foreach(line IN LISTS lines)
  if(line MATCHES "not found")
    message(FATAL_ERROR "${so}: missing dependency: ${line}")
  endif()
  if(line MATCHES "=> ([^ ]+)" AND NOT CMAKE_MATCH_1 MATCHES "^/(usr/)?lib(64|32|x32)?/")
    message(FATAL_ERROR "${so} depends on a non-system library: ${line}")
  endif()
endforeach()
message(STATUS "${so}: ${count} ${prefix} symbols exported, system libraries only")

# Only the C libraries: libstdc++ and SUNDIALS are linked in. libgcc_s
# (the unwinder) is part of every glibc system: glibc loads it itself.
set(allowed libc.so.6 libm.so.6 libdl.so.2 libpthread.so.0 libgcc_s.so.1
            ld-linux-x86-64.so.2)
execute_process(COMMAND readelf -d ${so} OUTPUT_VARIABLE dynamic RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "readelf failed on ${so}")
endif()
string(REGEX MATCHALL "NEEDED\\)[^[]*\\[([^]]+)\\]" entries "${dynamic}")
foreach(entry IN LISTS entries)
  string(REGEX REPLACE ".*\\[([^]]+)\\]" "\\1" library "${entry}")
  if(NOT library IN_LIST allowed)
    message(FATAL_ERROR "${so} needs ${library}; an FMU binary may need only ${allowed}")
  endif()
endforeach()

# The lowest glibc it runs on: the highest symbol version it asks for
execute_process(COMMAND objdump -T ${so} OUTPUT_VARIABLE imports RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "objdump failed on ${so}")
endif()
string(REGEX MATCHALL "(GLIBCXX|CXXABI)_[0-9.]+" cxx "${imports}")
if(cxx)
  list(REMOVE_DUPLICATES cxx)
  message(FATAL_ERROR "${so} asks for the C++ runtime's ${cxx}: libstdc++ must be linked in")
endif()
string(REGEX MATCHALL "GLIBC_[0-9.]+" versions "${imports}")
set(highest 0)
foreach(version IN LISTS versions)
  string(REPLACE "GLIBC_" "" version "${version}")
  if(version VERSION_GREATER highest)
    set(highest ${version})
  endif()
endforeach()
if(highest VERSION_GREATER MAX_GLIBC)
  message(FATAL_ERROR "${so} needs glibc ${highest}; the FMUs promise ${MAX_GLIBC} (fmu/cmake/glibcCompat.c)")
endif()

# Loads, and its fmi2GetVersion (fmi3GetVersion) answers, with an empty library path and
# neither libstdc++ nor SUNDIALS mapped into the process
set(probe "import ctypes, sys
lib = ctypes.CDLL(sys.argv[1])
getVersion = getattr(lib, sys.argv[2] + 'GetVersion')
getVersion.restype = ctypes.c_char_p
version = getVersion().decode()
maps = open('/proc/self/maps').read()
foreign = [name for name in ('libstdc++', 'libsundials') if name in maps]
print(version, foreign)
sys.exit(1 if version != sys.argv[3] or foreign else 0)")
execute_process(COMMAND ${CMAKE_COMMAND} -E env LD_LIBRARY_PATH= python3 -c "${probe}" ${so} ${prefix} ${version}
  OUTPUT_VARIABLE loaded ERROR_VARIABLE loadError RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "${so} does not load on its own: ${loaded}${loadError}")
endif()
message(STATUS "${so}: needs glibc ${highest} (promised ${MAX_GLIBC}), C libraries only; loaded alone: ${loaded}")
