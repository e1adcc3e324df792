// granpen analysis: input a command refuses before it starts anything, for a reason the
// user fixes on the command line as they would a bad option (a folder that holds no trace,
// an empty list, headers that contradict the set-up asked for). The CLI's one handler
// (cli/subcommand.h: run_subcommand) exits 2 for it, as for a usage error; every other
// InputError exits 1.
#ifndef GRANPEN_INPUT_REFUSED_H
#define GRANPEN_INPUT_REFUSED_H

#include "errors.h"    // InputError

namespace granpen {

class InputRefused : public InputError {
 public:
  using InputError::InputError;
};

}    // namespace granpen

#endif
