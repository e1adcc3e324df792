// granpen analysis: values of a JSON document by key path, for `granpen get` and for the
// code that reads granpen's own JSON outputs back (the gap selftest's scorer). A script asks
// for "heldout.gap_before" instead of matching the text's layout, so the writer is free to
// format the JSON as it likes.
//
// A path is a chain of steps, each a member name or a bracket:
//   heldout.gap_before                    a member of a member
//   per_speed[0].v0                       an array element by index (from 0)
//   detection_limits[effect=cohesion]     the first element whose member `effect` is "cohesion"
//                                         (a string compared as text, a number as its JSON text)
//   traces[*].peak                        every element (each gives one value)
// Member names are any characters but '.', '[' and ']'.
#ifndef GRANPEN_JSON_PATH_H
#define GRANPEN_JSON_PATH_H

#include "json_writer.h"    // Json

#include <string>
#include <vector>

namespace granpen {

struct JsonPathStep {
  enum Kind { member, index, match, every };
  Kind kind = member;
  std::string name;       // member: the name; match: the element's member compared
  std::string value;      // match: the value it must have
  std::size_t at = 0;     // index
};

// The steps of path. Throws InputError "key path 'P': ..." for an empty path, an empty
// step, an unclosed or empty bracket, or an index that is not a whole number.
std::vector<JsonPathStep> parse_json_path(const std::string &path);

// What a path found: one value, or one per element for each [*] step, in document order;
// a null pointer where the path leads nowhere (a missing member, an index past the end, no
// matching element, a step into a value that is not an object or array), and then
// `missing` says why for the first such place, naming the path walked so far
// ("no member 'x' in 'heldout'").
struct JsonLookup {
  std::vector<const Json *> values;
  std::string missing;
  bool complete() const { return missing.empty(); }
};

// The values of doc at path (parse_json_path's InputError for a malformed path). They point
// into doc, so doc must outlive them (a temporary is refused at compile time).
JsonLookup json_lookup(const Json &doc, const std::string &path);
JsonLookup json_lookup(const Json &&doc, const std::string &path) = delete;

// A value as a script reads it: a string without its quotes, a number as its JSON text
// (what the writer wrote), true, false, null, an object or array as compact JSON.
std::string json_value_text(const Json &v);

// A JSON file, parsed. Throws InputError "PATH: cannot read it" or
// "PATH:LINE:COLUMN: not JSON (...)" naming where the text stops being JSON.
Json read_json_file(const std::string &path);

}    // namespace granpen

#endif
