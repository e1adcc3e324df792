// granpen analysis: the little JSON the tools write by hand (no JSON library in the
// dependencies): string literals with escapes, numbers that are always valid JSON.
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
