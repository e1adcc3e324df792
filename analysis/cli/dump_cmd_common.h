// granpen flow / granpen momentum: what the two dump subcommands share: the rod options,
// progress on stderr, and outputs written all at once (nothing half-written on failure),
// never over an input. The frames as arrays: io/dump_frames.h.
#ifndef GRANPEN_CLI_DUMP_CMD_COMMON_H
#define GRANPEN_CLI_DUMP_CMD_COMMON_H

#include "args.h"
#include "dump_frames.h"
#include "dump_reader.h"

#include <string>
#include <utility>
#include <vector>

namespace granpen {
namespace cli {

// Progress lines on stderr every 2 s while reading and once at the end
// ("TOOL: N frames, X MB, Y MB/s").
void report_progress(DumpReader &reader, const std::string &tool);

// Writes every (name, text) into dir (made if missing) through io/atomic_file (every
// temporary written before the first rename); false with a message naming the path.
bool write_outputs(const std::string &dir, const std::vector<std::pair<std::string, std::string>> &files,
                   std::string &message);

// Throws OutputError when dir/NAME for one of names is one of the inputs (the dumps,
// args.positional, and --trace): checked before anything is read.
void refuse_outputs_over_inputs(const std::string &dir, const std::vector<const char *> &names, const ParsedArgs &args);

}    // namespace cli
}    // namespace granpen

#endif
