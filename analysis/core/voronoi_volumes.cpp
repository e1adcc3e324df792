/* ----------------------------------------------------------------------
   granpen analysis: Voronoi cell volumes with Voro++ (voronoi_volumes.h).
------------------------------------------------------------------------- */

#include "voronoi_volumes.h"

#include "voronoi_cells.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace granpen {

std::vector<double> voronoi_volumes(const double *x, const double *y, const double *z,
                                    const double *radius, std::size_t n, const VoronoiBox &box,
                                    const std::vector<char> *wanted, VoronoiInfo *info)
{
  for (int d = 0; d < 3; ++d)
    if (!(box.hi[d] > box.lo[d]) || !std::isfinite(box.lo[d]) || !std::isfinite(box.hi[d]))
      throw std::invalid_argument("voronoi_volumes: empty or inverted box in direction " +
                                  std::string(1, "xyz"[d]));
  if (wanted && wanted->size() != n)
    throw std::invalid_argument("voronoi_volumes: wanted has " + std::to_string(wanted->size()) +
                                " entries for " + std::to_string(n) + " grains");
  const double *pos[3] = {x, y, z};
  double amin[3] = {1e300, 1e300, 1e300}, amax[3] = {-1e300, -1e300, -1e300}, rmax = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) {
      if (!std::isfinite(pos[d][i]))
        throw std::invalid_argument("voronoi_volumes: grain " + std::to_string(i) + " has a non-finite position");
      amin[d] = std::min(amin[d], pos[d][i]);
      amax[d] = std::max(amax[d], pos[d][i]);
    }
    if (!(radius[i] >= 0.0) || !std::isfinite(radius[i]))
      throw std::invalid_argument("voronoi_volumes: grain " + std::to_string(i) + " has a bad radius");
    rmax = std::max(rmax, radius[i]);
  }

  // the container: the box where periodic; else closed 3 radii beyond the outermost grain,
  // within the box (the kernel compute flow/azimuthal's voro++ route calls too)
  VoronoiContainer con;
  bool lid[3];
  for (int d = 0; d < 3; ++d) {
    con.lo[d] = box.lo[d], con.hi[d] = box.hi[d];
    con.periodic[d] = box.periodic[d];
    lid[d] = !box.periodic[d];
  }
  if (n > 0) close_container(con, lid, amin, amax, rmax);
  if (info) {
    for (int d = 0; d < 3; ++d) info->lo[d] = con.lo[d], info->hi[d] = con.hi[d];
    info->cells = info->missing = 0;
  }
  std::vector<double> vol(n, 0.0);
  if (n == 0) return vol;
  const std::size_t cells = voronoi_cell_volumes(con, n, x, y, z, 1, radius, nullptr,
                                                 wanted ? wanted->data() : nullptr, vol.data());
  if (info) {
    info->cells = cells;
    std::size_t want = 0;
    for (std::size_t i = 0; i < n; ++i) want += wanted ? ((*wanted)[i] != 0) : 1;
    info->missing = want - cells;
  }
  return vol;
}

std::vector<double> voronoi_volumes_among(const double *x, const double *y, const double *z,
                                          const double *radius, std::size_t n, const double *ox,
                                          const double *oy, const double *oz, const double *oradius,
                                          std::size_t m, const VoronoiBox &box, VoronoiInfo *info)
{
  std::vector<double> X(x, x + n), Y(y, y + n), Z(z, z + n), R(radius, radius + n);
  X.insert(X.end(), ox, ox + m), Y.insert(Y.end(), oy, oy + m), Z.insert(Z.end(), oz, oz + m);
  R.insert(R.end(), oradius, oradius + m);
  std::vector<char> wanted(n + m, 0);
  std::fill(wanted.begin(), wanted.begin() + static_cast<long>(n), 1);
  auto v = voronoi_volumes(X.data(), Y.data(), Z.data(), R.data(), n + m, box, &wanted, info);
  v.resize(n);
  return v;
}

}    // namespace granpen
