// granpen analysis: dump frames as arrays and a push's trace values (see dump_frames.h).
#include "dump_frames.h"

#include "json_text.h"
#include "text_util.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace granpen {

namespace {

constexpr double PI = 3.14159265358979323846;

// s as a whole finite number (strtod; trailing text, overflow or underflow: false)
bool number_arg(const std::string &s, double &v)
{
  char *end = nullptr;
  errno = 0;
  v = std::strtod(s.c_str(), &end);
  return !s.empty() && end && *end == '\0' && errno != ERANGE && std::isfinite(v);
}

}    // namespace

GrainArrays GrainFrame::arrays() const
{
  GrainArrays a;
  a.n = x.size();
  a.x = x.data(), a.y = y.data(), a.z = z.data();
  a.vx = vx.data(), a.vy = vy.data(), a.vz = vz.data();
  a.radius = radius.data(), a.mass = mass.data();
  if (have_vor) a.voronoi = vor.data();
  if (have_stress) a.sxx = sxx.data(), a.syy = syy.data(), a.szz = szz.data();
  return a;
}

void extract_frame(const DumpFrame &f, const RodOptions &ro, const ColumnChoice &cols, double rho,
                   bool periodic_x, bool periodic_y, GrainFrame &g)
{
  g.where = file_line(f.file, f.line);
  g.timestep = f.timestep;
  for (int d = 0; d < 3; ++d) g.lo[d] = f.lo[d], g.hi[d] = f.hi[d];
  g.period_x = periodic_x ? f.hi[0] - f.lo[0] : 0.0;
  g.period_y = periodic_y ? f.hi[1] - f.lo[1] : 0.0;
  const auto &type = f.col("type");
  const auto &X = f.col("x"), &Y = f.col("y"), &Z = f.col("z");
  const auto &VX = f.col("vx"), &VY = f.col("vy"), &VZ = f.col("vz");
  const auto &R = f.col("radius");
  const std::vector<double> *M = cols.mass ? &f.col("mass") : nullptr;
  const std::vector<double> *V = cols.voronoi.empty() ? nullptr : &f.col(cols.voronoi);
  const std::vector<double> *S[3] = {nullptr, nullptr, nullptr};
  if (!cols.stress[0].empty())
    for (int k = 0; k < 3; ++k) S[k] = &f.col(cols.stress[k]);
  const std::size_t n = f.natoms();

  g.rod = find_rod(X.data(), Y.data(), Z.data(), R.data(), type.data(), n, ro.rod_type, g.period_x, g.period_y);
  if (!g.rod.found && !(ro.have_axis && ro.have_tip))
    throw InputError(g.where + ": frame (timestep " + std::to_string(f.timestep) + ") has no atoms of rod type " +
                     std::to_string(ro.rod_type) + "; give --rod-type, or --axis X Y and --tip Z");
  g.axis_x = ro.have_axis ? ro.axis_x : g.rod.axis_x;
  g.axis_y = ro.have_axis ? ro.axis_y : g.rod.axis_y;
  g.tip = ro.have_tip ? ro.tip : g.rod.tip;

  for (auto *v : {&g.x, &g.y, &g.z, &g.vx, &g.vy, &g.vz, &g.radius, &g.mass, &g.vor, &g.sxx, &g.syy, &g.szz,
                  &g.rod_x, &g.rod_y, &g.rod_z, &g.rod_radius})
    v->clear();
  g.is_rod.assign(n, 0);
  g.have_vor = V != nullptr;
  g.have_stress = S[0] != nullptr;
  for (std::size_t i = 0; i < n; ++i) {
    if (std::lround(type[i]) == ro.rod_type) {
      g.is_rod[i] = 1;
      g.rod_x.push_back(X[i]), g.rod_y.push_back(Y[i]), g.rod_z.push_back(Z[i]), g.rod_radius.push_back(R[i]);
      continue;
    }
    if (!(R[i] > 0.0))
      throw InputError(g.where + ": atom " + std::to_string(i + 1) + " of the frame has radius " +
                       json_number("%g", R[i]) + " (grains need a positive radius)");
    g.x.push_back(X[i]), g.y.push_back(Y[i]), g.z.push_back(Z[i]);
    g.vx.push_back(VX[i]), g.vy.push_back(VY[i]), g.vz.push_back(VZ[i]);
    g.radius.push_back(R[i]);
    g.mass.push_back(M ? (*M)[i] : rho * 4.0 / 3.0 * PI * R[i] * R[i] * R[i]);
    if (V) g.vor.push_back((*V)[i]);
    if (S[0]) g.sxx.push_back((*S[0])[i]), g.syy.push_back((*S[1])[i]), g.szz.push_back((*S[2])[i]);
  }
}

PushTrace load_push_trace(const std::string &path)
{
  PushTrace h;
  h.trace = read_trace(path);
  require_t(h.trace, "--trace (the push's time against the dump's steps)");
  h.present = true;
  auto get = [&](const char *key, bool &have, double &v) {
    auto it = h.trace.keys.find(key);
    if (it == h.trace.keys.end()) return;
    if (!number_arg(it->second, v))
      throw InputError(path + ": header key " + key + " = '" + it->second + "' is not a number");
    have = true;
  };
  get("d_g", h.have_dg, h.d_g);
  get("rho_g", h.have_rho, h.rho_g);
  get("mu", h.have_mu, h.mu);
  get("surface", h.have_surface, h.surface);
  get("dt", h.have_dt, h.dt);
  return h;
}

}    // namespace granpen
