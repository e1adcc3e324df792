// granpen analysis: figures as gnuplot scripts with their data (see plot_writer.h).
#include "plot_writer.h"

#include "atomic_file.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <system_error>
#include <unistd.h>

namespace fs = std::filesystem;

namespace granpen {

// ---------------------------------------------------------------- text helpers

std::string gp_quote(const std::string &s)
{
  std::string o = "\"";
  for (char c : s) {
    if (c == '\\' || c == '"') o += '\\', o += c;
    else if (c == '\n') o += "\\n";
    else if (c == '\t') o += "\\t";
    else if (c == '\r') continue;
    else o += c;
  }
  return o + "\"";
}

std::string gp_literal(const std::string &s)
{
  std::string raw;
  for (char c : s) {
    if (std::strchr("_^@&~{}", c) && c) raw += '\\';
    raw += c;
  }
  return gp_quote(raw);
}

std::string gp_number(double v)
{
  if (!std::isfinite(v)) return "NaN";
  char b[40];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}

std::string plot_colour(int i)
{
  static const char *palette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                  "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"};
  const int n = sizeof palette / sizeof palette[0];
  return palette[((i % n) + n) % n];
}

std::string plot_shade(const std::string &colour, int j, int n)
{
  if (n <= 1 || colour.size() != 7 || colour[0] != '#') return colour;
  const long rgb = std::strtol(colour.c_str() + 1, nullptr, 16);
  const double t = std::min(1.0, std::max(0.0, double(j) / (n - 1)));
  const double f = -0.35 + 0.8 * t;    // < 0 towards black, > 0 towards white
  int c[3] = {int((rgb >> 16) & 255), int((rgb >> 8) & 255), int(rgb & 255)};
  for (int &v : c) v = f < 0 ? int(v * (1 + f) + 0.5) : int(v + (255 - v) * f + 0.5);
  char b[8];
  std::snprintf(b, sizeof b, "#%02x%02x%02x", c[0], c[1], c[2]);
  return b;
}

// ---------------------------------------------------------------- files

int PlotFiles::add_block(const PlotBlock &b)
{
  blocks.push_back(b);
  return static_cast<int>(blocks.size()) - 1;
}

namespace {

std::string data_text(const PlotFiles &f)
{
  std::ostringstream o;
  o << "# " << f.name << ".dat: data of " << f.name << ".gp (gnuplot data blocks: `index i` is block i)\n";
  for (std::size_t i = 0; i < f.blocks.size(); ++i) {
    const PlotBlock &b = f.blocks[i];
    o << (i ? "\n\n" : "\n") << "# index " << i;
    if (!b.title.empty()) {
      std::string t = b.title;
      std::replace(t.begin(), t.end(), '\n', ' ');
      o << ": " << t;
    }
    o << "\n";
    if (!b.columns.empty()) {
      o << "#";
      for (const auto &c : b.columns) o << " " << c;
      o << "\n";
    }
    for (const auto &r : b.rows) {
      for (std::size_t k = 0; k < r.size(); ++k) o << (k ? " " : "") << gp_number(r[k]);
      o << "\n";
    }
    if (b.rows.empty()) o << "# (no rows)\n";
  }
  return o.str();
}

std::string comment_lines(const std::string &text)
{
  std::string o;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) o += "# " + line + "\n";
  return o;
}

// last n non-empty lines of text, indented
std::string tail_lines(const std::string &text, std::size_t n)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string l;
  while (std::getline(in, l))
    if (l.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(l);
  std::string o;
  for (std::size_t i = lines.size() > n ? lines.size() - n : 0; i < lines.size(); ++i) o += "\n    " + lines[i];
  return o;
}

}    // namespace

std::string plot_script(const PlotFiles &f)
{
  std::ostringstream o;
  o << "# " << f.name << ".gp, written by granpen. The data are in " << f.name << ".dat beside it.\n";
  if (!f.about.empty()) o << comment_lines(f.about);
  o << "# Run in this folder: `gnuplot " << f.name << ".gp` makes " << f.name << ".png and " << f.name
    << ".svg;\n# `gnuplot -e \"formats='png'\" " << f.name << ".gp` makes only the PNG.\n"
    << "if (!exists(\"formats\")) formats = \"png svg\"\n"
    << "data = " << gp_quote(f.name + ".dat") << "\n"
    << "do for [fmt in formats] {\n"
    << "  if (fmt eq \"png\") {\n"
    << "    set terminal pngcairo enhanced size " << f.width << "," << f.height
    << " font \"sans,12\" background rgb \"white\"\n"
    << "  } else {\n"
    << "    if (fmt ne \"svg\") { print \"unknown format \", fmt, \" (png or svg)\"; exit status 1 }\n"
    << "    set terminal svg enhanced size " << f.width << "," << f.height
    << " font \"sans,12\" background rgb \"white\"\n"
    << "  }\n"
    << "  set output " << gp_quote(f.name + ".") << " . fmt\n"
    << "  reset\n  set encoding utf8\n";
  std::istringstream body(f.body);
  std::string line;
  while (std::getline(body, line)) o << (line.empty() ? "" : "  ") << line << "\n";
  o << "  unset multiplot\n  set output\n}\n";
  return o.str();
}

std::string run_gnuplot(const std::string &dir, const std::string &script, bool &missing)
{
  missing = false;
  const char *env = std::getenv("GRANPEN_GNUPLOT");
  std::string prog = env && *env ? env : "gnuplot", arg = script;
  std::vector<char *> args = {&prog[0], &arg[0], nullptr};
  int status_pipe[2], out_pipe[2];
  if (pipe(status_pipe) != 0) return std::string("pipe failed: ") + std::strerror(errno);
  if (pipe(out_pipe) != 0) {
    close(status_pipe[0]), close(status_pipe[1]);
    return std::string("pipe failed: ") + std::strerror(errno);
  }
  fcntl(status_pipe[1], F_SETFD, FD_CLOEXEC);
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = fork();
  if (pid < 0) {
    for (int fd : {status_pipe[0], status_pipe[1], out_pipe[0], out_pipe[1]}) close(fd);
    return std::string("fork failed: ") + std::strerror(errno);
  }
  if (pid == 0) {
    close(status_pipe[0]);
    close(out_pipe[0]);
    dup2(out_pipe[1], 1);
    dup2(out_pipe[1], 2);
    close(out_pipe[1]);
    const int devnull = open("/dev/null", O_RDONLY);
    if (devnull >= 0) dup2(devnull, 0);
    int msg[2] = {0, 0};    // {stage: 0 chdir, 1 exec; errno}
    if (chdir(dir.c_str()) != 0) msg[1] = errno;
    else {
      execvp(args[0], args.data());
      msg[0] = 1;
      msg[1] = errno;
    }
    if (write(status_pipe[1], msg, sizeof msg) < 0) {
    }
    _exit(127);
  }
  close(status_pipe[1]);
  close(out_pipe[1]);
  std::string output;
  char buf[4096];
  for (;;) {
    const ssize_t n = read(out_pipe[0], buf, sizeof buf);
    if (n > 0) output.append(buf, n);
    else if (n < 0 && errno == EINTR) continue;
    else break;
  }
  close(out_pipe[0]);
  int msg[2] = {0, 0};
  ssize_t got;
  do got = read(status_pipe[0], msg, sizeof msg);
  while (got < 0 && errno == EINTR);
  close(status_pipe[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (got == (ssize_t) sizeof msg) {
    if (msg[0] == 0) return "cannot enter " + dir + ": " + std::strerror(msg[1]);
    if (msg[1] == ENOENT) {
      missing = true;
      return prog + " not found" + (env && *env ? " (GRANPEN_GNUPLOT)" : " on PATH (Debian: apt-get install gnuplot-nox)");
    }
    return "cannot run " + prog + ": " + std::strerror(msg[1]);
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  std::string why = WIFEXITED(status) ? prog + " failed (exit status " + std::to_string(WEXITSTATUS(status)) + ")"
                                      : prog + " was killed by signal " + std::to_string(WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  const std::string t = tail_lines(output, 8);
  return t.empty() ? why : why + ", its last words:" + t;
}

PlotResult write_plot(const std::string &dir, const PlotFiles &f, bool run)
{
  PlotResult r;
  const fs::path d = dir.empty() ? fs::path(".") : fs::path(dir);
  r.script = (d / (f.name + ".gp")).string();
  r.data = (d / (f.name + ".dat")).string();
  r.png = (d / (f.name + ".png")).string();
  r.svg = (d / (f.name + ".svg")).string();
  if (f.name.empty() || f.name.find('/') != std::string::npos) {
    r.error = "figure name '" + f.name + "' is empty or holds a '/'";
    return r;
  }
  std::error_code ec;
  fs::create_directories(d, ec);
  if (ec) {
    r.error = "cannot create folder " + d.string() + ": " + ec.message();
    return r;
  }
  try {
    write_files_atomic({{r.data, data_text(f)}, {r.script, plot_script(f)}});
  } catch (const OutputError &e) {
    r.error = e.what();
    return r;
  }
  std::string why;
  r.written = true;
  if (!run) return r;
  fs::remove(r.png, ec);
  fs::remove(r.svg, ec);
  bool missing = false;
  why = run_gnuplot(d.string(), f.name + ".gp", missing);
  if (!why.empty()) {
    r.gnuplot_missing = missing;
    r.error = missing ? r.script + " not run: " + why + "; run `gnuplot " + f.name + ".gp` in " + d.string() +
                            " to make the figure"
                      : "gnuplot failed on " + r.script + ": " + why;
    return r;
  }
  for (const auto &img : {r.png, r.svg}) {
    const auto size = fs::file_size(img, ec);
    if (ec || size == 0) {
      r.error = "gnuplot ran " + r.script + " but made no " + img + (ec ? "" : " (empty file)");
      return r;
    }
  }
  r.ran = true;
  return r;
}

// ---------------------------------------------------------------- series figures

namespace {

std::string range(double lo, double hi)
{
  return "[" + (std::isfinite(lo) ? gp_number(lo) : std::string("*")) + ":" +
         (std::isfinite(hi) ? gp_number(hi) : std::string("*")) + "]";
}

std::string line_props(const std::string &colour, double lw, int dash)
{
  return "lw " + gp_number(lw) + " dt " + std::to_string(dash < 1 ? 1 : dash) + " lc rgb " + gp_quote(colour);
}

std::string title_of(const std::string &t) { return t.empty() ? "notitle" : "title " + gp_quote(t); }

// one line of a legend at key spacing 1.25 in the 12 pt font of plot_script, pixels
// (measured on pngcairo: 22 entries over 489 px)
constexpr double KEY_LINE_PX = 22.5;

bool has_data(const SeriesPanel &p)
{
  for (const auto &s : p.series)
    if (!s.x.empty() && !s.y.empty()) return true;
  return false;
}

int text_lines(const std::string &t) { return t.empty() ? 0 : 1 + (int) std::count(t.begin(), t.end(), '\n'); }

// the titles of a panel's legend, in the order gnuplot lists them (bands, band entries,
// series, guides)
std::vector<std::string *> key_titles(SeriesPanel &p)
{
  std::vector<std::string *> t;
  for (auto &s : p.series)
    if (!s.x.empty() && s.band_lo.size() == s.x.size() && !s.band_title.empty()) t.push_back(&s.band_title);
  for (auto &h : p.hbands)
    if (!h.title.empty()) t.push_back(&h.title);
  for (auto &s : p.series)
    if (!s.x.empty() && !s.title.empty()) t.push_back(&s.title);
  for (auto &g : p.guides)
    if (!g.title.empty()) t.push_back(&g.title);
  return t;
}

// a key-column legend longer than the column: its tail folded into one entry
void fold_key_column(std::vector<SeriesPanel> &panels, const SeriesFigure &fig, double top,
                     std::vector<std::string> &notes)
{
  double bottom = 0.02;
  for (const auto &p : panels)
    if (p.at_w > 0 && p.at_h > 0 && p.at_x + 1e-9 >= fig.grid_width) bottom = std::max(bottom, p.at_y + p.at_h + 0.01);
  const int room = (int) std::floor((top - bottom) / key_line_height(fig.height) + 1e-9);
  for (auto &p : panels) {
    if (p.key != "column") continue;
    auto titles = key_titles(p);
    const int fit = room - text_lines(p.key_title);
    if ((int) titles.size() <= fit) continue;
    const int keep = std::max(0, fit - 1), folded = (int) titles.size() - keep;
    for (int k = keep; k < (int) titles.size(); ++k) titles[k]->clear();
    PlotGuide more;
    more.expression = "keyentry";    // a legend line without a curve
    more.colour = "#ffffff";
    more.title = "+ " + std::to_string(folded) + " more not listed (drawn)";
    p.guides.push_back(more);
    notes.push_back(fig.name + ": the legend has room for " + std::to_string(std::max(0, fit)) + " of its " +
                    std::to_string(titles.size()) + " entries; " + std::to_string(folded) +
                    " folded into one \"more not listed\" entry");
  }
}

// the figure without its panels that have no data (a note for each), unless every panel
// is empty (then its "no data" panel stays)
SeriesFigure without_empty_panels(const SeriesFigure &in, std::vector<std::string> &notes)
{
  SeriesFigure fig = in;
  if (!std::any_of(in.panels.begin(), in.panels.end(), has_data)) return fig;
  fig.panels.clear();
  for (std::size_t i = 0; i < in.panels.size(); ++i) {
    if (has_data(in.panels[i])) fig.panels.push_back(in.panels[i]);
    else
      notes.push_back(in.name + ": panel " + std::to_string(i + 1) +
                      (in.panels[i].title.empty() ? "" : " (" + in.panels[i].title + ")") + " has no data: left out");
  }
  return fig;
}

}    // namespace

double key_line_height(int height_px) { return KEY_LINE_PX / (double) std::max(1, height_px); }

double key_column_top(const SeriesFigure &fig)
{
  const bool titled = !fig.title.empty();
  return (titled ? 0.94 : 1.0) - 0.04;
}

PlotFiles series_figure(const SeriesFigure &fig_in)
{
  PlotFiles f;
  f.name = fig_in.name;
  f.about = fig_in.about;
  f.width = fig_in.width;
  f.height = fig_in.height;
  SeriesFigure fig = without_empty_panels(fig_in, f.notes);

  int unplaced = 0;
  for (const auto &p : fig.panels)
    if (!(p.at_w > 0 && p.at_h > 0)) ++unplaced;
  const int cols = fig.columns > 0 ? fig.columns : std::max(1, unplaced);
  const int rows = std::max(1, (unplaced + cols - 1) / cols);
  // a multiplot whenever there is more than one panel, a placed panel, a key column or a
  // figure title (centred on the figure, not on a panel of fixed aspect)
  const bool multi = fig.panels.size() > 1 || unplaced != (int) fig.panels.size() || fig.grid_width < 1.0 ||
                     !fig.title.empty();
  // the title's room: 6% of the figure for its first line, and about 24 px (a line at 14 pt)
  // for each further one, so that they do not reach the top panels' titles
  const int more_lines = (int) std::count(fig.title.begin(), fig.title.end(), '\n');
  const double title_room = 0.06 + 24.0 * more_lines / std::max(fig.height, 1);
  const double top = (multi && !fig.title.empty()) ? 1.0 - title_room : 1.0;
  if (multi) fold_key_column(fig.panels, fig, top - 0.04, f.notes);

  std::ostringstream b;
  if (multi)
    b << "set multiplot" << (fig.title.empty() ? "" : " title " + gp_quote(fig.title) + " font \",14\"") << "\n";
  int cell = 0;
  for (std::size_t pi = 0; pi < fig.panels.size(); ++pi) {
    const SeriesPanel &p = fig.panels[pi];
    std::string label = p.title;
    std::replace(label.begin(), label.end(), '\n', ' ');
    b << "\n# ---- panel " << pi + 1 << (label.empty() ? "" : ": " + label) << "\n";
    if (pi) b << "reset\nset encoding utf8\n";
    const bool inset = p.at_w > 0 && p.at_h > 0;
    if (inset) {
      b << "set origin " << gp_number(p.at_x) << "," << gp_number(p.at_y) << "\nset size " << gp_number(p.at_w) << ","
        << gp_number(p.at_h) << "\n"
        << "set object 1 rectangle from screen " << gp_number(p.at_x) << "," << gp_number(p.at_y) << " to screen "
        << gp_number(p.at_x + p.at_w) << "," << gp_number(p.at_y + p.at_h)
        << " behind fillcolor rgb \"white\" fillstyle solid 1.0 border lc rgb \"#a0a0a0\"\n"
        << "set tics font \",10\"\nset title font \",10\"\nset xlabel font \",10\"\nset ylabel font \",10\"\n";
    } else if (multi) {
      const int r = cell / cols, c = cell % cols;
      ++cell;
      const double gw = fig.grid_width > 0 && fig.grid_width <= 1 ? fig.grid_width : 1.0;
      b << "set origin " << gp_number(gw * c / cols) << "," << gp_number(top * (1.0 - double(r + 1) / rows))
        << "\nset size " << gp_number(gw / cols) << "," << gp_number(top / rows) << "\n";
    }
    const std::string ptitle = (!multi && !fig.title.empty()) ? fig.title : p.title;
    if (!ptitle.empty()) b << "set title " << gp_quote(ptitle) << "\n";
    if (!p.xlabel.empty()) b << "set xlabel " << gp_quote(p.xlabel) << "\n";
    if (!p.ylabel.empty()) b << "set ylabel " << gp_quote(p.ylabel) << "\n";
    b << "set grid lc rgb \"#d0d0d0\"\n";
    if (p.logx) b << "set logscale x\n";
    if (p.logy) b << "set logscale y\n";
    if (std::isfinite(p.xmin) || std::isfinite(p.xmax)) b << "set xrange " << range(p.xmin, p.xmax) << "\n";
    if (std::isfinite(p.ymin) || std::isfinite(p.ymax)) b << "set yrange " << range(p.ymin, p.ymax) << "\n";
    if (p.key == "off") b << "unset key\n";
    else if (p.key == "column")
      b << "set key at screen " << gp_number(std::min(0.99, fig.grid_width + 0.01)) << ", screen "
        << gp_number(top - 0.04) << " left top Left reverse\n";
    else b << "set key " << p.key << "\n";
    if (p.key != "off") b << "set key spacing 1.25\n";    // room for sub- and superscripts
    if (p.key != "off" && !p.key_title.empty()) b << "set key title " << gp_quote(p.key_title) << "\n";
    int obj = 10;
    for (const auto &h : p.hbands)
      b << "set object " << obj++ << " rectangle from graph 0, first " << gp_number(h.lo) << " to graph 1, first "
        << gp_number(h.hi) << " behind fillcolor rgb " << gp_quote(h.colour) << " fillstyle transparent solid "
        << gp_number(h.opacity) << " noborder\n";
    int arrow = 1;
    for (const auto &v : p.vlines) {
      b << "set arrow " << arrow << " from first " << gp_number(v.x) << ", graph 0 to first " << gp_number(v.x)
        << ", graph 1 nohead " << line_props(v.colour, 1.5, v.dash) << "\n";
      if (!v.label.empty())
        b << "set label " << arrow << " " << gp_quote(v.label) << " at first " << gp_number(v.x)
          << ", graph 0.96 left offset char 0.4,0 textcolor rgb " << gp_quote(v.colour) << "\n";
      ++arrow;
    }
    if (!p.extra.empty()) b << p.extra << (p.extra.back() == '\n' ? "" : "\n");

    // data blocks and plot clauses: bands first (under the lines), then the band key
    // entries, the series, the guides
    std::vector<std::string> bands, lines;
    for (std::size_t si = 0; si < p.series.size(); ++si) {
      const PlotSeries &s = p.series[si];
      const std::size_t n = std::min(s.x.size(), s.y.size());
      if (n == 0) continue;
      const bool band = s.band_lo.size() == n && s.band_hi.size() == n;
      const bool err = s.y_err.size() == n;
      PlotBlock blk;
      blk.title = "panel " + std::to_string(pi + 1) + ", series " + std::to_string(si + 1) +
                  (s.title.empty() ? "" : ": " + s.title);
      blk.columns = {"x", "y"};
      if (band) blk.columns.push_back("band_lo"), blk.columns.push_back("band_hi");
      if (err) blk.columns.push_back("y_err");
      for (std::size_t k = 0; k < n; ++k) {
        std::vector<double> row = {s.x[k], s.y[k]};
        if (band) row.push_back(s.band_lo[k]), row.push_back(s.band_hi[k]);
        if (err) row.push_back(s.y_err[k]);
        blk.rows.push_back(row);
      }
      const int idx = f.add_block(blk);
      const std::string colour = s.colour.empty() ? plot_colour((int) si) : s.colour;
      const std::string src = "data index " + std::to_string(idx) + " using ";
      if (band)
        bands.push_back(src + "1:3:4 with filledcurves fillcolor rgb " + gp_quote(colour) +
                        " fillstyle transparent solid " + gp_number(s.band_opacity) + " noborder " +
                        title_of(s.band_title));
      const int ecol = band ? 5 : 3;
      std::string clause;
      if (err) {
        const bool joined = s.style != "points";
        clause = src + "1:2:" + std::to_string(ecol) + (joined ? " with yerrorlines " : " with yerrorbars ") +
                 line_props(colour, s.line_width, s.dash) + " pt " + std::to_string(s.point_type) + " ps " +
                 gp_number(s.point_size);
      } else if (s.style == "points") {
        clause = src + "1:2 with points pt " + std::to_string(s.point_type) + " ps " + gp_number(s.point_size) +
                 " lc rgb " + gp_quote(colour);
      } else if (s.style == "linespoints") {
        clause = src + "1:2 with linespoints " + line_props(colour, s.line_width, s.dash) + " pt " +
                 std::to_string(s.point_type) + " ps " + gp_number(s.point_size);
      } else {
        clause = src + "1:2 with lines " + line_props(colour, s.line_width, s.dash);
      }
      lines.push_back(clause + " " + title_of(s.title));
    }
    for (const auto &h : p.hbands)
      if (!h.title.empty())
        bands.push_back("keyentry with filledcurves fillcolor rgb " + gp_quote(h.colour) +
                        " fillstyle transparent solid " + gp_number(std::min(1.0, 2 * h.opacity)) + " noborder title " +
                        gp_quote(h.title));
    for (const auto &g : p.guides)
      lines.push_back(g.expression + " with lines " + line_props(g.colour, g.expression == "keyentry" ? 0.0 : g.line_width, g.dash) + " " +
                      title_of(g.title));
    std::vector<std::string> all = bands;
    all.insert(all.end(), lines.begin(), lines.end());
    if (!has_data(p)) {
      b << "unset logscale\nset xrange [0:1]\nset yrange [0:1]\nunset key\n"
        << "set label 99 \"no data\" at graph 0.5, graph 0.5 center font \",16\"\nplot 2 notitle\n";
      continue;
    }
    b << "set samples 400\nplot ";
    for (std::size_t k = 0; k < all.size(); ++k) b << (k ? ", \\\n     " : "") << all[k];
    b << "\n";
  }
  if (multi) b << "unset multiplot\n";
  f.body = b.str();
  return f;
}

// ---------------------------------------------------------------- bar charts

PlotFiles bar_chart(const BarChart &c)
{
  PlotFiles f;
  f.name = c.name;
  f.about = c.about;
  f.width = c.width;
  f.height = c.height;
  const std::size_t n = c.values.size();
  const bool err = c.errors.size() == n;
  PlotBlock blk;
  blk.title = "bars: position, value, error (+-), colour (0xRRGGBB); labels in the script's xtics";
  blk.columns = {"i", "value", "error", "colour"};
  bool negative = false;
  for (std::size_t i = 0; i < n; ++i) {
    const std::string col = i < c.colours.size() && !c.colours[i].empty() ? c.colours[i] : plot_colour(0);
    const double rgb = (double) std::strtol(col.c_str() + (col[0] == '#' ? 1 : 0), nullptr, 16);
    blk.rows.push_back({(double) i, c.values[i], err ? c.errors[i] : 0.0, rgb});
    negative |= c.values[i] < 0;
  }
  std::ostringstream b;
  if (!c.title.empty()) b << "set title " << gp_quote(c.title) << "\n";
  if (!c.xlabel.empty()) b << "set xlabel " << gp_quote(c.xlabel) << "\n";
  if (!c.ylabel.empty()) b << "set ylabel " << gp_quote(c.ylabel) << "\n";
  if (n == 0) {
    b << "set xrange [0:1]\nset yrange [0:1]\nunset key\nset label 99 \"no data\" at graph 0.5, graph 0.5 center font \",16\"\n"
      << "plot 2 notitle\n";
    f.body = b.str();
    return f;
  }
  f.add_block(blk);
  std::size_t longest = 0;
  for (const auto &l : c.labels) longest = std::max(longest, l.size());
  b << "set grid ytics lc rgb \"#d0d0d0\"\nunset key\nset boxwidth 0.6\nset style fill solid 0.85 border lc rgb \"#303030\"\n"
    << "set xrange [-0.6:" << gp_number(n - 0.4) << "]\n"
    << "set xtics nomirror scale 0" << (longest > 12 || n > 6 ? " rotate by -25 left" : "") << " (";
  for (std::size_t i = 0; i < n; ++i)
    b << (i ? ", " : "") << gp_literal(i < c.labels.size() ? c.labels[i] : std::to_string(i + 1)) << " " << i;
  b << ")\n";
  if (std::isfinite(c.ymin) || std::isfinite(c.ymax)) b << "set yrange " << range(c.ymin, c.ymax) << "\n";
  else b << "set yrange [" << (negative ? "*" : "0") << ":*]\n";
  b << "set offsets 0, 0, graph 0.12, " << (negative ? "graph 0.12" : "0") << "\n"
    << "set xzeroaxis lt -1\n"
    << "plot data index 0 using 1:2:(0.6):4 with boxes lc rgb variable notitle";
  if (err) b << ", \\\n     data index 0 using 1:2:3 with yerrorbars pt 7 ps 0 lw 1.5 lc rgb \"#202020\" notitle";
  if (c.show_values) {
    const std::string fmt = gp_quote(c.value_format);
    b << ", \\\n     data index 0 using 1:($2 >= 0 ? $2 + $3 : NaN):(sprintf(" << fmt
      << ", $2)) with labels offset char 0,0.8 notitle"
      << ", \\\n     data index 0 using 1:($2 < 0 ? $2 - $3 : NaN):(sprintf(" << fmt
      << ", $2)) with labels offset char 0,-0.8 notitle";
  }
  for (const auto &g : c.guides)
    b << ", \\\n     " << g.expression << " with lines " << line_props(g.colour, g.line_width, g.dash) << " "
      << title_of(g.title);
  b << "\n";
  if (std::any_of(c.guides.begin(), c.guides.end(), [](const PlotGuide &g) { return !g.title.empty(); })) {
    // guides with titles need a key: put it above the plot
    std::string s = b.str();
    const auto pos = s.find("unset key\n");
    if (pos != std::string::npos) s.replace(pos, 10, "set key outside top center horizontal\n");
    f.body = s;
  } else {
    f.body = b.str();
  }
  return f;
}

}    // namespace granpen
