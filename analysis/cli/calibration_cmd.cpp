// granpen calibration SWEEP_DIR: the friction-calibration table of a sweep folder,
// phi_0 and k_z against mu (core/calibration.h, core/trace_fit.h, io/bed_info.h).
#include "args.h"
#include "json_text.h"
#include "bed_info.h"
#include "calibration.h"
#include "subcommands.h"
#include "trace_fit.h"
#include "trace_reader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

using granpen::json_number;
using granpen::json_string;

namespace {

namespace fs = std::filesystem;
using granpen::CalibrationRow;

const char *HELP =
    "usage: granpen calibration SWEEP_DIR [--zmin Z] [--zmax Z] [--out DIR]\n"
    "Summarises a friction-calibration sweep (the paper's Simulation Calibration: mu sets\n"
    "the packing fraction phi_0 of the poured bed, and mu and phi_0 set k_z). SWEEP_DIR holds\n"
    "  beds/NAME.info    written by inputs/in.pour (keys mu, seed, phi_0, z_s, ...)\n"
    "  traces/*.csv      granpen-trace v1 pushes whose headers carry mu, seed, v0 and\n"
    "                    bed = NAME (mu and seed default to the bed's)\n"
    "For each mu (and v0): phi_0 mean and sd over its beds; k_z (slope of F on z over the\n"
    "window, as granpen fit) and alpha = k_z / (mu rho_g g D^2) mean and sd over its pushes.\n"
    "sd is the sample standard deviation (n - 1); with one value it is 0.\n"
    "options:\n"
    "  --zmin Z   window start, cm (default 1.0)\n"
    "  --zmax Z   window end, cm (default 3.0). The defaults are the bench scenario's usable\n"
    "             depths: its bed is about 5.7 cm deep and the push goes to 4 cm, so the last\n"
    "             centimetre feels the floor, and the first grows through the impact peak.\n"
    "             The paper fits z >= 3 cm in a 13.5 cm bed: widen the window for deeper beds.\n"
    "  --out DIR  where to write (default SWEEP_DIR): calibration.csv, calibration.json,\n"
    "             calibration.md, and with gnuplot calibration_phi0.png, calibration_kz.png\n"
    "             (from calibration.gp, written beside them)\n"
    "Exit status: 0 when every bed and trace was used, 1 when one was rejected or could not\n"
    "be fitted (the tables are still written from the rest), 2 for a usage error.\n";


std::string num(double v) { return granpen::json_number("%.10g", v); }


std::string csv_field(const std::string &s)
{
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string o = "\"";
  for (char c : s) o += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return o + "\"";
}

// markdown cell text: no pipes or line breaks
std::string md_cell(std::string s)
{
  for (char &c : s)
    if (c == '|' || c == '\n' || c == '\r') c = ' ';
  return s;
}

std::vector<std::string> files_with(const fs::path &dir, const std::string &ext, std::string &err)
{
  std::vector<std::string> out;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    err = dir.string() + ": no such folder";
    return out;
  }
  for (const auto &e : fs::directory_iterator(dir, ec))
    if (e.path().extension() == ext && e.is_regular_file(ec)) out.push_back(e.path().string());
  if (ec) err = dir.string() + ": cannot list folder: " + ec.message();
  std::sort(out.begin(), out.end());
  return out;
}

std::string pm(const granpen::Stat &s, const char *mf, const char *sf)
{
  if (!s.n) return "-";
  return json_number(mf, s.mean) + " +- " + json_number(sf, s.sd);
}

std::string markdown(const std::vector<CalibrationRow> &rows, double zmin, double zmax)
{
  std::string o = "| mu | n beds | phi_0 (mean +- sd) | n pushes | v0 (cm/s) | k_z (dyne/cm, mean +- sd) | "
                  "alpha (mean +- sd) |\n|---:|---:|---|---:|---:|---|---|\n";
  for (const auto &r : rows)
    o += "| " + json_number("%g", r.mu) + " | " + std::to_string(r.phi_0.n) + " | " + pm(r.phi_0, "%.4f", "%.4f") +
         " | " + std::to_string(r.k_z.n) + " | " + (r.pushes.empty() ? std::string("-") : json_number("%g", r.v0)) +
         " | " + pm(r.k_z, "%.4g", "%.2g") + " | " + pm(r.alpha, "%.3g", "%.2g") + " |\n";
  o += "\nk_z: slope of F on z over z = " + json_number("%g", zmin) + ".." + json_number("%g", zmax) +
       " cm; alpha = k_z / (mu rho_g g D^2); sd over beds/pushes (n - 1).\n";
  return o;
}

bool write_file(const fs::path &path, const std::string &text)
{
  std::ofstream o(path, std::ios::binary);
  if (!o) return false;
  o << text;
  return (bool) o.flush();
}

std::string csv_table(const std::vector<CalibrationRow> &rows)
{
  std::string o = "mu,n_beds,phi_0_mean,phi_0_sd,n_pushes,v0,k_z_mean,k_z_sd,alpha_mean,alpha_sd\n";
  for (const auto &r : rows)
    o += num(r.mu) + "," + std::to_string(r.phi_0.n) + "," + num(r.phi_0.mean) + "," + num(r.phi_0.sd) + "," +
         std::to_string(r.k_z.n) + "," + num(r.v0) + "," + num(r.k_z.mean) + "," + num(r.k_z.sd) + "," +
         num(r.alpha.mean) + "," + num(r.alpha.sd) + "\n";
  return o;
}

std::string json_table(const std::vector<CalibrationRow> &rows, const std::string &sweep, double zmin,
                       double zmax, const std::vector<std::string> &problems)
{
  std::ostringstream o;
  auto stat = [&](const granpen::Stat &s) {
    return "{\"n\": " + std::to_string(s.n) + ", \"mean\": " + num(s.mean) + ", \"sd\": " + num(s.sd) + "}";
  };
  o << "{\n  \"tool\": \"granpen calibration\",\n  \"sweep\": " << json_string(sweep) << ",\n"
    << "  \"units\": {\"k_z\": \"dyne/cm\", \"v0\": \"cm/s\", \"z\": \"cm\"},\n"
    << "  \"window\": {\"zmin\": " << num(zmin) << ", \"zmax\": " << num(zmax) << "},\n"
    << "  \"sd\": \"sample standard deviation (n - 1), 0 for one value\",\n  \"rows\": [";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto &r = rows[i];
    o << (i ? ",\n" : "\n") << "    {\"mu\": " << num(r.mu) << ", \"v0\": " << num(r.v0)
      << ", \"phi_0\": " << stat(r.phi_0) << ", \"k_z\": " << stat(r.k_z) << ", \"alpha\": " << stat(r.alpha)
      << ",\n     \"beds\": [";
    for (std::size_t k = 0; k < r.beds.size(); ++k)
      o << (k ? ", " : "") << "{\"name\": " << json_string(r.beds[k].name) << ", \"seed\": " << num(r.beds[k].seed)
        << ", \"phi_0\": " << num(r.beds[k].phi_0) << "}";
    o << "],\n     \"pushes\": [";
    for (std::size_t k = 0; k < r.pushes.size(); ++k) {
      const auto &p = r.pushes[k];
      o << (k ? ",\n                 " : "") << "{\"trace\": " << json_string(p.name) << ", \"bed\": "
        << json_string(p.bed) << ", \"seed\": " << num(p.seed) << ", \"k_z\": " << num(p.k_z)
        << ", \"alpha\": " << num(p.alpha) << "}";
    }
    o << "]}";
  }
  o << (rows.empty() ? "],\n" : "\n  ],\n") << "  \"problems\": [";
  for (std::size_t i = 0; i < problems.size(); ++i) o << (i ? ",\n    " : "\n    ") << json_string(problems[i]);
  o << (problems.empty() ? "]\n}\n" : "\n  ]\n}\n");
  return o.str();
}

// gnuplot script with the data inline (datablocks); run in the output folder
std::string gnuplot_script(const std::vector<CalibrationRow> &rows)
{
  double lo = 0, hi = 0;
  bool any = false;
  for (const auto &r : rows) {
    lo = any ? std::min(lo, r.mu) : r.mu;
    hi = any ? std::max(hi, r.mu) : r.mu;
    any = true;
  }
  const double pad = hi > lo ? 0.1 * (hi - lo) : std::max(0.05, 0.1 * std::fabs(lo));
  std::ostringstream o;
  o << "# granpen calibration: phi_0 and k_z against the grain friction mu (written by granpen calibration)\n"
    << "set encoding utf8\nset terminal pngcairo size 1000,600 font \",12\"\nset grid\nset key outside right top box\nset offsets 0, 0, graph 0.05, graph 0.05\n"
    << "set xrange [" << num(lo - pad) << ":" << num(hi + pad) << "]\n"
    << "set xlabel \"grain friction coefficient {/Symbol m}\"\n\n";

  // phi_0: per-bed points, mean +- sd per mu
  o << "$beds << EOD\n# mu phi_0 seed\n";
  for (const auto &r : rows) {
    if (&r != &rows.front() && r.mu == (&r - 1)->mu) continue;    // each mu's beds once
    for (const auto &b : r.beds) o << num(b.mu) << " " << num(b.phi_0) << " " << num(b.seed) << "\n";
  }
  o << "EOD\n$phi << EOD\n# mu mean sd n\n";
  for (const auto &r : rows) {
    if (&r != &rows.front() && r.mu == (&r - 1)->mu) continue;
    if (r.phi_0.n) o << num(r.mu) << " " << num(r.phi_0.mean) << " " << num(r.phi_0.sd) << " " << r.phi_0.n << "\n";
  }
  o << "EOD\n"
    << "set output \"calibration_phi0.png\"\nset title \"Bed packing fraction against friction\"\n"
    << "set ylabel \"packing fraction {/Symbol f}_0\"\n"
    << "plot $phi using 1:2:3 with yerrorbars pt 7 ps 1.5 lw 2 lc rgb \"#1f77b4\" title \"mean ± sd over seeds\", \\\n"
    << "     $beds using 1:2 with points pt 6 ps 1.2 lc rgb \"#555555\" title \"each seed's bed\"\n"
    << "unset output\n\n";

  // k_z: one series per v0
  std::vector<double> v0s;
  for (const auto &r : rows)
    if (!r.pushes.empty() && std::find(v0s.begin(), v0s.end(), r.v0) == v0s.end()) v0s.push_back(r.v0);
  for (std::size_t i = 0; i < v0s.size(); ++i) {
    o << "$kz" << i << " << EOD\n# mu mean sd n\n";
    for (const auto &r : rows)
      if (!r.pushes.empty() && r.v0 == v0s[i])
        o << num(r.mu) << " " << num(r.k_z.mean) << " " << num(r.k_z.sd) << " " << r.k_z.n << "\n";
    o << "EOD\n$pts" << i << " << EOD\n# mu k_z seed\n";
    for (const auto &r : rows)
      if (!r.pushes.empty() && r.v0 == v0s[i])
        for (const auto &p : r.pushes) o << num(p.mu) << " " << num(p.k_z) << " " << num(p.seed) << "\n";
    o << "EOD\n";
  }
  o << "set output \"calibration_kz.png\"\nset title \"Depth term k_z against friction\"\n"
    << "set ylabel \"k_z (dyne/cm)\"\n";
  if (v0s.empty()) {
    o << "set label 1 \"no fitted pushes\" at graph 0.5, graph 0.5 center\nset yrange [0:1]\n"
      << "plot 1/0 notitle\n";
  } else {
    const char *colours[] = {"#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf"};
    o << "plot ";
    for (std::size_t i = 0; i < v0s.size(); ++i) {
      const char *c = colours[i % 6];
      o << (i ? ", \\\n     " : "") << "$kz" << i << " using 1:2:3 with yerrorbars pt 7 ps 1.5 lw 2 lc rgb \"" << c
        << "\" title \"v_0 = " << json_number("%g", v0s[i]) << " cm/s: mean ± sd over seeds\", \\\n     $pts" << i
        << " using 1:2 with points pt 6 ps 1.2 lc rgb \"" << c << "\" title \"each seed's push\"";
    }
    o << "\n";
  }
  o << "unset output\n";
  return o.str();
}

// runs `gnuplot SCRIPT` in DIR without a shell; returns "" on success, else why not
// (missing set when gnuplot is not installed)
std::string run_gnuplot(const fs::path &dir, const std::string &script, bool &missing)
{
  missing = false;
  int fds[2];
  if (pipe(fds) != 0) return std::string("pipe failed: ") + std::strerror(errno);
  fcntl(fds[1], F_SETFD, FD_CLOEXEC);
  std::string prog = "gnuplot", arg = script;
  std::vector<char *> args = {&prog[0], &arg[0], nullptr};
  const std::string where = dir.string();
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    return std::string("fork failed: ") + std::strerror(errno);
  }
  if (pid == 0) {
    close(fds[0]);
    int msg[2] = {0, 0};    // {stage: 0 chdir, 1 exec; errno}
    if (chdir(where.c_str()) != 0) msg[1] = errno;
    else {
      execvp(args[0], args.data());
      msg[0] = 1;
      msg[1] = errno;
    }
    if (write(fds[1], msg, sizeof msg) < 0) {
    }
    _exit(127);
  }
  close(fds[1]);
  int msg[2] = {0, 0};
  ssize_t got;
  do got = read(fds[0], msg, sizeof msg);
  while (got < 0 && errno == EINTR);
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (got == (ssize_t) sizeof msg) {
    if (msg[0] == 0) return "cannot enter " + where + ": " + std::strerror(msg[1]);
    if (msg[1] == ENOENT) {
      missing = true;
      return "gnuplot is missing (not found on PATH)";
    }
    return std::string("cannot run gnuplot: ") + std::strerror(msg[1]);
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  if (WIFEXITED(status)) return "gnuplot failed (exit status " + std::to_string(WEXITSTATUS(status)) + ")";
  return "gnuplot was killed by signal " + std::to_string(WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

const granpen::cli::Usage usage_error{"calibration", HELP};

}    // namespace

int granpen::cli::calibration(int argc, char **argv)
{
  if (argc < 1) return usage_error.no_arguments();
  double zmin = 1.0, zmax = 3.0;
  std::string sweep, out;
  for (int i = 0; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--help" || a == "-h") return usage_error.help_asked();
    if (is_option(a)) {
      std::string name, value;
      if (!split_option(a, name, value) && (name == "--zmin" || name == "--zmax" || name == "--out") &&
          !next_value(argc, argv, i, value))
        return usage_error(needs_value(name));
      if (name == "--out") {
        if (value.empty()) return usage_error("--out needs a folder");
        out = value;
      } else if (name == "--zmin" || name == "--zmax") {
        double v;
        if (!number_arg(value, v)) return usage_error(not_a_number(name, value));
        (name == "--zmin" ? zmin : zmax) = v;
      } else {
        return usage_error(unknown_option(name));
      }
      continue;
    }
    if (!sweep.empty()) return usage_error("one SWEEP_DIR only ('" + sweep + "' and '" + a + "')");
    sweep = a;
  }
  if (sweep.empty()) return usage_error("no SWEEP_DIR given");
  if (!(zmin < zmax)) return usage_error("--zmin must be below --zmax");
  if (out.empty()) out = sweep;

  std::vector<std::string> problems;
  auto problem = [&](const std::string &msg) {
    std::fprintf(stderr, "granpen calibration: %s\n", msg.c_str());
    problems.push_back(msg);
  };

  // beds
  std::string err;
  const auto info_files = files_with(fs::path(sweep) / "beds", ".info", err);
  if (!err.empty()) problem(err);
  std::vector<CalibrationBed> beds;
  std::map<std::string, CalibrationBed> bed_by_name;
  for (const auto &f : info_files) {
    try {
      const BedInfo info = read_bed_info(f);
      CalibrationBed b;
      b.name = info.name;
      b.mu = info.mu;
      b.seed = info.seed;
      b.phi_0 = info.phi_0;
      beds.push_back(b);
      bed_by_name[b.name] = b;
    } catch (InputError &e) {
      problem(e.what());
    }
  }

  // pushes
  err.clear();
  const auto trace_files = files_with(fs::path(sweep) / "traces", ".csv", err);
  if (!err.empty()) problem(err);
  std::vector<CalibrationPush> pushes;
  std::vector<std::string> notes;
  for (const auto &f : trace_files) {
    try {
      const Trace tr = to_cgs(read_trace(f));
      CalibrationPush p;
      p.name = fs::path(f).filename().string();
      p.v0 = tr.v0;
      const CalibrationBed *bed = nullptr;
      auto bk = tr.keys.find("bed");
      if (bk != tr.keys.end()) {
        p.bed = bed_name(bk->second);
        auto it = bed_by_name.find(p.bed);
        if (it != bed_by_name.end()) bed = &it->second;
        else notes.push_back(f + ": bed '" + p.bed + "' has no beds/" + p.bed + ".info");
      } else {
        notes.push_back(f + ": no 'bed' header key");
      }
      auto key = [&](const char *k, double &v) {
        auto it = tr.keys.find(k);
        if (it == tr.keys.end()) return false;
        if (it->second.find('\0') != std::string::npos || !number_arg(it->second, v))    // nor with a NUL byte in it
          throw InputError(f + ": header key " + k + " = '" + it->second + "' is not a number");
        return true;
      };
      if (!key("mu", p.mu)) {
        if (!bed) throw InputError(f + ": no header key mu and no known bed to take it from");
        p.mu = bed->mu;
      }
      if (!key("seed", p.seed) && bed) p.seed = bed->seed;
      if (bed && std::fabs(bed->mu - p.mu) > 1e-9 * std::fabs(p.mu))
        notes.push_back(f + ": pushed at mu = " + json_number("%g", p.mu) + " into bed '" + p.bed + "' poured at mu = " +
                        json_number("%g", bed->mu) + " (grouped by the push's mu)");
      double rho_g = 3.0;
      if (!key("rho_g", rho_g)) notes.push_back(f + ": no rho_g header key; alpha uses rho_g = 3 g/cm^3");

      TraceFitParams par;
      par.zlo = zmin;
      par.zhi = zmax;
      par.v0 = tr.v0;
      par.D = tr.D;
      par.g = tr.g;
      par.mu = p.mu;
      par.rho_g = rho_g;
      double dg = 0.4;
      key("d_g", dg);
      par.d_g = dg;
      const TraceFit fit = fit_trace(tr.z, tr.F, par);
      if (!fit.slope_ok) {
        problem(f + ": " + (fit.notes.empty() ? std::string("k_z undefined") : fit.notes.front()));
        continue;
      }
      p.k_z = fit.k_z;
      p.alpha = fit.alpha_ok ? fit.alpha : 0.0;
      if (!fit.alpha_ok) notes.push_back(f + ": alpha undefined, counted as 0");
      pushes.push_back(p);
    } catch (std::exception &e) {
      problem(e.what());
    }
  }

  const auto rows = calibration_table(beds, pushes);
  const std::string md = markdown(rows, zmin, zmax);

  std::printf("granpen calibration: %s: %zu beds, %zu pushes fitted over z = %g..%g cm\n\n", sweep.c_str(),
              beds.size(), pushes.size(), zmin, zmax);
  std::fputs(md.c_str(), stdout);
  for (const auto &n : notes) std::printf("note: %s\n", n.c_str());

  std::error_code ec;
  fs::create_directories(out, ec);
  const fs::path od(out);
  int status = problems.empty() ? 0 : 1;
  const std::string title = "# Friction calibration: " + md_cell(sweep) + "\n\n";
  for (const auto &[name, text] : std::vector<std::pair<std::string, std::string>>{
           {"calibration.csv", csv_table(rows)},
           {"calibration.json", json_table(rows, sweep, zmin, zmax, problems)},
           {"calibration.md", title + md}}) {
    if (write_file(od / name, text)) std::printf("wrote %s\n", (od / name).c_str());
    else {
      std::fprintf(stderr, "granpen calibration: cannot write %s\n", (od / name).c_str());
      status = 1;
    }
  }
  if (!write_file(od / "calibration.gp", gnuplot_script(rows))) {
    std::fprintf(stderr, "granpen calibration: cannot write %s\n", (od / "calibration.gp").c_str());
    return 1;
  }
  bool missing = false;
  const std::string why = run_gnuplot(od, "calibration.gp", missing);
  if (!why.empty() && !missing) status = 1;
  if (why.empty())
    std::printf("wrote %s and %s (script %s)\n", (od / "calibration_phi0.png").c_str(),
                (od / "calibration_kz.png").c_str(), (od / "calibration.gp").c_str());
  else
    std::printf("granpen calibration: no plots: %s; the tables are written (script %s)\n", why.c_str(),
                (od / "calibration.gp").c_str());
  if (!problems.empty())
    std::printf("granpen calibration: %zu problem%s (see above)\n", problems.size(), problems.size() == 1 ? "" : "s");
  return status;
}
