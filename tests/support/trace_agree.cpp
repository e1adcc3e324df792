// trace_agree A.csv B.csv [--rtol R] [--min-rows N]
// Exit 0 when every row of B whose t matches a row of A agrees with it:
// |z_A - z_B| <= 1e-9 cm and |F_A - F_B| <= R * max|F_A| (R default 1e-12),
// with at least N (default 10) matched rows. Prints the largest deviations.
#include "trace_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

int main(int argc, char **argv)
{
  if (argc < 3) {
    std::fprintf(stderr, "usage: trace_agree A.csv B.csv [--rtol R] [--min-rows N]\n");
    return 2;
  }
  double rtol = 1e-12;
  std::size_t min_rows = 10;
  for (int i = 3; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--rtol")) rtol = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--min-rows")) min_rows = std::atol(argv[i + 1]);
    else {
      std::fprintf(stderr, "trace_agree: unknown option %s\n", argv[i]);
      return 2;
    }
  }
  try {
    auto a = granpen::read_trace(argv[1]);
    auto b = granpen::read_trace(argv[2]);
    double fscale = 0.0;
    for (double f : a.F) fscale = std::max(fscale, std::fabs(f));
    std::size_t matched = 0, ia = 0;
    double dz = 0.0, df = 0.0;
    for (std::size_t ib = 0; ib < b.t.size(); ++ib) {
      while (ia < a.t.size() && a.t[ia] < b.t[ib] - 1e-9 * std::max(1e-6, b.t[ib])) ++ia;
      if (ia == a.t.size()) break;
      if (std::fabs(a.t[ia] - b.t[ib]) > 1e-9 * std::max(1e-6, b.t[ib])) continue;
      ++matched;
      dz = std::max(dz, std::fabs(a.z[ia] - b.z[ib]));
      df = std::max(df, std::fabs(a.F[ia] - b.F[ib]));
    }
    const double rel = fscale > 0.0 ? df / fscale : df;
    std::printf("trace_agree: %zu matched rows, max |dz| = %.3g, max |dF| = %.3g (%.3g of max |F| = %.6g), rtol %.3g\n",
                matched, dz, df, rel, fscale, rtol);
    if (matched < min_rows) {
      std::printf("trace_agree: FAIL: fewer than %zu matched rows\n", min_rows);
      return 1;
    }
    if (dz > 1e-9 || rel > rtol) {
      std::printf("trace_agree: FAIL\n");
      return 1;
    }
    std::printf("trace_agree: OK\n");
    return 0;
  } catch (granpen::InputError &e) {
    std::fprintf(stderr, "trace_agree: %s\n", e.what());
    return 2;
  }
}
