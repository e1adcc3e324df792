// granpen: LAMMPS's -h text with the GRANPEN styles added (see help_styles.h).
#include "help_styles.h"

#include <algorithm>
#include <sstream>

namespace granpen {
namespace {

std::vector<std::string> split_lines(const std::string &text)
{
  std::vector<std::string> lines;
  std::string line;
  std::istringstream in(text);
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

// LAMMPS's print_style(): names in columns of 16, 32, ... characters, a new line past 80
void print_style(std::string &out, const std::string &name, int &pos)
{
  const int len = static_cast<int>(name.size());
  if (pos + len > 80) {
    out += "\n";
    pos = 0;
  }
  int width = 80;
  for (int w : {16, 32, 48, 64})
    if (len < w) {
      width = w;
      break;
    }
  out += name + std::string(static_cast<size_t>(std::max(0, width - len)), ' ');
  pos += width;
}

// The lines of the style list headed `title`: from the line after the title's blank line to
// the blank line that ends it. Appends `names`, continuing LAMMPS's layout.
void extend_list(std::vector<std::string> &lines, const std::string &title,
                 const std::vector<std::string> &names)
{
  if (names.empty()) return;
  auto head = std::find(lines.begin(), lines.end(), title);
  if (head == lines.end() || head + 1 == lines.end() || !(head + 1)->empty()) return;
  auto first = head + 2, last = first;
  while (last != lines.end() && !last->empty()) ++last;
  if (first == last) return;    // an empty list: leave the layout to LAMMPS
  // the last line of the list, re-laid: its names, then ours
  std::vector<std::string> tail_names;
  std::istringstream words(*(last - 1));
  std::string w;
  while (words >> w) tail_names.push_back(w);
  for (const auto &n : names) tail_names.push_back(n);
  std::string text;
  int pos = 0;
  for (const auto &n : tail_names) print_style(text, n, pos);
  auto relaid = split_lines(text);
  auto at = lines.erase(last - 1);
  lines.insert(at, relaid.begin(), relaid.end());
}

// "Installed packages:" then a blank line, then names wrapped at 78 columns
void add_package(std::vector<std::string> &lines, const std::string &package)
{
  auto head = std::find(lines.begin(), lines.end(), "Installed packages:");
  if (head == lines.end() || head + 1 == lines.end()) return;
  auto first = head + 2, last = first;
  while (last != lines.end() && !last->empty()) ++last;
  std::vector<std::string> pkgs;
  for (auto it = first; it != last; ++it) {
    std::istringstream words(*it);
    std::string w;
    while (words >> w) pkgs.push_back(w);
  }
  if (std::find(pkgs.begin(), pkgs.end(), package) != pkgs.end()) return;
  pkgs.insert(std::upper_bound(pkgs.begin(), pkgs.end(), package), package);
  std::vector<std::string> relaid(1);
  size_t ncline = 0;
  for (const auto &p : pkgs) {
    if (ncline + p.size() > 78) {
      relaid.emplace_back();
      ncline = 0;
    }
    relaid.back() += p + " ";
    ncline += p.size() + 1;
  }
  auto at = lines.erase(first, last);
  lines.insert(at, relaid.begin(), relaid.end());
}

}    // namespace

std::string add_styles_to_help(const std::string &help, const std::string &package,
                               const HelpStyles &styles)
{
  auto lines = split_lines(help);
  add_package(lines, package);
  extend_list(lines, "* Fix styles", styles.fixes);
  extend_list(lines, "* Compute styles:", styles.computes);
  extend_list(lines, "* Command styles", styles.commands);
  std::string out;
  for (const auto &l : lines) out += l + "\n";
  if (!help.empty() && help.back() != '\n' && !out.empty()) out.pop_back();
  return out;
}

}    // namespace granpen
