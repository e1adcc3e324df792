/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: where the rod is in one frame of grains and rod atoms,
   and the bed surface, on plain arrays (no files).
   - find_rod: the rod's atoms (one type): axis = mean x, y of their centres
     (nearest periodic images of the first), tip = lowest z - radius, diameter
     D = 2 max(r_xy + radius): src/rod_shape.h, the kernel fix rod/drive measures
     its rod with;
   - bed_surface: z_s as compute bed/surface and fix rod/drive's surface auto
     define it: the mean over an n x n grid of columns spanning the box of the
     highest grain top (z + radius) in each column (src/bed_surface.h).
   t~ and the other scaling relations: src/scaling_laws.h.
------------------------------------------------------------------------- */

#ifndef GRANPEN_ROD_FRAME_H
#define GRANPEN_ROD_FRAME_H

#include <cstddef>

namespace granpen {

struct RodPosition {
  bool found = false;       // at least one rod atom
  std::size_t atoms = 0;
  double axis_x = 0.0, axis_y = 0.0;
  double tip = 0.0;         // lowest point: min(z - radius)
  double diameter = 0.0;    // 2 max(r_xy + radius) about the axis
};

// Atoms i with type[i] == rod_type (types as stored in a dump: doubles). period_x,
// period_y: box lengths of periodic directions, 0 for non-periodic ones.
RodPosition find_rod(const double *x, const double *y, const double *z, const double *radius,
                     const double *type, std::size_t n, int rod_type, double period_x, double period_y);

// z_s of the grains (i with skip == nullptr or !skip[i]); ncolumns per side over
// [xlo, xhi] x [ylo, yhi]. nempty gets the number of columns without a grain. NaN when
// there is no grain.
double bed_surface(const double *x, const double *y, const double *z, const double *radius,
                   const char *skip, std::size_t n, double xlo, double xhi, double ylo, double yhi,
                   int ncolumns, int &nempty);

}    // namespace granpen

#endif
