# The facts about a host LAMMPS given as a CMake build tree (LAMMPS_BUILD_DIR) of a source tree
# (LAMMPS_SOURCE_DIR): its settings from CMakeCache.txt, its compiler from CMakeFiles, its headers
# from <source>/src. Sets the HOST_* variables LAMMPSHost.cmake documents.

if(NOT LAMMPS_SOURCE_DIR)
  message(FATAL_ERROR "cellsph: LAMMPS_BUILD_DIR needs LAMMPS_SOURCE_DIR, the LAMMPS source tree "
    "it was configured from (its src/ holds the headers)")
endif()
if(NOT EXISTS ${LAMMPS_BUILD_DIR}/CMakeCache.txt)
  message(FATAL_ERROR "cellsph: ${LAMMPS_BUILD_DIR} is not a CMake build of LAMMPS (no "
    "CMakeCache.txt); give the folder holding CMakeCache.txt and lmp, or an installed LAMMPS")
endif()
get_filename_component(LAMMPS_BUILD_DIR "${LAMMPS_BUILD_DIR}" ABSOLUTE)
set(HOST_WHERE "the LAMMPS build in ${LAMMPS_BUILD_DIR}")
set(HOST_RECONFIGURE "reconfigure ${LAMMPS_BUILD_DIR} with")
load_cache(${LAMMPS_BUILD_DIR} READ_WITH_PREFIX HOSTC_ BUILD_MPI BUILD_SHARED_LIBS LAMMPS_SIZES
  LAMMPS_EXCEPTIONS PKG_PLUGIN PKG_MOLECULE CMAKE_CXX_COMPILER CMAKE_CXX_STANDARD LAMMPS_MACHINE)

set(HOST_VERSION_NUM "")    # from the headers of the source tree
string(TOUPPER "${HOSTC_LAMMPS_SIZES}" HOST_SIZES)
set(HOST_EXCEPTIONS ${HOSTC_LAMMPS_EXCEPTIONS})
set(HOST_MPI ${HOSTC_BUILD_MPI})
set(HOST_SHARED ${HOSTC_BUILD_SHARED_LIBS})
set(HOST_PACKAGES "")
foreach(_pkg PLUGIN MOLECULE)
  if(HOSTC_PKG_${_pkg})
    list(APPEND HOST_PACKAGES ${_pkg})
  endif()
endforeach()
set(HOST_CXX_STANDARD ${HOSTC_CMAKE_CXX_STANDARD})
set(HOST_COMPILER_PATH ${HOSTC_CMAKE_CXX_COMPILER})
set(HOST_COMPILER_ID "")
set(HOST_COMPILER_MAJOR "")
file(GLOB _hostcompiler ${LAMMPS_BUILD_DIR}/CMakeFiles/*/CMakeCXXCompiler.cmake)
if(_hostcompiler)
  list(GET _hostcompiler 0 _hostcompiler)
  file(STRINGS ${_hostcompiler} _hostid REGEX "set\\(CMAKE_CXX_COMPILER_(ID|VERSION) ")
  string(REGEX MATCH "CMAKE_CXX_COMPILER_ID \"([A-Za-z]+)\"" _m "${_hostid}")
  set(HOST_COMPILER_ID ${CMAKE_MATCH_1})
  string(REGEX MATCH "CMAKE_CXX_COMPILER_VERSION \"([0-9]+)" _m "${_hostid}")
  set(HOST_COMPILER_MAJOR ${CMAKE_MATCH_1})
endif()
set(LAMMPS_EXECUTABLE ${LAMMPS_BUILD_DIR}/lmp)
if(HOSTC_LAMMPS_MACHINE)    # -DLAMMPS_MACHINE=mpi names the executable lmp_mpi
  set(LAMMPS_EXECUTABLE ${LAMMPS_BUILD_DIR}/lmp_${HOSTC_LAMMPS_MACHINE})
endif()
set(LAMMPS_LIBRARY_DIR ${LAMMPS_BUILD_DIR})
set(HOST_HEADER_DIR "")    # LAMMPSHost.cmake takes the source tree's src/
