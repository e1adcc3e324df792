// granpen analysis: the JSON writer (see json_writer.h).
#include "json_writer.h"

#include "atomic_file.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace granpen {

namespace {

// an array of objects: a table, one row per line
bool is_table(const Json &j)
{
  if (!j.is_array() || j.empty()) return false;
  for (const auto &e : j)
    if (!e.is_object()) return false;
  return true;
}

void put(const Json &j, int depth, int open_levels, std::string &o)
{
  const bool open = depth < open_levels || (depth == open_levels && is_table(j));
  const std::string pad(2 * (depth + 1), ' '), end_pad(2 * depth, ' ');
  if (j.is_object() && !j.empty()) {
    o += '{';
    bool first = true;
    for (auto it = j.begin(); it != j.end(); ++it) {
      o += first ? "" : ",";
      o += open ? "\n" + pad : (first ? "" : " ");
      o += Json(it.key()).dump(-1, ' ', false, Json::error_handler_t::replace) + ": ";
      put(it.value(), depth + 1, open_levels, o);
      first = false;
    }
    o += open ? "\n" + end_pad + "}" : "}";
  } else if (j.is_array() && !j.empty()) {
    o += '[';
    bool first = true;
    for (const auto &e : j) {
      o += first ? "" : ",";
      o += open ? "\n" + pad : (first ? "" : " ");
      put(e, depth + 1, open_levels, o);
      first = false;
    }
    o += open ? "\n" + end_pad + "]" : "]";
  } else {
    // invalid UTF-8 in a string becomes U+FFFD rather than an exception
    o += j.dump(-1, ' ', false, Json::error_handler_t::replace);
  }
}

}    // namespace

Json json_rounded(const char *f, double v)
{
  if (!std::isfinite(v)) return 0;
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  const double r = std::strtod(buf, nullptr);
  // below 2^53 every whole double is an exact integer
  if (r == std::floor(r) && std::fabs(r) < 9.0e15) return (long long) r;
  return r;
}

std::string json_layout(const Json &j, int open_levels)
{
  std::string o;
  put(j, 0, open_levels, o);
  return o + "\n";
}

void write_json(const std::string &path, const Json &j, int open_levels)
{
  write_file_atomic(path, json_layout(j, open_levels));
}

}    // namespace granpen
