/* ----------------------------------------------------------------------
   granpen analysis: Voronoi cell volumes with Voro++ (voronoi_volumes.h).
------------------------------------------------------------------------- */

#include "voronoi_volumes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <voro++.hh>

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
  // within the box (compute flow/azimuthal's voro++ route)
  double lo[3], hi[3];
  for (int d = 0; d < 3; ++d) {
    lo[d] = box.lo[d];
    hi[d] = box.hi[d];
    if (!box.periodic[d] && n > 0) {
      lo[d] = std::max(lo[d], amin[d] - 3.0 * rmax);
      hi[d] = std::min(hi[d], amax[d] + 3.0 * rmax);
      if (!(hi[d] > lo[d])) {    // every grain outside the box on this side
        lo[d] = box.lo[d];
        hi[d] = box.hi[d];
      }
    }
  }
  if (info) {
    for (int d = 0; d < 3; ++d) info->lo[d] = lo[d], info->hi[d] = hi[d];
    info->cells = info->missing = 0;
  }
  std::vector<double> vol(n, 0.0);
  if (n == 0) return vol;

  // spatial hash of about 3 grains per block (measured fastest for compute flow/azimuthal)
  const double V = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
  int nb[3];
  for (int d = 0; d < 3; ++d)
    nb[d] = std::max(1, static_cast<int>(std::lround((hi[d] - lo[d]) * std::cbrt((double) n / (V * 3.0)))));
  voro::container_poly con(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2], nb[0], nb[1], nb[2], box.periodic[0],
                           box.periodic[1], box.periodic[2], 8);
  std::vector<char> placed(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    bool inside = true;
    for (int d = 0; d < 3; ++d)
      if (!box.periodic[d] && (pos[d][i] < lo[d] || pos[d][i] > hi[d])) inside = false;
    if (!inside) continue;
    con.put(static_cast<int>(i), x[i], y[i], z[i], radius[i]);    // periodic: wrapped by Voro++
    placed[i] = 1;
  }
  voro::c_loop_all loop(con);
  voro::voronoicell cell;
  std::size_t cells = 0;
  if (loop.start()) do {
      const std::size_t i = (std::size_t) loop.pid();
      if (wanted && !(*wanted)[i]) continue;
      if (con.compute_cell(cell, loop)) {
        vol[i] = cell.volume();
        ++cells;
      }
    } while (loop.inc());
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
