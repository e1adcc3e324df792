# LAMMPS's CMake module for the GRANPEN package (cmake/Modules/Packages/GRANPEN.cmake in a
# LAMMPS tree; GRANPEN added to the PKG_WITH_INCL list of cmake/CMakeLists.txt includes it).
# compute flow/azimuthal computes Voronoi cells with Voro++, which LAMMPS finds, or downloads,
# and links for its VORONOI package: GRANPEN needs that package, and says so at configure
# time rather than with a missing <voro++.hh> in the middle of the build.
if(NOT PKG_VORONOI)
  message(FATAL_ERROR "The GRANPEN package needs the VORONOI package (Voro++ for compute "
    "flow/azimuthal): add -D PKG_VORONOI=on")
endif()
