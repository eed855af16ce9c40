# Describe the host LAMMPS the plugin is built for, as an INTERFACE target `lammps_host`.
# Everything that changes the binary interface is taken from the host build, never guessed:
# version (src/version.h), MPI or STUBS, integer sizes, exceptions, C++ standard, compiler.
# Hosts that cannot load plugins are refused here with the reason.

if(NOT LAMMPS_SOURCE_DIR)
  message(FATAL_ERROR "cellsph: set LAMMPS_SOURCE_DIR to a LAMMPS source tree (or run tools/setup.sh)")
endif()
get_filename_component(LAMMPS_SOURCE_DIR "${LAMMPS_SOURCE_DIR}" ABSOLUTE)
if(EXISTS ${LAMMPS_SOURCE_DIR}/version.h AND NOT EXISTS ${LAMMPS_SOURCE_DIR}/src/version.h)
  get_filename_component(LAMMPS_SOURCE_DIR "${LAMMPS_SOURCE_DIR}/.." ABSOLUTE)
endif()
set(LAMMPS_HEADER_DIR ${LAMMPS_SOURCE_DIR}/src)
if(NOT EXISTS ${LAMMPS_HEADER_DIR}/version.h)
  message(FATAL_ERROR "cellsph: ${LAMMPS_SOURCE_DIR} is not a LAMMPS source tree (no src/version.h)")
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
message(STATUS "cellsph: LAMMPS ${LMP_VERSION_STRING} (${LMP_VERSION_NUM}) in ${LAMMPS_SOURCE_DIR}")

if(NOT LAMMPS_BUILD_DIR OR NOT EXISTS ${LAMMPS_BUILD_DIR}/CMakeCache.txt)
  message(FATAL_ERROR "cellsph: set LAMMPS_BUILD_DIR to the CMake build of ${LAMMPS_SOURCE_DIR} "
    "(the folder with CMakeCache.txt and lmp); its settings decide how the plugin is compiled")
endif()
get_filename_component(LAMMPS_BUILD_DIR "${LAMMPS_BUILD_DIR}" ABSOLUTE)
load_cache(${LAMMPS_BUILD_DIR} READ_WITH_PREFIX HOST_ BUILD_MPI BUILD_SHARED_LIBS LAMMPS_SIZES
  LAMMPS_EXCEPTIONS PKG_PLUGIN PKG_MOLECULE CMAKE_CXX_COMPILER CMAKE_CXX_STANDARD)

if(NOT HOST_PKG_PLUGIN)
  message(FATAL_ERROR "cellsph: the LAMMPS build in ${LAMMPS_BUILD_DIR} has no PLUGIN package; "
    "reconfigure it with -DPKG_PLUGIN=on")
endif()
if(NOT HOST_PKG_MOLECULE)
  message(FATAL_ERROR "cellsph: the LAMMPS build in ${LAMMPS_BUILD_DIR} has no MOLECULE package "
    "(needed for bonded cell walls); reconfigure it with -DPKG_MOLECULE=on")
endif()
# until lmp exported its symbols (2022), plugins load only into a shared-library build
file(STRINGS ${LAMMPS_SOURCE_DIR}/cmake/CMakeLists.txt _exports REGEX "ENABLE_EXPORTS")
if(NOT _exports AND NOT HOST_BUILD_SHARED_LIBS)
  message(FATAL_ERROR "cellsph: LAMMPS ${LMP_VERSION_STRING} loads plugins only when built as a "
    "shared library; reconfigure ${LAMMPS_BUILD_DIR} with -DBUILD_SHARED_LIBS=on")
endif()

# the C++ standard of the host: from its cache, else from its CMakeLists; never below C++17
set(_std ${HOST_CMAKE_CXX_STANDARD})
if(NOT _std)
  file(STRINGS ${LAMMPS_SOURCE_DIR}/cmake/CMakeLists.txt _stdline REGEX "set\\(CMAKE_CXX_STANDARD [0-9]+\\)")
  string(REGEX MATCH "[0-9]+" _std "${_stdline}")
endif()
set(CELLSPH_CXX_STANDARD 17)
if(_std AND _std GREATER 17)
  set(CELLSPH_CXX_STANDARD ${_std})
endif()
message(STATUS "cellsph: host C++${_std}, plugin C++${CELLSPH_CXX_STANDARD} (same libstdc++ ABI)")

# the same compiler family and major version as the host (libstdc++ ABI)
if(HOST_CMAKE_CXX_COMPILER AND EXISTS ${LAMMPS_BUILD_DIR}/CMakeFiles)
  file(GLOB _hostcompiler ${LAMMPS_BUILD_DIR}/CMakeFiles/*/CMakeCXXCompiler.cmake)
  if(_hostcompiler)
    list(GET _hostcompiler 0 _hostcompiler)
    file(STRINGS ${_hostcompiler} _hostid REGEX "set\\(CMAKE_CXX_COMPILER_(ID|VERSION) ")
    string(REGEX MATCH "CMAKE_CXX_COMPILER_ID \"([A-Za-z]+)\"" _m "${_hostid}")
    set(_host_cid ${CMAKE_MATCH_1})
    string(REGEX MATCH "CMAKE_CXX_COMPILER_VERSION \"([0-9]+)" _m "${_hostid}")
    set(_host_cmajor ${CMAKE_MATCH_1})
    string(REGEX MATCH "^[0-9]+" _cmajor "${CMAKE_CXX_COMPILER_VERSION}")
    if(NOT _host_cid STREQUAL CMAKE_CXX_COMPILER_ID OR NOT _host_cmajor STREQUAL _cmajor)
      message(FATAL_ERROR "cellsph: LAMMPS was built with ${_host_cid} ${_host_cmajor}, this is "
        "${CMAKE_CXX_COMPILER_ID} ${_cmajor}; use -DCMAKE_CXX_COMPILER=${HOST_CMAKE_CXX_COMPILER}")
    endif()
  endif()
endif()

add_library(lammps_host INTERFACE)
target_include_directories(lammps_host INTERFACE ${LAMMPS_HEADER_DIR})
string(TOUPPER "${HOST_LAMMPS_SIZES}" _sizes)
if(NOT _sizes)
  set(_sizes SMALLBIG)
endif()
target_compile_definitions(lammps_host INTERFACE LAMMPS_${_sizes} LMP_VERSION_NUM=${LMP_VERSION_NUM})
if(HOST_LAMMPS_EXCEPTIONS)
  target_compile_definitions(lammps_host INTERFACE LAMMPS_EXCEPTIONS)
endif()
if(HOST_BUILD_MPI)
  set(MPI_CXX_SKIP_MPICXX ON)
  find_package(MPI REQUIRED COMPONENTS CXX)
  target_link_libraries(lammps_host INTERFACE MPI::MPI_CXX)
  set(CELLSPH_HOST_MPI ON)
else()
  target_include_directories(lammps_host INTERFACE ${LAMMPS_HEADER_DIR}/STUBS)
  set(CELLSPH_HOST_MPI OFF)
endif()
target_link_options(lammps_host INTERFACE -rdynamic)
