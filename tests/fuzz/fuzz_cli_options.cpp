// libFuzzer target: every granpen subcommand's option parser (analysis/cli/options.h) on
// argument vectors made of arbitrary bytes, one word a line (fuzz_cli_body.h).
#include "fuzz_cli_body.h"

#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  granpen_fuzz::cli_body(std::string(reinterpret_cast<const char *>(data), size));
  return 0;
}
