// granpen analysis: the one JSON writer. Results are built as nlohmann::ordered_json (key
// order as inserted) and written here, laid out for a person reading the file: one member
// per line down to a given depth, deeper objects and arrays on one line ("a": 1, "b": 2).
// The layout is no contract: scripts ask for values by key path (`granpen get FILE KEY`,
// io/json_path.h), and tests/architecture/json_in_scripts.sh fails on a script that greps
// the text. (It is kept, not nlohmann's dump(2), because the committed outputs under
// docs/results are this layout: a change would rewrite every one of them.)
#ifndef GRANPEN_JSON_WRITER_H
#define GRANPEN_JSON_WRITER_H

#include <nlohmann/json.hpp>

#include <string>

namespace granpen {

using Json = nlohmann::ordered_json;

// v as a JSON number rounded to the printf format f ("%.6g"): the text nlohmann writes for
// it is then the shortest one that reads back as that rounded value (for "%.6g", six
// significant digits or fewer), a whole value as an integer (25300, not 25300.0), as
// printf wrote it. Non-finite values (not valid JSON) become 0, as json_text.h's
// json_number writes them.
Json json_rounded(const char *f, double v);

// j as text: members (and array elements) each on its own line, indented by 2, for the
// first `open_levels` levels, and one more level for an array of objects (a table: one
// row per line); anything deeper on one line. A trailing newline.
std::string json_layout(const Json &j, int open_levels = 1);

// json_layout(j, open_levels) into path through write_file_atomic (throws OutputError).
void write_json(const std::string &path, const Json &j, int open_levels = 1);

}    // namespace granpen

#endif
