# Describe the host LAMMPS the plugin is built for, as an INTERFACE target `lammps_host`.
# Everything that changes the binary interface is taken from the host, never guessed: version,
# MPI or STUBS, integer sizes, exceptions, C++ standard, compiler. The host is either
#   a CMake build tree  LAMMPS_BUILD_DIR (+ LAMMPS_SOURCE_DIR)   LAMMPSFromBuildTree.cmake
#   an installed LAMMPS find_package(LAMMPS) or liblammps.pc     LAMMPSFromInstall.cmake
# Each reader sets HOST_WHERE (for messages), HOST_RECONFIGURE, HOST_VERSION_NUM (YYYYMMDD, or
# empty: from the headers), HOST_SIZES, HOST_EXCEPTIONS, HOST_MPI, HOST_SHARED, HOST_PACKAGES
# (list, or "unknown"), HOST_CXX_STANDARD, HOST_COMPILER_ID/_MAJOR/_PATH (empty: unknown),
# HOST_HEADER_DIR (installed headers, empty if none), LAMMPS_EXECUTABLE and LAMMPS_LIBRARY_DIR.
# The headers are the install's when it has all the plugin includes, else those of the source
# tree LAMMPS_SOURCE_DIR (29 Sep 2021 installs 34 headers, without version.h, neigh_request.h
# or fmt/), whose version must then be the host's.
# Hosts that cannot load plugins are refused here with the reason.

if(LAMMPS_BUILD_DIR)
  include(LAMMPSFromBuildTree)
else()
  include(LAMMPSFromInstall)
endif()

# --- headers -----------------------------------------------------------------------------------
# the LAMMPS headers cellsph includes (every quoted include that is not one of its own files),
# and fmt/, which pointers.h and utils.h include
file(GLOB _own RELATIVE ${CMAKE_CURRENT_SOURCE_DIR}/src ${CMAKE_CURRENT_SOURCE_DIR}/src/*)
file(GLOB _sources ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp ${CMAKE_CURRENT_SOURCE_DIR}/src/*.h)
set(_needed fmt/format.h)
foreach(_src ${_sources})
  file(STRINGS ${_src} _lines REGEX "^#include \"")
  foreach(_line ${_lines})
    string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" _h "${_line}")
    if(NOT _h IN_LIST _own)
      list(APPEND _needed ${_h})
    endif()
  endforeach()
endforeach()
list(REMOVE_DUPLICATES _needed)
set(_missing "")
foreach(_h ${_needed})
  if(NOT HOST_HEADER_DIR OR NOT EXISTS ${HOST_HEADER_DIR}/${_h})
    list(APPEND _missing ${_h})
  endif()
endforeach()

if(NOT _missing)
  set(LAMMPS_HEADER_DIR ${HOST_HEADER_DIR})
else()
  if(NOT LAMMPS_SOURCE_DIR)
    string(REPLACE ";" " " _missing "${_missing}")
    message(FATAL_ERROR "cellsph: ${HOST_WHERE} lacks headers the plugin includes (${_missing}); "
      "give -DLAMMPS_SOURCE_DIR=<the LAMMPS source tree of the same version>")
  endif()
  get_filename_component(LAMMPS_SOURCE_DIR "${LAMMPS_SOURCE_DIR}" ABSOLUTE)
  if(EXISTS ${LAMMPS_SOURCE_DIR}/version.h AND NOT EXISTS ${LAMMPS_SOURCE_DIR}/src/version.h)
    get_filename_component(LAMMPS_SOURCE_DIR "${LAMMPS_SOURCE_DIR}/.." ABSOLUTE)
  endif()
  set(LAMMPS_HEADER_DIR ${LAMMPS_SOURCE_DIR}/src)
  if(NOT EXISTS ${LAMMPS_HEADER_DIR}/version.h)
    message(FATAL_ERROR "cellsph: ${LAMMPS_SOURCE_DIR} is not a LAMMPS source tree (no src/version.h)")
  endif()
endif()

# version "29 Sep 2021" -> 20210929, the number LAMMPS itself reports as lmp->num_ver
file(STRINGS ${LAMMPS_HEADER_DIR}/version.h _ver REGEX "^#define LAMMPS_VERSION ")
string(REGEX REPLACE ".*\"([0-9]+) ([A-Za-z]+) ([0-9]+)\".*" "\\1;\\2;\\3" _ver "${_ver}")
list(GET _ver 0 _day)
list(GET _ver 1 _mon)
list(GET _ver 2 _year)
set(_months Jan Feb Mar Apr May Jun Jul Aug Sep Oct Nov Dec)
list(FIND _months ${_mon} _imon)
math(EXPR _imon "${_imon} + 1")
math(EXPR LMP_VERSION_NUM "${_year} * 10000 + ${_imon} * 100 + ${_day}")
set(LMP_VERSION_STRING "${_day} ${_mon} ${_year}")
if(HOST_VERSION_NUM MATCHES "^[0-9]+$" AND NOT HOST_VERSION_NUM EQUAL LMP_VERSION_NUM)
  message(FATAL_ERROR "cellsph: ${HOST_WHERE} is LAMMPS ${HOST_VERSION_NUM}, but the headers in "
    "${LAMMPS_HEADER_DIR} are of ${LMP_VERSION_NUM}; give the source tree of ${HOST_VERSION_NUM}")
endif()
message(STATUS "cellsph: LAMMPS ${LMP_VERSION_STRING} (${LMP_VERSION_NUM}): ${HOST_WHERE}, "
  "headers in ${LAMMPS_HEADER_DIR}")

# --- can it load this plugin? ------------------------------------------------------------------
if(NOT HOST_PACKAGES STREQUAL "unknown")
  if(NOT PLUGIN IN_LIST HOST_PACKAGES)
    message(FATAL_ERROR "cellsph: ${HOST_WHERE} has no PLUGIN package; "
      "${HOST_RECONFIGURE} -DPKG_PLUGIN=on")
  endif()
  if(NOT MOLECULE IN_LIST HOST_PACKAGES)
    message(FATAL_ERROR "cellsph: ${HOST_WHERE} has no MOLECULE package (needed for bonded cell "
      "walls); ${HOST_RECONFIGURE} -DPKG_MOLECULE=on")
  endif()
endif()
# until lmp exported its symbols (2022), plugins load only into a shared-library build; an install
# without the source tree is of a later release (earlier ones lack headers it needs)
if(NOT HOST_SHARED AND LAMMPS_SOURCE_DIR AND EXISTS ${LAMMPS_SOURCE_DIR}/cmake/CMakeLists.txt)
  file(STRINGS ${LAMMPS_SOURCE_DIR}/cmake/CMakeLists.txt _exports REGEX "ENABLE_EXPORTS")
  if(NOT _exports)
    message(FATAL_ERROR "cellsph: LAMMPS ${LMP_VERSION_STRING} loads plugins only when built as a "
      "shared library; ${HOST_RECONFIGURE} -DBUILD_SHARED_LIBS=on")
  endif()
endif()

# the C++ standard of the host: as reported, else from its CMakeLists; never below C++17
set(_std ${HOST_CXX_STANDARD})
if(NOT _std AND LAMMPS_SOURCE_DIR AND EXISTS ${LAMMPS_SOURCE_DIR}/cmake/CMakeLists.txt)
  file(STRINGS ${LAMMPS_SOURCE_DIR}/cmake/CMakeLists.txt _stdline REGEX "set\\(CMAKE_CXX_STANDARD [0-9]+\\)")
  string(REGEX MATCH "[0-9]+" _std "${_stdline}")
endif()
set(CELLSPH_CXX_STANDARD 17)
if(_std AND _std GREATER 17)
  set(CELLSPH_CXX_STANDARD ${_std})
endif()
message(STATUS "cellsph: host C++${_std}, plugin C++${CELLSPH_CXX_STANDARD} (same libstdc++ ABI)")

# the same compiler family and major version as the host (libstdc++ ABI)
if(HOST_COMPILER_ID)
  string(REGEX MATCH "^[0-9]+" _cmajor "${CMAKE_CXX_COMPILER_VERSION}")
  if(NOT HOST_COMPILER_ID STREQUAL CMAKE_CXX_COMPILER_ID OR NOT HOST_COMPILER_MAJOR STREQUAL _cmajor)
    set(_hint "")
    if(HOST_COMPILER_PATH)
      set(_hint "; use -DCMAKE_CXX_COMPILER=${HOST_COMPILER_PATH}")
    endif()
    message(FATAL_ERROR "cellsph: LAMMPS was built with ${HOST_COMPILER_ID} ${HOST_COMPILER_MAJOR}, "
      "this is ${CMAKE_CXX_COMPILER_ID} ${_cmajor}${_hint}")
  endif()
endif()

# --- the interface target ----------------------------------------------------------------------
add_library(lammps_host INTERFACE)
target_include_directories(lammps_host INTERFACE ${LAMMPS_HEADER_DIR})
if(NOT HOST_SIZES)
  set(HOST_SIZES SMALLBIG)
endif()
target_compile_definitions(lammps_host INTERFACE LAMMPS_${HOST_SIZES} LMP_VERSION_NUM=${LMP_VERSION_NUM})
if(HOST_EXCEPTIONS)
  target_compile_definitions(lammps_host INTERFACE LAMMPS_EXCEPTIONS)
endif()
if(HOST_MPI)
  set(MPI_CXX_SKIP_MPICXX ON)
  find_package(MPI REQUIRED COMPONENTS CXX)
  target_link_libraries(lammps_host INTERFACE MPI::MPI_CXX)
  set(CELLSPH_HOST_MPI ON)
else()
  target_include_directories(lammps_host INTERFACE ${LAMMPS_HEADER_DIR}/STUBS)
  set(CELLSPH_HOST_MPI OFF)
endif()
target_link_options(lammps_host INTERFACE -rdynamic)
message(STATUS "cellsph: LAMMPS_${HOST_SIZES}, exceptions ${HOST_EXCEPTIONS}, MPI ${HOST_MPI}, "
  "shared library ${HOST_SHARED}; runs ${LAMMPS_EXECUTABLE}")
