// granpen flow: its command line (flow_options.h).
#include "flow_options.h"

#include "args.h"

#include <string>
#include <vector>

namespace {

using namespace granpen::cli;

const char *HELP =
    "usage: granpen flow DUMP... [--trace TRACE] [--out DIR] [options]\n"
    "The flow of the grains around the rod from LAMMPS text dumps (dump custom, plain or\n"
    "gzip; columns id type x y z vx vy vz radius, optional mass, a Voronoi volume and a\n"
    "per-atom stress), as compute flow/azimuthal defines it (docs/postprocess.md):\n"
    "  fields   (r, z) bins about the rod axis, z from the rod tip (negative below it),\n"
    "           pooled over the frames: count, phi (Voronoi), phi_centre, v_r, v_z, T,\n"
    "           shear rate gammadot, pressure p, inertial number I = gammadot d_g / sqrt(p/rho_g)\n"
    "  below    v_z and phi against z in the cylinder r < D/3 below the rod face, with the\n"
    "           exponential fit v_z ~ A exp(z / lambda) (paper: lambda_vz = 0.98 D +- 0.15)\n"
    "  edge     per frame with the tip in the bed, phi and I of the bins at the rod's bottom\n"
    "           edge (r = R, z = 0), and the fit phi = phi_0 + b I (paper: phi = 0.57 - 0.35 I)\n"
    "  strip    v_z against height above the bed surface, 0.5 to 1.5 cm from the shaft\n"
    "  surface  per frame, v_z of the strip's top grain layer (one dz below the surface)\n"
    "           against t~, and the t~ where it last turns from up to down (paper: 1)\n"
    "  annulus  per frame, phi, v_z and T for r = 2 to 3 cm between 0.5 cm below the bed\n"
    "           surface and the tip, against t~ = (z_tip / v0) sqrt(g / D)\n"
    "The rod is found in each frame from its atoms: axis = mean x, y, tip = lowest z - radius.\n"
    "Outputs in DIR (default .): flow.json (every fitted number with its error),\n"
    "flow_fields.csv (r,z,count,phi,phi_centre,vr,vz,T,gammadot,p,I),\n"
    "flow_profile_below.csv (z,vz,vz_se,phi), flow_edge_phi_I.csv (I,phi),\n"
    "flow_strip.csv (z,vz), flow_annulus.csv (t_tilde,z_tip,phi,vz,T),\n"
    "flow_surface.csv (t_tilde,z_tip,vz,grains).\n"
    "Units are the dump's (cgs for granpen's decks). Progress goes to stderr.\n"
    "Exit status: 0 on success, 1 for unreadable input (the message names file and line;\n"
    "no output is written), 2 for a usage error.\n";

// --steps FIRST[:LAST]
void read_steps(const std::string &t, FlowOptions &o)
{
  const auto colon = t.find(':');
  const std::string a = t.substr(0, colon), b = colon == std::string::npos ? a : t.substr(colon + 1);
  if ((!a.empty() && !integer_arg(a, o.step_lo)) || (!b.empty() && !integer_arg(b, o.step_hi)) || (a.empty() && b.empty()))
    throw UsageError("--steps '" + t + "' is not FIRST[:LAST] (timesteps)");
  if (o.step_hi < o.step_lo) throw UsageError("--steps '" + t + "': LAST is before FIRST");
}

}    // namespace

granpen::cli::FlowOptions granpen::cli::parse_flow(int argc, char **argv)
{
  Command cmd("flow", HELP);
  FlowOptions o;
  cmd.app.add_option("dumps", o.dumps, "dumps");
  add_text(cmd, "--trace", o.trace, "FILE", "the push's force trace: v0, D, g, d_g, rho_g and the bed surface\n(key surface) from its header");
  add_text(cmd, "--out", o.out_dir, "DIR", "output folder (made if missing; default .)");
  RodArgs rod;
  add_rod_options(cmd, rod, "fixed rod axis instead of the rod atoms' mean x, y", "fixed tip height instead of the rod atoms' lowest point");
  add_positive(cmd, "--D", o.D, "D", "rod diameter (default: trace header, else measured from the rod\natoms as fix rod/drive does: 2 max(r_xy + radius))");
  add_positive(cmd, "--dg", o.d_g, "D", "grain diameter for I and the default bins (default: trace header,\nelse the mean grain diameter of the first frame)");
  add_positive(cmd, "--rho", o.rho_g, "RHO", "grain density for I and for masses without a mass column\n(default: trace header rho_g, else 3.0)");
  add_positive(cmd, "--v0", o.v0, "V", "push speed for t~ (default: trace header)");
  add_positive(cmd, "--g", o.g, "G", "gravity for t~ (default: trace header)");
  add_number(cmd, "--zs", o.z_s, "Z", "bed surface height (default: trace header key surface, else\nmeasured in the first frame as compute bed/surface does)");
  add_positive(cmd, "--dr", o.dr, "DR", "radial bin size (default d_g), rounded to whole bins as the compute does");
  add_positive(cmd, "--dz", o.dz, "DZ", "vertical bin size (default d_g), rounded likewise");
  add_positive(cmd, "--rmax", o.rmax, "R", "outer radius of the bins (default half the smaller box width)");
  add_number(cmd, "--zlo", o.zlo, "Z", "bin range about the tip, lower end (default -4)");
  add_number(cmd, "--zhi", o.zhi, "Z", "bin range about the tip, upper end (default 6)");
  add_text(cmd, "--voronoi", o.voronoi, "WHAT", "auto (default: column c_vor[1] if the dump has it, else voro++),\na column name, voro++ (tessellate each frame, as compute\nflow/azimuthal voronoi voro++ does) or none");
  add_text(cmd, "--stress", o.stress, "WHAT", "auto (default: columns c_stress[1..3] if present), a compute ID\n(columns c_ID[1] c_ID[2] c_ID[3] of compute stress/atom), or none");
  add_periodic_option(cmd, o.periodic);
  add_positive(cmd, "--profile-radius", o.profile_radius, "R", "cylinder radius of the profile below the rod (default D/3)");
  CLI::Option *strip = add_numbers(cmd, "--strip", 2, "A B", "strip distances from the shaft surface (default 0.5 1.5)");
  CLI::Option *annulus = add_numbers(cmd, "--annulus", 2, "R1 R2", "annulus radii (default 2 3)");
  add_number(cmd, "--annulus-top", o.ann_top, "H", "the annulus starts H below the bed surface (default 0.5)");
  CLI::Option *edge = add_numbers(cmd, "--edge", 2, "WR WZ", "edge bins: centres within WR of r = R and WZ of z = 0 (default:\none bin size each)");
  CLI::Option *steps = cmd.app.add_option("--steps", o.steps, "only the frames with timesteps A to B (either may be left out)")
                           ->type_name("A[:B]");
  cmd.app.add_flag("--rod-cells", o.rod_cells, "with voro++: the rod's spheres take part in the tessellation, so\nthat the grains' cells end at the rod surface instead of reaching\ninto the rod (phi next to the rod; the compute does not do this)");
  if (!cmd.parse(argc, argv, o.help)) return o;
  if (o.dumps.empty()) throw UsageError("no dump given");
  finish_rod_options(rod, o.rod);
  finish_periodic(o.periodic, o.px, o.py);
  const std::vector<double> s = take_numbers(strip, 2), a = take_numbers(annulus, 2), e = take_numbers(edge, 2);
  if (!s.empty()) o.strip1 = s[0], o.strip2 = s[1];
  if (!a.empty()) o.ann1 = a[0], o.ann2 = a[1];
  if (!(o.strip1 >= 0 && o.strip2 > o.strip1)) throw UsageError("--strip needs 0 <= A < B");
  if (!(o.ann1 >= 0 && o.ann2 > o.ann1)) throw UsageError("--annulus needs 0 <= R1 < R2");
  if (!e.empty()) {
    if (!(e[0] > 0 && e[1] > 0)) throw UsageError("--edge needs WR > 0 and WZ > 0 (bin widths)");
    o.edge_wr = e[0], o.edge_wz = e[1];
  }
  if (!(o.zhi > o.zlo)) throw UsageError("--zhi must exceed --zlo");
  if (!(o.zlo < 0.0)) throw UsageError("--zlo must be below 0 (the profile below the rod needs bins below the tip)");
  if (steps->count()) read_steps(o.steps, o);
  return o;
}
