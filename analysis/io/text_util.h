/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: what the line-oriented text readers share (io/trace_reader.cpp,
   io/csv_table.cpp, io/bed_info.cpp, sweep/sweep_spec.cpp): trimming, splitting,
   reading a whole file, and the "FILE:LINE: what" rejection they all throw.
------------------------------------------------------------------------- */

#ifndef GRANPEN_TEXT_UTIL_H
#define GRANPEN_TEXT_UTIL_H

#include <string>
#include <vector>

namespace granpen {

// s without leading and trailing blanks, tabs and carriage returns
std::string trim(const std::string &s);

// s cut at every sep, fields untrimmed: "a,,b" -> {a, "", b}; a trailing sep ends with an
// empty field; "" -> {}
std::vector<std::string> split(const std::string &s, char sep);

// the white-space separated words of s
std::vector<std::string> words(const std::string &s);

// The whole file at path (binary) into text; false, text untouched, when it cannot be
// opened (errno as the failed open left it).
bool read_text_file(const std::string &path, std::string &text);

// One number through printf's format f ("%.3f", "%g", ...), non-finite values as printf
// writes them (json_text.h's json_number is the JSON-safe variant).
std::string printf_number(const char *f, double v);

// printf's format f with its arguments, as a string.
std::string format_text(const char *f, ...) __attribute__((format(printf, 1, 2)));

// "FILE:LINE"
std::string file_line(const std::string &file, long line);

// Throws InputError (trace_reader.h) "FILE:LINE: WHAT".
[[noreturn]] void fail_at(const std::string &file, long line, const std::string &what);

}    // namespace granpen

#endif
