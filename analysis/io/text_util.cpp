// granpen analysis: shared helpers of the text readers (see text_util.h).
#include "text_util.h"
#include "errors.h"

#include <cstdarg>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <sys/stat.h>

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
  require_regular_file(path);
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  std::ostringstream ss;
  ss << f.rdbuf();
  text = ss.str();
  return true;
}

void require_regular_file(const std::string &path)
{
  struct stat st;
  if (::stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return;
  const char *what = S_ISDIR(st.st_mode)    ? "a folder"
                     : S_ISFIFO(st.st_mode) ? "a FIFO (a named pipe: reading it would wait for a writer)"
                     : S_ISSOCK(st.st_mode) ? "a socket"
                     : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device"
                                                                   : "not a file";
  throw InputError(path + ": " + what + ", not a regular file");
}

bool read_bounded_line(std::istream &in, std::vector<char> &buf, std::string &line, const std::string &name,
                       long lineno, std::size_t max_line, const char *what)
{
  line.clear();
  if (in.eof()) return false;
  const auto too_long = [&]() {
    if (line.size() > max_line)
      fail_at(name, lineno + 1, "line longer than " + std::to_string(max_line) + " bytes: " + what);
  };
  bool more = true;
  while (more) {
    in.getline(buf.data(), (std::streamsize) buf.size());
    const std::streamsize n = in.gcount();    // with the '\n' when one was taken
    if (in.bad()) fail_at(name, lineno + 1, "read error");
    if (in.fail() && !in.eof()) {    // buf filled, the line goes on
      line.append(buf.data(), (std::size_t) n);
      too_long();
      in.clear();
      continue;
    }
    if (n == 0 && in.eof()) {
      if (line.empty()) return false;
      break;
    }
    line.append(buf.data(), (std::size_t) (in.eof() ? n : n - 1));
    too_long();
    more = false;
  }
  const auto nul = line.find('\0');
  if (nul != std::string::npos)
    fail_at(name, lineno + 1, "a NUL byte at byte " + std::to_string(nul + 1) +
                                  " of the line (a binary file, or text in UTF-16?): " + what);
  return true;
}

std::string without_bom(const std::string &s)
{
  return s.compare(0, 3, "\xEF\xBB\xBF") == 0 ? s.substr(3) : s;
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
