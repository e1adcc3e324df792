// granpen analysis: shared helpers of the text readers (see text_util.h).
#include "text_util.h"
#include "errors.h"

#include <cstdarg>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace granpen {

std::string trim(const std::string &s)
{
  const char *ws = " \t\r";
  const auto a = s.find_first_not_of(ws);
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(ws);
  return s.substr(a, b - a + 1);
}

std::vector<std::string> split(const std::string &s, char sep)
{
  std::vector<std::string> out;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, sep)) out.push_back(cur);
  if (!s.empty() && s.back() == sep) out.emplace_back();
  return out;
}

std::vector<std::string> words(const std::string &s)
{
  std::istringstream in(s);
  std::vector<std::string> out;
  std::string w;
  while (in >> w) out.push_back(w);
  return out;
}

bool read_text_file(const std::string &path, std::string &text)
{
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  std::ostringstream ss;
  ss << f.rdbuf();
  text = ss.str();
  return true;
}

std::string format_text(const char *f, ...)
{
  va_list ap, again;
  va_start(ap, f);
  va_copy(again, ap);
  const int n = std::vsnprintf(nullptr, 0, f, ap);
  va_end(ap);
  std::string out(n > 0 ? (std::size_t) n : 0, '\0');
  if (n > 0) std::vsnprintf(out.data(), out.size() + 1, f, again);
  va_end(again);
  return out;
}

std::string printf_number(const char *f, double v)
{
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

std::string file_line(const std::string &file, long line) { return file + ":" + std::to_string(line); }

void fail_at(const std::string &file, long line, const std::string &what)
{
  throw InputError(file_line(file, line) + ": " + what);
}

}    // namespace granpen
