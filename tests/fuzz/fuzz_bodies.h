// The bodies of the reader fuzz targets, shared by the libFuzzer drivers
// (fuzz_dump_reader.cpp, fuzz_trace_reader.cpp) and the unit test that replays the
// committed corpus and crash regressions (tests/analysis/io/test_dump_reader.cpp), so a
// regression input is replayed exactly as the fuzzer ran it. A reader may accept an
// input or reject it with InputError; anything else, or a broken invariant of what
// it returned, aborts.
#ifndef GRANPEN_FUZZ_BODIES_H
#define GRANPEN_FUZZ_BODIES_H

#include "dump_reader.h"
#include "fuzz_check.h"
#include "trace_reader.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace granpen_fuzz {

// Reads the dump at path. The input's size picks the variant, so that corpus files
// stay plain dump files: required columns none, {"x"} or the default set (size % 3),
// and the file read once or twice in a row (size / 3 % 2).
inline void dump_body(const std::string &path, std::size_t size)
{
  std::vector<std::string> required;
  if (size % 3 == 1) required = {"x"};
  if (size % 3 == 2) required = {"id", "type", "x", "y", "z", "vx", "vy", "vz", "radius"};
  std::vector<std::string> paths(size / 3 % 2 ? 2 : 1, path);
  granpen::DumpFrame f;
  try {
    granpen::DumpReader r(paths, required);
    std::uint64_t frames = 0;
    long long last_step = 0;
    while (r.next(f)) {
      // time never goes backwards (a file read twice does: that is rejected, not returned)
      GRANPEN_FUZZ_CHECK(!frames || f.timestep >= last_step);
      last_step = f.timestep;
      ++frames;
      GRANPEN_FUZZ_CHECK(f.columns.size() == f.data.size());
      GRANPEN_FUZZ_CHECK(!f.columns.empty());
      for (const auto &c : f.data) {
        GRANPEN_FUZZ_CHECK(c.size() == f.natoms());
        for (double v : c) GRANPEN_FUZZ_CHECK(std::isfinite(v));
      }
      for (const auto &name : required) GRANPEN_FUZZ_CHECK(f.col(name).size() == f.natoms());
      for (int d = 0; d < 3; ++d) GRANPEN_FUZZ_CHECK(f.lo[d] <= f.hi[d]);
      GRANPEN_FUZZ_CHECK(f.line >= 1);
      GRANPEN_FUZZ_CHECK(r.progress().frames == frames);
    }
    GRANPEN_FUZZ_CHECK(!r.next(f));
  } catch (granpen::InputError &e) {
    GRANPEN_FUZZ_CHECK(f.data.empty());    // a failed frame is never left half read
    GRANPEN_FUZZ_CHECK(std::string(e.what()).compare(0, path.size(), path) == 0);
  }
}

// The input's size picks the row limit: the reader's own (even) or 12 rows (odd), so
// that the limit's rejection is reached by small inputs too.
inline void trace_body(const std::string &text)
{
  const std::size_t max_rows = text.size() % 2 ? 12 : granpen::kMaxTraceRows;
  try {
    granpen::Trace t = granpen::parse_trace(text, "fuzz.csv", max_rows);
    GRANPEN_FUZZ_CHECK(t.t.size() == t.z.size() && t.t.size() == t.F.size());
    GRANPEN_FUZZ_CHECK(t.t.size() >= 10 && t.t.size() <= max_rows);
    // the header validation: what every tool divides by is positive and finite
    for (double v : {t.v0, t.D, t.g}) GRANPEN_FUZZ_CHECK(std::isfinite(v) && v > 0.0);
    GRANPEN_FUZZ_CHECK(t.units == "cgs" || t.units == "si");
    for (const char *k : {"d_g", "rho_g", "mu"})
      if (t.keys.count(k)) GRANPEN_FUZZ_CHECK(std::isfinite(t.number(k, NAN)) && t.number(k, NAN) >= 0.0);
    GRANPEN_FUZZ_CHECK(t.z.back() >= t.z.front());    // depth, not height
    GRANPEN_FUZZ_CHECK(text.find('\0') == std::string::npos);    // a NUL byte is refused, never skipped
    GRANPEN_FUZZ_CHECK(t.columns.size() <= granpen::kMaxTraceColumns);
    for (std::size_t i = 0; i < t.t.size(); ++i) {
      GRANPEN_FUZZ_CHECK(std::isfinite(t.t[i]) && std::isfinite(t.z[i]) && std::isfinite(t.F[i]));
      if (i) GRANPEN_FUZZ_CHECK(t.t[i] > t.t[i - 1]);
    }
    for (const auto &kv : t.other) GRANPEN_FUZZ_CHECK(kv.second.size() == t.t.size());
    granpen::Trace c = granpen::to_cgs(t);
    GRANPEN_FUZZ_CHECK(c.units == "cgs" && c.t.size() == t.t.size());
    GRANPEN_FUZZ_CHECK(std::isfinite(c.v0) && std::isfinite(c.D) && std::isfinite(c.g));
  } catch (granpen::InputError &e) {
    GRANPEN_FUZZ_CHECK(std::string(e.what()).compare(0, 9, "fuzz.csv:") == 0);    // file and line named
  }
}

}    // namespace granpen_fuzz

#endif
