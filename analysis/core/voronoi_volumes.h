/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: per-grain Voronoi cell volumes of one frame with Voro++,
   for dumps without a Voronoi volume column (e.g. c_vor[1] of compute
   voronoi/atom). Plain arrays in, volumes out; no files.

   The tessellation is the kernel of src/voronoi_cells.h, which compute
   flow/azimuthal's "voronoi voro++" route calls too: a radical (power)
   tessellation with the grains' radii (Voro++ container_poly), periodic where
   the box is, and in a
   non-periodic direction closed 1.5 grain diameters (3 largest radii) beyond
   the outermost grain, but not beyond the box: in a poured bed the floor is
   the box bottom and the lid sits 1.5 d_g above the highest grain, so the open
   cells of the free surface end there instead of at the box top. Inside the
   bed the cells do not touch the container and the volumes are exact.
------------------------------------------------------------------------- */

#ifndef GRANPEN_VORONOI_VOLUMES_H
#define GRANPEN_VORONOI_VOLUMES_H

#include <cstddef>
#include <vector>

namespace granpen {

struct VoronoiBox {
  double lo[3] = {0.0, 0.0, 0.0}, hi[3] = {0.0, 0.0, 0.0};
  bool periodic[3] = {true, true, false};
};

struct VoronoiInfo {
  double lo[3] = {0.0, 0.0, 0.0}, hi[3] = {0.0, 0.0, 0.0};    // the container used
  std::size_t cells = 0;       // cells computed
  std::size_t missing = 0;     // wanted grains without a cell (outside a closed side, or no cell)
};

// Cell volume of each grain i (0 where it has none). wanted: when given (size n), cells
// are computed only for grains with wanted[i] != 0 (all grains are still neighbours).
// Throws std::invalid_argument for an empty or inverted box or non-finite input.
std::vector<double> voronoi_volumes(const double *x, const double *y, const double *z,
                                    const double *radius, std::size_t n, const VoronoiBox &box,
                                    const std::vector<char> *wanted = nullptr,
                                    VoronoiInfo *info = nullptr);

// The same for n grains among m obstacles (the rod's spheres): the obstacles take part in
// the tessellation, so that the grains' cells end at the radical planes to them instead of
// reaching into the rod; only the grains' cells are computed (size n).
std::vector<double> voronoi_volumes_among(const double *x, const double *y, const double *z,
                                          const double *radius, std::size_t n, const double *ox,
                                          const double *oy, const double *oz, const double *oradius,
                                          std::size_t m, const VoronoiBox &box, VoronoiInfo *info = nullptr);

}    // namespace granpen

#endif
