// granpen analysis: two pieces of JSON text: a string literal with escapes, and a number
// that is always valid JSON. The documents themselves are built with nlohmann::json and
// written by json_writer.h, which writes its numbers with json_number.
#ifndef GRANPEN_JSON_TEXT_H
#define GRANPEN_JSON_TEXT_H

#include <string>

namespace granpen {

// A JSON string literal: quotes, backslashes and control characters escaped; valid
// UTF-8 passes through, invalid bytes become U+FFFD.
std::string json_string(const std::string &s);

// A number printed with the printf format f; non-finite values (not valid JSON) as 0.
std::string json_number(const char *f, double v);

}    // namespace granpen

#endif
