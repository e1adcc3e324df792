/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: the error types of the layers from io up (readers,
   writers, the sweep runner, the gap diagnosis). core throws only
   std::invalid_argument, so it needs none of these.
   InputError: bad input or a failed write the user can act on; its message
   names the file (and line, key or option). The CLI prints it and exits 1.
------------------------------------------------------------------------- */

#ifndef GRANPEN_ERRORS_H
#define GRANPEN_ERRORS_H

#include <stdexcept>

namespace granpen {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}    // namespace granpen

#endif
