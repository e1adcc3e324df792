// granpen analysis: trace paths from files and folders (see trace_files.h).
#include "trace_files.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace granpen {

std::vector<std::string> expand_trace_paths(const std::vector<std::string> &inputs,
                                            std::vector<std::string> &problems)
{
  std::vector<std::string> files;
  for (const auto &in : inputs) {
    std::error_code ec;
    if (!fs::is_directory(in, ec)) {
      files.push_back(in);
      continue;
    }
    std::vector<std::string> found;
    for (const auto &e : fs::directory_iterator(in, ec))
      if (e.path().extension() == ".csv" && e.is_regular_file(ec)) found.push_back(e.path().string());
    if (ec) {
      problems.push_back(in + ": cannot list folder: " + ec.message());
      continue;
    }
    std::sort(found.begin(), found.end());
    if (found.empty()) problems.push_back(in + ": folder holds no *.csv file");
    files.insert(files.end(), found.begin(), found.end());
  }
  return files;
}

}    // namespace granpen
