// granpen analysis: values of a JSON document by key path (see json_path.h).
#include "json_path.h"

#include "errors.h"
#include "text_util.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace granpen {

namespace {

[[noreturn]] void bad_path(const std::string &path, const std::string &why)
{
  throw InputError("key path '" + path + "': " + why);
}

// the bracket's text at path[open + 1, close) as a step
JsonPathStep bracket_step(const std::string &path, const std::string &inside)
{
  JsonPathStep s;
  if (inside.empty()) bad_path(path, "an empty []");
  if (inside == "*") {
    s.kind = JsonPathStep::every;
    return s;
  }
  const auto eq = inside.find('=');
  if (eq != std::string::npos) {
    s.kind = JsonPathStep::match;
    s.name = inside.substr(0, eq);
    s.value = inside.substr(eq + 1);
    if (s.name.empty()) bad_path(path, "[" + inside + "] names no member to compare");
    return s;
  }
  if (inside.find_first_not_of("0123456789") != std::string::npos)
    bad_path(path, "[" + inside + "] is not an index (a whole number from 0), [*] or [member=value]");
  errno = 0;
  const unsigned long long i = std::strtoull(inside.c_str(), nullptr, 10);
  if (errno == ERANGE) bad_path(path, "[" + inside + "] is too large an index");
  s.kind = JsonPathStep::index;
  s.at = static_cast<std::size_t>(i);
  return s;
}

// the path's text up to step k, for the messages: "heldout", "per_speed[0]"
std::string walked(const std::vector<JsonPathStep> &steps, std::size_t k)
{
  std::string o;
  for (std::size_t i = 0; i < k; ++i) {
    const auto &s = steps[i];
    switch (s.kind) {
    case JsonPathStep::member: o += (o.empty() ? "" : ".") + s.name; break;
    case JsonPathStep::index: o += "[" + std::to_string(s.at) + "]"; break;
    case JsonPathStep::match: o += "[" + s.name + "=" + s.value + "]"; break;
    case JsonPathStep::every: o += "[*]"; break;
    }
  }
  return o.empty() ? "the document" : "'" + o + "'";
}

const char *type_word(const Json &v)
{
  if (v.is_object()) return "an object";
  if (v.is_array()) return "an array";
  if (v.is_string()) return "a string";
  if (v.is_boolean()) return "a boolean";
  if (v.is_null()) return "null";
  return "a number";
}

// step k applied to v: the values it leads to, or why it leads nowhere
std::string apply(const std::vector<JsonPathStep> &steps, std::size_t k, const Json &v, std::vector<const Json *> &out)
{
  const auto &s = steps[k];
  const std::string where = walked(steps, k);
  if (s.kind == JsonPathStep::member) {
    if (!v.is_object()) return where + " is " + type_word(v) + ", not an object with member '" + s.name + "'";
    const auto it = v.find(s.name);
    if (it == v.end()) return "no member '" + s.name + "' in " + where;
    out.push_back(&*it);
    return "";
  }
  if (!v.is_array()) return where + " is " + type_word(v) + ", not an array";
  if (s.kind == JsonPathStep::index) {
    if (s.at >= v.size())
      return "index " + std::to_string(s.at) + " past the end of " + where + " (" + std::to_string(v.size()) + " elements)";
    out.push_back(&v[s.at]);
    return "";
  }
  if (s.kind == JsonPathStep::every) {
    for (const auto &e : v) out.push_back(&e);
    return "";
  }
  for (const auto &e : v) {
    if (!e.is_object()) continue;
    const auto it = e.find(s.name);
    if (it != e.end() && json_value_text(*it) == s.value) {
      out.push_back(&e);
      return "";
    }
  }
  return "no element of " + where + " with " + s.name + " = " + s.value;
}

// (line, column) from 1 of byte offset `at` in text
std::pair<std::size_t, std::size_t> line_column(const std::string &text, std::size_t at)
{
  std::size_t line = 1, col = 1;
  for (std::size_t i = 0; i < at && i < text.size(); ++i) {
    if (text[i] == '\n') ++line, col = 1;
    else ++col;
  }
  return {line, col};
}

}    // namespace

std::vector<JsonPathStep> parse_json_path(const std::string &path)
{
  if (path.empty()) bad_path(path, "empty");
  std::vector<JsonPathStep> steps;
  std::size_t i = 0;
  while (i < path.size()) {
    if (path[i] == '[') {
      const auto close = path.find(']', i);
      if (close == std::string::npos) bad_path(path, "a '[' without its ']'");
      steps.push_back(bracket_step(path, path.substr(i + 1, close - i - 1)));
      i = close + 1;
      continue;
    }
    if (i > 0) {    // after a step, a member name follows a '.'
      if (path[i] != '.') bad_path(path, "a member name right after ']' (a '.' between them)");
      ++i;
    }
    const auto end = path.find_first_of(".[]", i);
    JsonPathStep s;
    s.name = path.substr(i, end == std::string::npos ? std::string::npos : end - i);
    if (s.name.empty()) bad_path(path, "an empty member name");
    if (end != std::string::npos && path[end] == ']') bad_path(path, "a ']' without its '['");
    steps.push_back(s);
    i = end == std::string::npos ? path.size() : end;
  }
  return steps;
}

JsonLookup json_lookup(const Json &doc, const std::string &path)
{
  const auto steps = parse_json_path(path);
  JsonLookup r;
  std::vector<const Json *> at{&doc};
  for (std::size_t k = 0; k < steps.size(); ++k) {
    std::vector<const Json *> next;
    for (const Json *v : at) {
      if (!v) {
        next.push_back(nullptr);
        continue;
      }
      const std::string why = apply(steps, k, *v, next);
      if (why.empty()) continue;
      next.push_back(nullptr);
      if (r.missing.empty()) r.missing = why;
    }
    at.swap(next);
  }
  r.values = at;
  return r;
}

std::string json_value_text(const Json &v)
{
  if (v.is_string()) return v.get<std::string>();
  // invalid UTF-8 in a string becomes U+FFFD rather than an exception (as the writer)
  return v.dump(-1, ' ', false, Json::error_handler_t::replace);
}

Json read_json_file(const std::string &path)
{
  std::string text;
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": a folder, not a JSON file");
  if (!read_text_file(path, text)) throw InputError(path + ": cannot read it (" + std::strerror(errno) + ")");
  try {
    return Json::parse(text);
  } catch (const Json::parse_error &e) {
    const auto lc = line_column(text, e.byte > 0 ? e.byte - 1 : 0);
    // nlohmann's text less its "[json.exception.parse_error.N] parse error at ...: " prefix
    std::string why = e.what();
    const auto colon = why.find(": ");
    if (colon != std::string::npos) why = why.substr(colon + 2);
    throw InputError(path + ":" + std::to_string(lc.first) + ":" + std::to_string(lc.second) + ": not JSON (" + why + ")");
  }
}

}    // namespace granpen
