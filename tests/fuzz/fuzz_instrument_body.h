// The body of the instrument-file fuzz target (fuzz_instrument_reader.cpp), shared with the
// unit test that replays the committed corpus (tests/analysis/io/test_dump_reader.cpp). The
// input is an instrument file; its size picks one of four mappings (column names, column
// indices, key=value rows, a depth log with a decimal comma). The reader may accept the file
// or reject it with InputError naming it; an accepted file holds no NUL byte and no line over
// kMaxInstrumentLine (issue 36: NUL bytes cut fields short, long lines took unbounded
// memory), and every row it returns is finite in its mapped columns, in file order.
#ifndef GRANPEN_FUZZ_INSTRUMENT_BODY_H
#define GRANPEN_FUZZ_INSTRUMENT_BODY_H

#include "errors.h"
#include "fuzz_check.h"
#include "import_mapping.h"
#include "instrument_reader.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace granpen_fuzz {

inline void instrument_body(const std::string &text)
{
  static const char *mappings[] = {
      "time = t\nforce = F\nforce_unit = dyne\ndisplacement = x\nposition_unit = cm\nsurface = 0\n",
      "column_names = no\ntime = #1\nforce = #2\ndisplacement = #3\nsurface = 0\n",
      "delimiter = keyvalue\ntime = t\nforce = F\ndepth = z\n",
      "decimal = comma\ndepth = Depth\nforce = Force\nspeed = Speed\n"};
  const int variant = (int) (text.size() % 4);
  const granpen::ImportMapping m = granpen::parse_import_mapping(mappings[variant], "fuzz.map", false);
  const std::string path = "/tmp/granpen_fuzz_instrument_" + std::to_string(::getpid()) + ".csv";
  {
    std::ofstream o(path, std::ios::binary);
    o << text;
    GRANPEN_FUZZ_CHECK(o.good());
  }
  try {
    granpen::InstrumentReader r(path, m);
    std::vector<granpen::ImportRow> rows;
    long last = 0;
    while (r.next(rows))
      for (const auto &row : rows) {
        GRANPEN_FUZZ_CHECK(std::isfinite(row.F));
        if (m.position.given()) GRANPEN_FUZZ_CHECK(std::isfinite(row.x));
        if (m.time.given()) GRANPEN_FUZZ_CHECK(std::isfinite(row.t));
        GRANPEN_FUZZ_CHECK(row.line > last);
        last = row.line;
      }
    GRANPEN_FUZZ_CHECK(text.find('\0') == std::string::npos);
    std::size_t longest = 0, start = 0;
    for (std::size_t nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1)
      longest = std::max(longest, nl - start);
    GRANPEN_FUZZ_CHECK(std::max(longest, text.size() - start) <= granpen::kMaxInstrumentLine);
  } catch (granpen::InputError &e) {
    GRANPEN_FUZZ_CHECK(std::string(e.what()).compare(0, path.size(), path) == 0);    // the file named
  }
  std::remove(path.c_str());
}

}    // namespace granpen_fuzz

#endif
