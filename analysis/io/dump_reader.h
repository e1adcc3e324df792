/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: streaming reader of LAMMPS text dumps (dump custom,
   dump atom; plain text or gzip, detected by magic bytes), one frame in
   memory at a time. Every rejection names the file and line.
------------------------------------------------------------------------- */

#ifndef GRANPEN_DUMP_READER_H
#define GRANPEN_DUMP_READER_H

#include "errors.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace granpen {

struct DumpFrame {
  std::string file;            // path it came from
  long line = 0;               // line number of its "ITEM: TIMESTEP"
  long long timestep = 0;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};    // orthogonal box bounds (triclinic is rejected)
  std::vector<std::string> columns;               // per-atom column names as in the file, except
                                                  // xs/xu/xsu renamed x y z (see DumpReader)
  std::vector<std::vector<double>> data;          // data[c][i]: column c, atom i (unscaled, unwrapped as given)

  std::size_t natoms() const;
  bool has(const std::string &name) const;
  // throws InputError "FILE:LINE: frame has no column NAME"
  const std::vector<double> &col(const std::string &name) const;
};

struct DumpProgress {
  std::uint64_t bytes = 0;     // bytes consumed so far, of the files as stored (compressed for gzip)
  std::uint64_t frames = 0;    // frames returned so far
  double seconds = 0;          // wall seconds since the reader was made
};

class DumpReader {
 public:
  // paths: one or many files (plain text or gzip: detected by magic bytes, not by name),
  // read in order. required: columns every frame must have. Coordinates: a frame with
  // xs ys zs (scaled) and no x y z has them converted to x y z (x = lo + xs (hi - lo));
  // xu yu zu (and xsu ysu zsu, scaled) are likewise renamed x y z, so col("x") works
  // whenever positions exist. When several forms are present, x beats xu beats xs beats xsu.
  DumpReader(std::vector<std::string> paths,
             std::vector<std::string> required = {"id", "type", "x", "y", "z", "vx", "vy", "vz", "radius"});
  ~DumpReader();
  DumpReader(const DumpReader &) = delete;
  DumpReader &operator=(const DumpReader &) = delete;

  // The next complete frame; false at the clean end of the last file. Throws InputError
  // naming file:line (truncated frame, truncated or corrupt gzip, missing required column,
  // non-numeric or non-finite value, wrong field count, missing or malformed ITEM line,
  // triclinic box, a file without frames, a timestep below the previous frame's, in this
  // file or the one before: files are read in the order given). A frame is never returned partly read; after
  // an error the reader is finished (next() throws the same error again).
  bool next(DumpFrame &frame);
  DumpProgress progress() const;
  // cb is called from next() at most every every_seconds of wall time (and once at the end).
  void on_progress(std::function<void(const DumpProgress &)> cb, double every_seconds = 2.0);

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}    // namespace granpen

#endif
