// granpen analysis: the trace files named on a command line: files as given, folders
// expanded into their *.csv files (sorted). Problems are returned, not thrown, so the
// other inputs are still used.
#ifndef GRANPEN_TRACE_FILES_H
#define GRANPEN_TRACE_FILES_H

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace granpen {

// Files as given; a folder stands for its entries that `keep` accepts, sorted. A folder
// that cannot be listed, or keeps none ("FOLDER: " + none_kept), adds to problems.
std::vector<std::string> expand_paths(const std::vector<std::string> &inputs,
                                      const std::function<bool(const std::filesystem::directory_entry &)> &keep,
                                      const std::string &none_kept, std::vector<std::string> &problems);

// granpen import's table of the files it imported, written beside the traces: not a
// trace, so a folder's expansion leaves it out
constexpr const char *kImportSummaryName = "import_summary.csv";

// expand_paths for traces: a folder's regular *.csv files but kImportSummaryName
std::vector<std::string> expand_trace_paths(const std::vector<std::string> &inputs,
                                            std::vector<std::string> &problems);

}    // namespace granpen

#endif
