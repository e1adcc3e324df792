// libFuzzer target: granpen::InstrumentReader (granpen import's reader of a lab's
// delimited files) on arbitrary bytes, under four mappings.
#include "fuzz_instrument_body.h"

#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  granpen_fuzz::instrument_body(std::string(reinterpret_cast<const char *>(data), size));
  return 0;
}
