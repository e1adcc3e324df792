// granpen import: its command line (import_options.h).
#include "import_options.h"

#include "args.h"

namespace {

const char *HELP =
    "usage: granpen import FILE-OR-FOLDER... --mapping MAP --out DIR --D D --g G\n"
    "                      [--units cgs|si] [--v0 V | --v0-table TABLE] [--window W] [--run N]\n"
    "                      [--speed-tolerance R] [--end-tolerance R] [--d_g DG]\n"
    "                      [--rho_g RHO] [--mu MU] [--dry-run]\n"
    "Reads instrument files (delimited text or key=value rows, as the mapping MAP says:\n"
    "columns, units, signs, tare, contact threshold or surface, speed checks; see\n"
    "docs/measurements.md) and writes one granpen-trace v1 file per input, DIR/NAME.csv:\n"
    "  t = time since the file's first row (a log sampled by depth: the integral of dz / v;\n"
    "  neither time nor speed: no t, header t_from = none), z = depth below the surface\n"
    "  (negative before contact), F = force with the offset of the first tare_rows rows removed.\n"
    "The data end where rows stop matching the layout (a logger's trailer), reported.\n"
    "The end of the push is cut by one rule: rows after the rod's furthest advance\n"
    "(standstill, retraction), and rows after the last block of speed_rows rows still\n"
    "moving within end_tolerance of the mean speed (the deceleration and its force spike;\n"
    "a slow drift is kept and reported); without a position, rows after the last at\n"
    "contact force. Each file's cut is reported.\n"
    "A folder stands for every file in it. Runs are numbered from --run in the order given.\n"
    "The header's v0 is the nominal speed (--v0, the table's line for the file, the\n"
    "mapping's v0), else the measured mean; v0_measured and v0_ripple stand beside it.\n"
    "Nothing is written unless every file imports; --dry-run prints what would be written.\n"
    "After the files, one table (also DIR/import_summary.csv), then the warnings.\n"
    "Exit status 0, 1 for bad input (named with file and line), 2 for usage.\n";

}    // namespace

granpen::cli::ImportOptions granpen::cli::parse_import(int argc, char **argv)
{
  Command cmd("import", HELP);
  ImportOptions o;
  std::string units = "cgs";
  auto &app = cmd.app;
  app.add_option("files", o.inputs, "instrument files, or folders of them")->required();
  app.add_option("--mapping", o.mapping, "the mapping file (columns, units, signs, rules), or gef: each file's own "
                 "GEF-CPT header")->required()->check(file_name())
      ->type_name("MAP");
  app.add_option("--out", o.out_dir, "the folder the traces go to (made when missing)")->required()->check(file_name())
      ->type_name("DIR");
  app.add_option("--units", units, "units of the traces and of --v0, --D, --g (default cgs)")
      ->type_name("UNITS")->check(CLI::IsMember({"cgs", "si"}));
  app.add_option("--v0", o.v0, "nominal push speed, > 0 (default: the mapping's v0, else the measured mean)")
      ->check(positive_number())->type_name("V");
  app.add_option("--v0-table", o.v0_table, "nominal v0 per file: lines 'FILE V0 [UNIT]' (FILE: name or stem)")
      ->check(file_name())->type_name("TABLE");
  app.add_option("--speed-tolerance", o.speed_tolerance, "relative: speed constant within this, for every file "
                 "(default: the mapping's speed_tolerance)")->check(positive_number())->type_name("R");
  app.add_option("--end-tolerance", o.end_tolerance, "relative, < 1: a block this far below the mean speed is "
                 "stopping, for every file (default: the mapping's end_tolerance)")->check(positive_number())->type_name("R");
  app.add_option("--D", o.D, "rod diameter, > 0")->check(positive_number())->required()->type_name("D");
  app.add_option("--g", o.g, "gravity, > 0")->check(positive_number())->required()->type_name("G");
  app.add_option("--window", o.window, "average into windows of W seconds (default: the mapping's window, else none)")
      ->check(positive_number())->type_name("W");
  app.add_option("--run", o.first_run, "the first run number (default 1)")->check(whole_number(1, 1000000000))->type_name("N");
  app.add_option("--d_g", o.d_g, "optional header key d_g")->check(positive_number())->type_name("DG");
  app.add_option("--rho_g", o.rho_g, "optional header key rho_g")->check(positive_number())->type_name("RHO");
  app.add_option("--mu", o.mu, "optional header key mu")->check(positive_number())->type_name("MU");
  app.add_flag("--dry-run", o.dry_run, "print what would be written; write nothing");
  if (!cmd.parse(argc, argv, o.help)) return o;
  o.si = units == "si";
  if (o.v0 > 0.0 && !o.v0_table.empty()) throw UsageError("--v0 and --v0-table: one nominal speed per file, give one of them");
  if (!(o.end_tolerance < 1.0)) throw UsageError("--end-tolerance must be below 1 (a fraction of the mean speed)");
  return o;
}
