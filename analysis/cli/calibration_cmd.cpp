// granpen calibration: placeholder until implemented (prints an error, exit 2).
#include "subcommands.h"

#include <cstdio>

int granpen::cli::calibration(int, char **)
{
  std::fprintf(stderr, "granpen calibration: not implemented yet\n");
  return 2;
}
