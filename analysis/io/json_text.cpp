// granpen analysis: JSON text helpers (see json_text.h).
#include "json_text.h"

#include <cmath>
#include <cstdio>

namespace granpen {

std::string json_string(const std::string &s)
{
  std::string o = "\"";
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = (unsigned char) s[i];
    if (c == '"') o += "\\\"";
    else if (c == '\\') o += "\\\\";
    else if (c == '\n') o += "\\n";
    else if (c == '\r') o += "\\r";
    else if (c == '\t') o += "\\t";
    else if (c == '\b') o += "\\b";
    else if (c == '\f') o += "\\f";
    else if (c < 0x20 || c == 0x7f) {
      char u[8];
      std::snprintf(u, sizeof u, "\\u%04x", (unsigned) c);
      o += u;
    }
    else if (c < 0x80) o += (char) c;
    else {
      // a valid UTF-8 sequence passes through
      const std::size_t len = (c >= 0xf0 && c <= 0xf4) ? 4 : (c >= 0xe0 && c <= 0xef) ? 3 : (c >= 0xc2 && c <= 0xdf) ? 2 : 0;
      bool ok = len && i + len <= s.size();
      for (std::size_t k = 1; ok && k < len; ++k) ok = ((unsigned char) s[i + k] & 0xc0) == 0x80;
      if (ok) {    // no overlong forms, surrogates or code points above U+10FFFF
        const unsigned char c1 = (unsigned char) s[i + 1];
        ok = !(c == 0xe0 && c1 < 0xa0) && !(c == 0xed && c1 >= 0xa0) && !(c == 0xf0 && c1 < 0x90) &&
             !(c == 0xf4 && c1 >= 0x90);
      }
      if (ok) {
        o.append(s, i, len);
        i += len;
        continue;
      }
      o += "\\ufffd";
    }
    ++i;
  }
  return o + "\"";
}

std::string json_number(const char *f, double v)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, f, std::isfinite(v) ? v : 0.0);
  return buf;
}

}    // namespace granpen
