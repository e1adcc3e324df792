// granpen analysis: every output file goes through here. A file is written to a temporary
// name in its own folder, flushed to disk and renamed into place, so an interrupted run
// leaves the old file or the new one, never half of one; every step is checked and a
// failure names the path. An output that is one of the inputs is refused before anything
// is written.
#ifndef GRANPEN_ATOMIC_FILE_H
#define GRANPEN_ATOMIC_FILE_H

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace granpen {

// An output that cannot be written (or must not be): the message names the path.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// text into path: PATH's folder must exist and be writable (it is not created).
// Throws OutputError "cannot write PATH: REASON"; the temporary is removed.
void write_file_atomic(const std::string &path, const std::string &text);

// Several (path, text) at once: every temporary is written before the first rename, so a
// failure while writing leaves every old file in place. Throws OutputError.
void write_files_atomic(const std::vector<std::pair<std::string, std::string>> &files);

// The folder dir, made (with its parents) when missing; OutputError when it cannot be.
void make_output_dir(const std::string &dir);

// true when a and b are the same file: both exist and are equivalent (hard links,
// symbolic links, ./x and x), or neither exists and their absolute normal forms agree.
bool same_file(const std::string &a, const std::string &b);

// Throws OutputError "OPTION OUTPUT is the input INPUT: refusing to overwrite it" when
// output is the same file as one of inputs (nothing has been written then).
void refuse_overwriting_inputs(const std::string &output, const std::string &option,
                               const std::vector<std::string> &inputs);

// Throws OutputError "OPTION_A X and OPTION_B X are the same file: ..." when two of the
// outputs (option, path; an empty path is no output) are the same file (same_file): the
// second write would replace the first, and both be reported written.
void refuse_shared_outputs(const std::vector<std::pair<std::string, std::string>> &outputs);

}    // namespace granpen

#endif
