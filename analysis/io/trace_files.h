// granpen analysis: the trace files named on a command line: files as given, folders
// expanded into their *.csv files (sorted). Problems are returned, not thrown, so the
// other inputs are still used.
#ifndef GRANPEN_TRACE_FILES_H
#define GRANPEN_TRACE_FILES_H

#include <string>
#include <vector>

namespace granpen {

std::vector<std::string> expand_trace_paths(const std::vector<std::string> &inputs,
                                            std::vector<std::string> &problems);

}    // namespace granpen

#endif
