/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: what the line-oriented text readers share (io/trace_reader.cpp,
   io/csv_table.cpp, io/bed_info.cpp, sweep/sweep_spec.cpp): trimming, splitting,
   reading a whole file, and the "FILE:LINE: what" rejection they all throw.
------------------------------------------------------------------------- */

#ifndef GRANPEN_TEXT_UTIL_H
#define GRANPEN_TEXT_UTIL_H

#include <cstddef>
#include <iosfwd>
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
// opened (errno as the failed open left it). A path that is not a regular file is an
// InputError (require_regular_file).
bool read_text_file(const std::string &path, std::string &text);

// Throws InputError "PATH: a FIFO, not a regular file ..." (or a folder, a device, a
// socket) when path exists and is not a regular file (symbolic links followed): opening a
// FIFO waits for a writer forever, and a folder or a device is no input. A path that does
// not exist passes: its open fails and says so. Called before every open of an input.
void require_regular_file(const std::string &path);

// The next line of in, without its '\n', into line; false at the end of the input. Read in
// pieces of buf (the caller's scratch, its size the piece), so memory does not grow with a
// line: a line longer than max_line bytes is an InputError "NAME:LINE: line longer than
// MAX bytes: WHAT", and so is a NUL byte in it (a binary file or UTF-16 text: strtod and
// the field splitters would stop at it and read a field's first part). lineno: the lines
// read before this one.
bool read_bounded_line(std::istream &in, std::vector<char> &buf, std::string &line, const std::string &name,
                       long lineno, std::size_t max_line, const char *what);

// s without a leading UTF-8 byte-order mark (EF BB BF), which some programs write at the
// start of a text file and which would otherwise be part of the first name or key.
std::string without_bom(const std::string &s);

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
