// granpen analysis: an instrument's delimited text file (a DAQ's, a materials tester's, a
// penetrometer's export) read row by row in chunks, as a mapping (import_mapping.h) says:
// comma, semicolon, tab or white-space delimited, or rows of key=value pairs; a decimal
// point or comma; any number of header lines before the column names (found when not
// given). Rows come out in the trace's units with the mapping's signs; t from the time
// column, the sample rate, the integral of dz / v (a depth-sampled log) or, without any,
// the row index. A field of a key=value row is named by its key or by its position
// (#N, also for a field without a key such as a logger's counter '%452304468'). Memory does not
// grow with the file: a chunk of rows at a time. Rejections name the file and line.
#ifndef GRANPEN_INSTRUMENT_READER_H
#define GRANPEN_INSTRUMENT_READER_H

#include "import_mapping.h"
#include "instrument_import.h"

#include <fstream>
#include <string>
#include <vector>

namespace granpen {

// The longest line of an instrument file (bytes): longer is an error naming it, so that one
// line never costs more memory than this (a chunk of rows is read at a time).
constexpr std::size_t kMaxInstrumentLine = std::size_t(1) << 20;

class InstrumentReader {
 public:
  // Opens path and finds its layout (delimiter, header lines, the mapped columns).
  // Throws InputError "PATH[:LINE]: ..." (unreadable, a mapped column missing, no data).
  InstrumentReader(const std::string &path, const ImportMapping &mapping);

  // The next rows (at most max_rows) into rows (cleared first); false when none are left.
  // Throws InputError "PATH:LINE: ..." (a mapped field that is not a number, too few
  // fields, a key missing from a key=value row).
  bool next(std::vector<ImportRow> &rows, std::size_t max_rows = 4096);

  // how the file was read, e.g. "semicolon-delimited, decimal comma, 3 header lines"
  std::string layout() const;

  // Where the data ended, once next() has returned false: the data end at the first line,
  // after at least one data row, whose mapped fields are not all numbers (a logger's
  // trailer, a footer, a summary); blank and '#' lines between rows are skipped. A data
  // row after that line is an InputError naming both lines.
  long last_data_line() const { return last_data_line_; }
  long trailer_line() const { return trailer_line_; }    // 0: the data run to the end of the file
  std::string trailer_text() const { return trailer_text_; }    // that line, trimmed, at most 60 characters

 private:
  enum class Delim { comma, semicolon, tab, whitespace, keyvalue };
  bool read_line(std::string &line);
  void find_layout();
  std::vector<std::string> fields(const std::string &line, Delim d) const;
  // the mapped columns' positions in the names line; false (missing set) when one is absent
  bool locate(const std::vector<std::string> &names, std::string &missing);
  bool parse_number(const std::string &field, double &v) const;
  bool numeric_row(const std::string &line, Delim d) const;
  // the row's values (parse_fields) in the trace's units, with its t
  ImportRow to_row(ImportRow raw, long line_no);
  // why the mapped columns of line are not all numbers ("" when they are), with the values
  // in r (raw: units not applied)
  // count_error (when given): why the row has more fields than the names line (or the first
  // data row without one) has, "" when it has not
  std::string parse_fields(const std::string &line, ImportRow &r, std::string *count_error = nullptr) const;
  std::string field_count_error(const std::vector<std::string> &f) const;
  // two of time, force, position and speed located at the same column: an InputError
  void refuse_shared_columns() const;
  // one mapped column's value from the row's fields; "" or why not
  std::string value_of(const std::vector<std::string> &f, Delim d, int index, const ColumnRef &c, const char *what,
                       double &v) const;

  std::string path_;
  ImportMapping m_;
  std::ifstream in_;
  std::vector<char> buf_ = std::vector<char>(64 * 1024);    // read_bounded_line's pieces
  long line_no_ = 0;
  Delim delim_ = Delim::comma;
  long header_lines_ = 0;             // lines before the names line (or the first data row)
  long names_line_ = 0;               // 0: no names line
  int i_time_ = -1, i_force_ = -1, i_position_ = -1, i_speed_ = -1;    // 0-based fields
  std::string pending_;               // a data line read while finding the layout
  long pending_no_ = 0;
  std::size_t row_fields_ = 0;        // fields of the names line (or the first data row); 0: key=value
  long first_row_line_ = 0;
  std::size_t rows_ = 0;              // data rows so far (the sample index without a time column)
  DepthClock clock_;                  // t of a depth-sampled log
  long last_data_line_ = 0, trailer_line_ = 0;
  std::string trailer_text_, trailer_why_;
};

}    // namespace granpen

#endif
