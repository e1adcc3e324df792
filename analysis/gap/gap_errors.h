// granpen gap: input the diagnosis refuses before it starts anything (docs/gap.md, issue
// 21's list: an empty --effects, --real naming a file, one trace in all, mixed units,
// a speed the scenario cannot run, headers that contradict the scenario). A usage error:
// the front end exits 2; every other InputError (an unreadable trace, a failed
// simulation) exits 1.
#ifndef GRANPEN_GAP_ERRORS_H
#define GRANPEN_GAP_ERRORS_H

#include "errors.h"    // InputError

namespace granpen {

class GapRefused : public InputError {
 public:
  using InputError::InputError;
};

}    // namespace granpen

#endif
