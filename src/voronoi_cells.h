/* -*- c++ -*- ----------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   Steve Plimpton, sjplimp@sandia.gov

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   Contributing author: granpen developers
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANPEN package: the Voronoi cell volume of each grain, as a pure kernel
   (no LAMMPS type, no I/O; Voro++). Written once, called by compute
   flow/azimuthal ("voronoi voro++": the owned and ghost atoms of a rank, in
   a non-periodic container around its sub-domain) and by the
   post-processor's analysis/core/voronoi_volumes (a dump frame, periodic
   where the box is).

   A radical (power) tessellation with the grains' radii (Voro++
   container_poly). In a non-periodic direction the container is closed
   1.5 grain diameters (3 largest radii) beyond the outermost grain, but not
   beyond where it was: the open cells of a free surface end there instead
   of at the box top. Inside the bed the cells do not touch the container
   and the volumes are exact. C++11, like the rest of src/.
------------------------------------------------------------------------- */

#ifndef LMP_VORONOI_CELLS_H
#define LMP_VORONOI_CELLS_H

#include <cstddef>

namespace granpen {

struct VoronoiContainer {
  double lo[3], hi[3];
  bool periodic[3];
};

// In each direction with a lid (a free surface: not periodic in the box) and grains
// (amax >= amin), close the container 3 largest radii (rmax) beyond the outermost grain,
// within where it was; a side that would leave no room keeps the container as it was.
void close_container(VoronoiContainer &c, const bool lid[3], const double amin[3], const double amax[3],
                     double rmax);

// Cell volumes of n points at (x[i s], y[i s], z[i s]) (s = stride: 1 for separate
// arrays, 3 for LAMMPS's x[][3]) with radii radius[i]. put (null: all): the points that
// take part; those outside a non-periodic side are left out. wanted (null: all put): the
// points whose cells are computed. volume[i] gets the cell volume (left as it was for the
// others). Returns the number of cells computed.
std::size_t voronoi_cell_volumes(const VoronoiContainer &c, std::size_t n, const double *x, const double *y,
                                 const double *z, std::size_t stride, const double *radius, const char *put,
                                 const char *wanted, double *volume);

}    // namespace granpen

#endif
