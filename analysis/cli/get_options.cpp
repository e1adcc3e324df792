// granpen get and granpen gap-score: their command lines (get_options.h).
#include "get_options.h"

#include "args.h"
#include "subcommand.h"

#include <cmath>

namespace {

const char *GET_HELP =
    "usage: granpen get FILE KEY... [--missing VALUE]\n"
    "Prints the values of a JSON file (any granpen output: diagnosis.json, manifest.json,\n"
    "flow.json, a --json of fit or collapse) at key paths, so that a script asks for a value\n"
    "by name instead of matching the file's layout. A KEY is a path of member names and\n"
    "brackets: heldout.gap_before, per_speed[0].v0 (an index from 0),\n"
    "detection_limits[effect=cohesion].limit (the first element whose member has that\n"
    "value), traces[*].peak (every element).\n"
    "Output: one line per record, the KEYs' values separated by a tab: a string without its\n"
    "quotes, a number as the file writes it, true, false, null, an object or array as compact\n"
    "JSON. A KEY with [*] gives a record per element; every KEY then gives as many values,\n"
    "or one (repeated on each line).\n"
    "Exit status 0; 1 when FILE cannot be read or is not JSON, or a KEY leads nowhere (the\n"
    "message names the member, index or element missing; --missing VALUE prints VALUE\n"
    "there instead); 2 for a usage error (a malformed KEY is named when run: 1).\n";

const char *GAP_SCORE_HELP =
    "usage: granpen gap-score DIAGNOSIS --case NAME --truth EFFECT|EFFECT,EFFECT|none|outside --magnitude TEXT\n"
    "                         [--as-effect EFFECT --as-magnitude X] [--below-limit] [--wall-seconds S]\n"
    "Scores a diagnosis.json of granpen gap made blind on data with one effect withheld\n"
    "(bench/gap_selftest.sh) against the case's truth, by issue 21's rules\n"
    "(analysis/gap/gap_selftest_score.h): the no-effect case must find none; a library\n"
    "effect must be named and G_all shrink as an explained verdict requires, or be named in\n"
    "a tie, or be missed only below its detection limit; an outside case must not be\n"
    "explained, but by --as-effect at --as-magnitude within two of its fit's errors; a pair\n"
    "(--truth A,B --magnitude X,Y: two effects at once) must be named as the pair, or one of\n"
    "the two alone, or be missed only below a member's detection limit.\n"
    "--below-limit: the library effect lies at about half its detection limit (issue 37): a\n"
    "verdict naming no effect, or the truth (alone or in a tie), is right; another effect\n"
    "named alone, or a tie without the truth, is a confident wrong answer.\n"
    "Prints the case's row of the selftest's table (docs/gap-validation.md): case, truth,\n"
    "true magnitude, detection limit, verdict, top effect, fitted magnitude, G before and\n"
    "after, held-out v0, G before and after there, chi^2 excess removed, wall s, pass\n"
    "(yes, yes (below its limit), **no**).\n"
    "Exit status 0 when the case passes, 3 when it does not, 1 when DIAGNOSIS cannot be\n"
    "read or lacks a key the score needs, 2 for a usage error.\n";

}    // namespace

granpen::cli::GetOptions granpen::cli::parse_get(int argc, char **argv)
{
  Command cmd("get", GET_HELP);
  GetOptions o;
  cmd.app.add_option("file", o.file, "a JSON file")->required()->check(file_name());
  cmd.app.add_option("keys", o.keys, "key paths")->required();
  auto *missing = cmd.app.add_option("--missing", o.missing, "printed for a key that leads nowhere (default: an error)")
                      ->type_name("VALUE");
  cmd.parse(argc, argv, o.help);
  o.has_missing = missing->count() > 0;
  return o;
}

granpen::cli::GapScoreOptions granpen::cli::parse_gap_score(int argc, char **argv)
{
  Command cmd("gap-score", GAP_SCORE_HELP);
  GapScoreOptions o;
  auto &app = cmd.app;
  app.add_option("diagnosis", o.diagnosis, "diagnosis.json of granpen gap")->required()->check(file_name());
  app.add_option("--case", o.case_name, "the case's name (the table's first column)")->required()->check(file_name());
  app.add_option("--truth", o.truth, "the effect withheld, none, or outside (an effect the library lacks)")
      ->required()->check(file_name());
  app.add_option("--magnitude", o.magnitude_text, "the true magnitude (a number for an effect; any text for outside)")
      ->required()->check(file_name());
  auto *as = app.add_option("--as-effect", o.as_effect, "outside: the library effect that is a right answer")->type_name("EFFECT");
  auto *as_mag = cmd.number("--as-magnitude", o.as_magnitude, "outside: ... at this magnitude");
  app.add_flag("--below-limit", o.below_limit, "the effect lies at about half its detection limit");
  app.add_option("--wall-seconds", o.wall_seconds, "the diagnosis's wall time, for the table")->check(whole_number(0, 1000000000))
      ->type_name("S");
  if (!cmd.parse(argc, argv, o.help)) return o;
  if ((as->count() > 0) != (as_mag->count() > 0)) throw UsageError("--as-effect and --as-magnitude go together");
  if (as->count() && o.truth != "outside") throw UsageError("--as-effect: only for --truth outside");
  if (o.below_limit && (o.truth == "none" || o.truth == "outside" || o.truth.find(',') != std::string::npos))
    throw UsageError("--below-limit: only for one library effect's --truth");
  double m = 0, m2 = 0;
  if (const auto comma = o.truth.find(','); comma != std::string::npos) {
    const auto mcomma = o.magnitude_text.find(',');
    if (comma == 0 || comma + 1 == o.truth.size() || o.truth.find(',', comma + 1) != std::string::npos)
      throw UsageError("--truth: a pair is two effects, A,B; got '" + o.truth + "'");
    if (mcomma == std::string::npos || !number_arg(o.magnitude_text.substr(0, mcomma), m) ||
        !number_arg(o.magnitude_text.substr(mcomma + 1), m2) || !std::isfinite(m) || !std::isfinite(m2))
      throw UsageError("--magnitude: a pair needs two numbers, X,Y; got '" + o.magnitude_text + "'");
  } else if (o.truth != "none" && o.truth != "outside" && (!number_arg(o.magnitude_text, m) || !std::isfinite(m)))
    throw UsageError("--magnitude: needs a number for an effect, got '" + o.magnitude_text + "'");
  return o;
}
