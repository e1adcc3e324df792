// granpen flow / granpen momentum: shared parts (dump_cmd_common.h).
#include "dump_cmd_common.h"

#include "atomic_file.h"
#include "json_text.h"
#include "text_util.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace granpen {
namespace cli {

namespace fs = std::filesystem;

namespace {
constexpr double PI = 3.14159265358979323846;
}

bool read_rod_options(const ParsedArgs &args, RodOptions &ro, std::string &message)
{
  double v;
  if (args.number("--rod-type", v)) {
    if (v != std::floor(v) || v < 1) {
      message = "--rod-type must be a positive integer";
      return false;
    }
    ro.rod_type = (int) v;
  }
  const auto axis = args.numbers.find("--axis");
  if (axis != args.numbers.end()) ro.have_axis = true, ro.axis_x = axis->second[0], ro.axis_y = axis->second[1];
  if (args.number("--tip", ro.tip)) ro.have_tip = true;
  return true;
}

bool periodic_axes(const std::string &axes, bool &x, bool &y)
{
  if (axes != "xy" && axes != "x" && axes != "y" && axes != "none") return false;
  x = axes == "xy" || axes == "x", y = axes == "xy" || axes == "y";
  return true;
}

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

TraceHeader load_trace(const std::string &path)
{
  TraceHeader h;
  h.trace = read_trace(path);
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

namespace {
void progress_line(const DumpProgress &p, const std::string &tool)
{
  const double mb = (double) p.bytes / 1.0e6;
  const double rate = p.seconds > 0.0 ? mb / p.seconds : 0.0;
  std::fprintf(stderr, "%s: %llu frames, %.1f MB, %.1f MB/s\n", tool.c_str(), (unsigned long long) p.frames, mb, rate);
  std::fflush(stderr);
}
}    // namespace

void report_progress(DumpReader &reader, const std::string &tool)
{
  reader.on_progress([tool](const DumpProgress &p) { progress_line(p, tool); }, 2.0);
}

std::string csv_num(double v) { return std::isfinite(v) ? json_number("%.10g", v) : std::string("nan"); }
std::string js(double v) { return json_number("%.10g", v); }

bool write_outputs(const std::string &dir, const std::vector<std::pair<std::string, std::string>> &files,
                   std::string &message)
{
  try {
    make_output_dir(dir);
    std::vector<std::pair<std::string, std::string>> paths;
    for (const auto &f : files) paths.emplace_back((fs::path(dir) / f.first).string(), f.second);
    write_files_atomic(paths);
  } catch (const OutputError &e) {
    message = e.what();
    return false;
  }
  return true;
}

void refuse_outputs_over_inputs(const std::string &dir, const std::vector<const char *> &names, const ParsedArgs &args)
{
  std::vector<std::string> inputs = args.positional;
  if (args.has("--trace")) inputs.push_back(args.value("--trace", ""));
  for (const char *name : names) refuse_overwriting_inputs((fs::path(dir) / name).string(), "--out", inputs);
}

}    // namespace cli
}    // namespace granpen
