// granpen fit: placeholder until implemented (prints an error, exit 2).
#include "subcommands.h"

#include <cstdio>

int granpen::cli::fit(int, char **)
{
  std::fprintf(stderr, "granpen fit: not implemented yet\n");
  return 2;
}
