// granpen analysis: an output written piece by piece (a trace streamed from a file of any
// length) with the guarantees of atomic_file.h: the pieces go to a temporary name in the
// output's folder, every write is checked, and commit() flushes it to disk and renames it
// into place; a StagedFile dropped without commit() removes its temporary, so a failure
// leaves no half-written output.
#ifndef GRANPEN_STAGED_FILE_H
#define GRANPEN_STAGED_FILE_H

#include <string>

namespace granpen {

class StagedFile {
 public:
  // Opens the temporary beside path; throws OutputError "cannot write PATH: REASON".
  explicit StagedFile(const std::string &path);
  ~StagedFile();
  StagedFile(const StagedFile &) = delete;
  StagedFile &operator=(const StagedFile &) = delete;

  // throws OutputError naming the path
  void write(const std::string &text);
  // Flushes and closes the temporary (throws OutputError); rename() then puts it in place.
  // Two steps so that several outputs are all on disk before the first is renamed.
  void close();
  void rename();
  // the temporary removed (nothing of it left); what the destructor does before rename()
  void abandon();

  const std::string &path() const { return path_; }
  // the temporary's name, until rename() (to read back what was written)
  const std::string &temporary() const { return tmp_; }

 private:
  void flush();
  std::string path_, tmp_;
  std::string buffer_;
  int fd_ = -1;
  bool renamed_ = false;
};

}    // namespace granpen

#endif
