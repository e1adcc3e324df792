// granpen analysis: trace paths from files and folders (see trace_files.h).
#include "trace_files.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace granpen {

std::vector<std::string> expand_paths(const std::vector<std::string> &inputs,
                                      const std::function<bool(const fs::directory_entry &)> &keep,
                                      const std::string &none_kept, std::vector<std::string> &problems)
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
      if (keep(e)) found.push_back(e.path().string());
    if (ec) {
      problems.push_back(in + ": cannot list folder: " + ec.message());
      continue;
    }
    std::sort(found.begin(), found.end());
    if (found.empty()) problems.push_back(in + ": " + none_kept);
    files.insert(files.end(), found.begin(), found.end());
  }
  return files;
}

std::vector<std::string> expand_trace_paths(const std::vector<std::string> &inputs,
                                            std::vector<std::string> &problems)
{
  return expand_paths(
      inputs,
      [](const fs::directory_entry &e) {
        std::error_code ec;
        return e.path().extension() == ".csv" && e.path().filename() != kImportSummaryName && e.is_regular_file(ec);
      },
      "folder holds no *.csv file", problems);
}

}    // namespace granpen
