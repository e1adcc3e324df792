// libFuzzer target: granpen::DumpReader on arbitrary bytes, written to a temporary
// file (the reader's public API reads files; plain or gzip is detected by its bytes).
#include "fuzz_bodies.h"

#include <cstdint>
#include <cstdio>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  struct TempFile {
    std::string path;
    TempFile()
    {
      const char *dir = std::getenv("TMPDIR");
      path = std::string(dir && *dir ? dir : "/tmp") + "/granpen_fuzz_dump_" + std::to_string(getpid()) + ".dump";
    }
    ~TempFile() { std::remove(path.c_str()); }
  };
  static const TempFile tmp;
  const std::string &path = tmp.path;
  FILE *f = std::fopen(path.c_str(), "wb");
  if (!f) std::abort();
  if (size && std::fwrite(data, 1, size, f) != size) std::abort();
  if (std::fclose(f) != 0) std::abort();
  granpen_fuzz::dump_body(path, size);
  return 0;
}
