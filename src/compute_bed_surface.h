/* -*- c++ -*- ----------------------------------------------------------
   GRANPEN package: compute bed/surface
   Bed surface height z_s and packing fraction phi_0 of a poured bed.
   See docs/compute_bed_surface.rst.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(bed/surface,ComputeBedSurface);
// clang-format on
#else

#ifndef LMP_COMPUTE_BED_SURFACE_H
#define LMP_COMPUTE_BED_SURFACE_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputeBedSurface : public Compute {
 public:
  ComputeBedSurface(class LAMMPS *, int, char **);
  ~ComputeBedSurface() override;
  void init() override {}
  void compute_vector() override;

 private:
  int ngrid;
  double floor_z;
};

}    // namespace LAMMPS_NS

#endif
#endif
