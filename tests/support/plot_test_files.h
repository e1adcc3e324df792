// Files for the tests of the figures (tests/analysis/io/test_plot_writer.cpp, the library;
// tests/analysis/cli/test_plot.cpp, granpen plot): fresh folders, a file's bytes, PNG and
// SVG recognised by their first bytes, and the numbers of one block of a gnuplot .dat file.
#ifndef GRANPEN_TEST_PLOT_TEST_FILES_H
#define GRANPEN_TEST_PLOT_TEST_FILES_H

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace plot_test {

namespace fs = std::filesystem;

// root/name, emptied
inline fs::path fresh_folder(const fs::path &root, const std::string &name)
{
  const fs::path d = root / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// a file's bytes
inline std::string slurp(const fs::path &p)
{
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// a file written, its folders made
inline void write(const fs::path &p, const std::string &text)
{
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

// gnuplot with the PNG and SVG terminals is installed
inline bool have_gnuplot()
{
  static const bool yes = std::system("gnuplot -e 'set terminal pngcairo; set terminal svg' >/dev/null 2>&1") == 0;
  return yes;
}

inline bool non_empty(const std::string &p)
{
  std::error_code ec;
  return fs::file_size(p, ec) > 0 && !ec;
}

inline bool is_png(const std::string &p) { return slurp(p).compare(0, 8, "\x89PNG\r\n\x1a\n") == 0; }

inline bool is_svg(const std::string &p) { return slurp(p).find("<svg") != std::string::npos; }

// the numeric rows of data block `index` of a .dat file
inline std::vector<std::vector<double>> block(const fs::path &dat, int index)
{
  std::istringstream in(slurp(dat));
  std::string line;
  std::vector<std::vector<double>> rows;
  int current = -1;
  while (std::getline(in, line)) {
    if (line.rfind("# index ", 0) == 0) {
      current = std::atoi(line.c_str() + 8);
      continue;
    }
    if (current != index || line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::vector<double> row;
    std::string cell;
    while (ls >> cell) row.push_back(cell == "NaN" ? NAN : std::strtod(cell.c_str(), nullptr));
    rows.push_back(row);
  }
  return rows;
}

}    // namespace plot_test

#endif
