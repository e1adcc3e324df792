// granpen analysis: an instrument's delimited text file (a DAQ's, a materials tester's, a
// penetrometer's export) read row by row in chunks, as a mapping (import_mapping.h) says:
// comma, semicolon, tab or white-space delimited, or rows of key=value pairs; a decimal
// point or comma; any number of header lines before the column names (found when not
// given). Rows come out in the trace's units with the mapping's signs. Memory does not
// grow with the file: a chunk of rows at a time. Rejections name the file and line.
#ifndef GRANPEN_INSTRUMENT_READER_H
#define GRANPEN_INSTRUMENT_READER_H

#include "import_mapping.h"
#include "instrument_import.h"

#include <fstream>
#include <string>
#include <vector>

namespace granpen {

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

 private:
  enum class Delim { comma, semicolon, tab, whitespace, keyvalue };
  bool read_line(std::string &line);
  void find_layout();
  std::vector<std::string> fields(const std::string &line, Delim d) const;
  // the mapped columns' positions in the names line; false (missing set) when one is absent
  bool locate(const std::vector<std::string> &names, std::string &missing);
  bool parse_number(const std::string &field, double &v) const;
  bool numeric_row(const std::string &line, Delim d) const;
  ImportRow to_row(const std::string &line, long line_no);
  double field_value(const std::vector<std::string> &f, int index, const ColumnRef &c, const char *what,
                     long line_no) const;
  double key_value(const std::string &line, const ColumnRef &c, const char *what, long line_no) const;

  std::string path_;
  ImportMapping m_;
  std::ifstream in_;
  long line_no_ = 0;
  Delim delim_ = Delim::comma;
  long header_lines_ = 0;             // lines before the names line (or the first data row)
  long names_line_ = 0;               // 0: no names line
  int i_time_ = -1, i_force_ = -1, i_position_ = -1, i_speed_ = -1;    // 0-based fields
  std::string pending_;               // a data line read while finding the layout
  long pending_no_ = 0;
  std::size_t rows_ = 0;              // data rows so far (the sample index without a time column)
};

}    // namespace granpen

#endif
