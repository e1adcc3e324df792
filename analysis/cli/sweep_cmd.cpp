// granpen sweep: placeholder until implemented (prints an error, exit 2).
#include "subcommands.h"

#include <cstdio>

int granpen::cli::sweep(int, char **)
{
  std::fprintf(stderr, "granpen sweep: not implemented yet\n");
  return 2;
}
