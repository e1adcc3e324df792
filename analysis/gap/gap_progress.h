// granpen gap: progress of a diagnosis, reported through a callback that the front end
// renders (the library prints nothing).
#ifndef GRANPEN_GAP_PROGRESS_H
#define GRANPEN_GAP_PROGRESS_H

#include <functional>
#include <string>

namespace granpen {

struct GapProgress {
  enum Kind {
    STEP,       // one of the diagnosis's main steps begins: done of total
    INFO,       // a fact worth a line (the plan, the verdict, a file written)
    DETAIL,     // one item of a step (an effect's fit: done of total)
    WARNING,    // a choice the data forced, also kept in the report's notes
    DEBUG       // numbers for a developer (every ensemble's means)
  };
  Kind kind = INFO;
  std::string stage;          // plan, simulate, align, features, where, which, confirm, report
  int done = 0, total = 0;    // this item's place in its stage (0 of 0: not counted)
  std::string message;
};

using GapProgressFn = std::function<void(const GapProgress &)>;

}    // namespace granpen

#endif
