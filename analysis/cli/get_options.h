// granpen get / granpen gap-score: their command lines as typed structs and parse functions
// (words -> options; pure, throwing only UsageError, as every subcommand's parse).
#ifndef GRANPEN_CLI_GET_OPTIONS_H
#define GRANPEN_CLI_GET_OPTIONS_H

#include <string>
#include <vector>

namespace granpen {
namespace cli {

// granpen get FILE KEY... [--missing VALUE]
// Checks: file not empty; at least one key (each a key path, json_path.h; checked when run,
// against the file's keys); missing given only with has_missing.
struct GetOptions {
  std::string help;
  bool help_requested() const { return !help.empty(); }
  std::string file;
  std::vector<std::string> keys;
  bool has_missing = false;    // --missing: a key that leads nowhere prints this, not an error
  std::string missing;
};
GetOptions parse_get(int argc, char **argv);
int run_get(const GetOptions &o);    // get_cmd.cpp

// granpen gap-score DIAGNOSIS --case NAME --truth EFFECT|none|outside --magnitude TEXT
//                   [--as-effect EFFECT --as-magnitude X] [--below-limit] [--wall-seconds S]
// Checks: diagnosis, case_name, truth, magnitude_text not empty; magnitude_text a finite
// number when truth is an effect; as_effect and as_magnitude given together, only with
// truth outside; below_limit only with a library effect; wall_seconds a whole number >= 0 (-1: not given).
struct GapScoreOptions {
  std::string help;
  bool help_requested() const { return !help.empty(); }
  std::string diagnosis, case_name, truth, magnitude_text, as_effect;
  double as_magnitude = 0;
  bool below_limit = false;    // the case lies at about half its detection limit (gap_selftest_score.h)
  long long wall_seconds = -1;
};
GapScoreOptions parse_gap_score(int argc, char **argv);
int run_gap_score(const GapScoreOptions &o);    // gap_score_cmd.cpp

}    // namespace cli
}    // namespace granpen

#endif
