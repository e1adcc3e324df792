// granpen gap: input the diagnosis refuses before it starts anything (docs/gap.md, issue
// 21's list: an empty --effects, --real naming a file, one trace in all, mixed units,
// a speed the scenario cannot run, headers that contradict the scenario). A usage error
// (io/input_refused.h): the front end exits 2; every other InputError (an unreadable
// trace, a failed simulation) exits 1.
#ifndef GRANPEN_GAP_ERRORS_H
#define GRANPEN_GAP_ERRORS_H

#include "input_refused.h"

namespace granpen {

class GapRefused : public InputRefused {
 public:
  using InputRefused::InputRefused;
};

}    // namespace granpen

#endif
