// granpen flow and momentum: the options the two dump subcommands share (dump_options.cpp).
#ifndef GRANPEN_CLI_DUMP_OPTIONS_H
#define GRANPEN_CLI_DUMP_OPTIONS_H

#include "args.h"
#include "dump_frames.h"    // RodOptions

#include <string>
#include <vector>

namespace granpen {
namespace cli {

// For flow and momentum: from the numeric options (ParsedArgs::read_numbers) --rod-type
// N, --axis X Y, --tip Z; false with a message when N is not a positive integer.
bool read_rod_options(const ParsedArgs &args, RodOptions &rod, std::string &message);
// --periodic AXES: xy, x, y or none, as periodic x and y; false for anything else.
bool periodic_axes(const std::string &axes, bool &x, bool &y);

}    // namespace cli
}    // namespace granpen

#endif
