// granpen flow / granpen momentum: what the two dump subcommands share: the rod options,
// progress on stderr, and outputs written all at once (nothing half-written on failure),
// never over an input. The frames as arrays: io/dump_frames.h.
#ifndef GRANPEN_CLI_DUMP_CMD_COMMON_H
#define GRANPEN_CLI_DUMP_CMD_COMMON_H

#include "dump_frames.h"
#include "dump_reader.h"

#include <string>
#include <utility>
#include <vector>

namespace granpen {
namespace cli {

// Throws OutputError when dir/NAME for one of names is one of the inputs (the dumps, and
// the trace unless empty): checked before anything is read.
void refuse_outputs_over_inputs(const std::string &dir, const std::vector<const char *> &names,
                                const std::vector<std::string> &dumps, const std::string &trace);

// Before anything is read: throws OutputError when one of the outputs NAMES in o.out_dir
// is an input (refuse_outputs_over_inputs); how (FlowProvenance, MomentumProvenance)
// records the dumps, the rod type and the periodic axes. Options: FlowOptions or
// MomentumOptions (flow_options.h, momentum_options.h).
template <class Options, class Provenance>
void begin_dump_command(const Options &o, const std::vector<const char *> &names, Provenance &how)
{
  refuse_outputs_over_inputs(o.out_dir, names, o.dumps, o.trace);
  how.dumps = o.dumps, how.rod_type = o.rod.rod_type, how.periodic = o.periodic;
}

// The dumps' first frame into frame, progress lines on stderr as TOOL from then on;
// throws InputError when the dumps hold no frame.
void first_frame(DumpReader &reader, const std::vector<std::string> &dumps, DumpFrame &frame, const std::string &tool);

// Progress lines on stderr every 2 s while reading and once at the end
// ("TOOL: N frames, X MB, Y MB/s").
void report_progress(DumpReader &reader, const std::string &tool);

// The bed surface of a frame (g: its grains), measured as compute bed/surface does (the
// highest grain top in each of 4 x 4 columns of the box, averaged).
double frame_bed_surface(const DumpFrame &frame, const GrainFrame &g);

// Writes every (name, text) into dir (made if missing) through io/atomic_file (every
// temporary written before the first rename); false with a message naming the path.
bool write_outputs(const std::string &dir, const std::vector<std::pair<std::string, std::string>> &files,
                   std::string &message);

}    // namespace cli
}    // namespace granpen

#endif
