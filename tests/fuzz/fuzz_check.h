// The fuzz targets' invariant check: a broken invariant prints what and where, and aborts
// (libFuzzer keeps the input as a crash; the gtest drivers die with the message).
#ifndef GRANPEN_FUZZ_CHECK_H
#define GRANPEN_FUZZ_CHECK_H

#include <cstdio>
#include <cstdlib>

#define GRANPEN_FUZZ_CHECK(cond)                                                                    \
  do {                                                                                              \
    if (!(cond)) {                                                                                  \
      std::fprintf(stderr, "fuzz invariant broken: %s (%s:%d)\n", #cond, __FILE__, __LINE__);       \
      std::abort();                                                                                 \
    }                                                                                               \
  } while (0)

#endif
