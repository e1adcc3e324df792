// libFuzzer target: granpen::parse_trace (granpen-trace v1) on arbitrary bytes.
#include "fuzz_bodies.h"

#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  granpen_fuzz::trace_body(std::string(reinterpret_cast<const char *>(data), size));
  return 0;
}
