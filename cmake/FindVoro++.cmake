# FindVoro++: Debian's voro++-dev ships a static libvoro++.a and headers in
# /usr/include/voro++ with no CMake or pkg-config file.
#   Voro++_FOUND, Voro++_INCLUDE_DIRS, Voro++_LIBRARIES, target Voro++::Voro++
find_path(Voro++_INCLUDE_DIR voro++.hh PATH_SUFFIXES voro++)
find_library(Voro++_LIBRARY NAMES voro++)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Voro++ REQUIRED_VARS Voro++_LIBRARY Voro++_INCLUDE_DIR)
if(Voro++_FOUND)
  set(Voro++_INCLUDE_DIRS ${Voro++_INCLUDE_DIR})
  set(Voro++_LIBRARIES ${Voro++_LIBRARY})
  if(NOT TARGET Voro++::Voro++)
    add_library(Voro++::Voro++ UNKNOWN IMPORTED)
    set_target_properties(Voro++::Voro++ PROPERTIES
      IMPORTED_LOCATION "${Voro++_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${Voro++_INCLUDE_DIR}")
  endif()
endif()
mark_as_advanced(Voro++_INCLUDE_DIR Voro++_LIBRARY)
