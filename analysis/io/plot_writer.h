/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: figures as gnuplot scripts with their data beside them.

   A figure NAME in a folder DIR is four files:
     DIR/NAME.dat  the numbers plotted, as gnuplot data blocks ("index 0", "index 1",
                   ...; each block preceded by "# title" and "# column names" lines)
     DIR/NAME.gp   a self-contained gnuplot script reading NAME.dat by relative name,
                   so it can be edited and rerun in DIR: `gnuplot NAME.gp` makes
     DIR/NAME.png  (pngcairo) and
     DIR/NAME.svg  (svg); `gnuplot -e "formats='png'" NAME.gp` makes one of them.
   The script's body (the commands after the terminal is set) is drawn once per
   format; the variable `data` holds "NAME.dat".

   Two levels:
   - PlotFiles + write_plot: any body of gnuplot commands over any data blocks
     (heatmaps, insets: the `granpen plot` kinds);
   - SeriesFigure / BarChart: generic figures (several series against x with
     optional error bands and error bars, reference lines and bands, log axes,
     panels and insets; a bar chart with labels and optional error bars), turned
     into PlotFiles by series_figure() / bar_chart().

   Every failure is reported as text naming the script, never thrown, so a caller
   can write the other figures and exit 1.
------------------------------------------------------------------------- */

#ifndef GRANPEN_PLOT_WRITER_H
#define GRANPEN_PLOT_WRITER_H

#include <cmath>
#include <string>
#include <vector>

namespace granpen {

// ---------------------------------------------------------------- low level

// One data block of NAME.dat. Non-finite values are written as NaN (gnuplot: an
// undefined point, which breaks a line); an empty row writes a blank line (a scan
// break for `with image` / pm3d data).
struct PlotBlock {
  std::string title;                        // "# title"
  std::vector<std::string> columns;         // "# name1 name2 ..."
  std::vector<std::vector<double>> rows;
};

struct PlotFiles {
  std::string name;        // base name: NAME.gp, NAME.dat, NAME.png, NAME.svg
  std::string about;       // comment at the top of the script (may hold newlines)
  int width = 1000, height = 620;    // pixels, both formats
  std::vector<PlotBlock> blocks;     // NAME.dat: blocks[i] is `index i`
  std::string body;                  // gnuplot commands; read the data as `data index i`
  std::vector<std::string> notes;    // what the writer changed (a legend it folded), for the caller
  // appends a block, returns its index
  int add_block(const PlotBlock &b);
};

struct PlotResult {
  bool written = false;            // NAME.dat and NAME.gp written
  bool ran = false;                // gnuplot ran and made non-empty NAME.png and NAME.svg
  bool gnuplot_missing = false;
  std::string script, data, png, svg;    // paths (DIR/NAME.*)
  std::string error;               // empty when ok; otherwise names the script or file
  bool ok() const { return error.empty(); }
};

// Writes DIR/NAME.dat and DIR/NAME.gp (creating DIR); when run is true, then runs
// gnuplot in DIR and checks that NAME.png and NAME.svg exist and are not empty.
PlotResult write_plot(const std::string &dir, const PlotFiles &files, bool run = true);

// Runs `gnuplot SCRIPT` in DIR without a shell. Returns "" on success, otherwise why
// not, with the last lines gnuplot printed; missing is set when gnuplot cannot be
// found. The program is $GRANPEN_GNUPLOT when set, else gnuplot on PATH.
std::string run_gnuplot(const std::string &dir, const std::string &script, bool &missing);

// The script text write_plot writes (header, format loop, body).
std::string plot_script(const PlotFiles &files);

// gnuplot text helpers: a double-quoted string literal (backslash and quote escaped);
// the same with enhanced-text specials (_ ^ @ & ~ { }) made literal, for file names;
// a number (%.10g, NaN when not finite).
std::string gp_quote(const std::string &s);
std::string gp_literal(const std::string &s);
std::string gp_number(double v);

// A colour as "#rrggbb": the i-th of a palette of well-separated hues, and the j-th
// of n shades of a colour (darker to lighter), for several runs of one case.
std::string plot_colour(int i);
std::string plot_shade(const std::string &colour, int j, int n);

// ---------------------------------------------------------------- series figures

struct PlotSeries {
  std::string title;                  // legend entry; "" for none
  std::vector<double> x, y;
  std::vector<double> band_lo, band_hi;    // optional shaded band (same length as x)
  std::string band_title;                  // legend entry of the band ("" for none)
  std::vector<double> y_err;          // optional +- error bars (same length as x)
  std::string style = "lines";        // lines | points | linespoints
  std::string colour;                 // "#rrggbb"; "" takes plot_colour(series index)
  double line_width = 2.0;
  int dash = 1;                       // gnuplot dashtype (1 solid, 2 dashed, 3 dotted, ...)
  int point_type = 7;                 // 7 filled circle, 5 filled square, 9 triangle, 6 open circle
  double point_size = 1.2;
  double band_opacity = 0.22;
};

// A reference line y = f(x), f a gnuplot expression in x ("1", "x", "2.5e3*x**2"); the
// expression "keyentry" draws nothing and only adds its title to the legend.
struct PlotGuide {
  std::string expression, title;
  std::string colour = "#404040";
  int dash = 2;
  double line_width = 1.5;
};

// A shaded horizontal band lo <= y <= hi across the panel (e.g. 1 +- 0.2).
struct PlotHBand {
  double lo = 0.0, hi = 0.0;
  std::string title;
  std::string colour = "#808080";
  double opacity = 0.18;
};

// A vertical marker line at x with a label at its top.
struct PlotVLine {
  double x = 0.0;
  std::string label;
  std::string colour = "#404040";
  int dash = 3;
};

struct SeriesPanel {
  std::string title, xlabel, ylabel;
  bool logx = false, logy = false;
  double xmin = NAN, xmax = NAN, ymin = NAN, ymax = NAN;    // NaN: autoscale that end
  std::vector<PlotSeries> series;
  std::vector<PlotGuide> guides;
  std::vector<PlotHBand> hbands;
  std::vector<PlotVLine> vlines;
  // `set key` arguments; "off" for no legend; "column" for the figure's key column
  // (SeriesFigure::grid_width), where a multi-panel figure's shared legend goes
  std::string key = "outside right top Left reverse";
  std::string key_title;                    // the key's title (lines counted in the key column's room)
  std::string extra;                        // further commands, set before plotting
  // Placement in the figure, screen fractions of the lower left corner and size
  // (an inset: drawn over what came before, on a white background, in a smaller
  // font; give it key "off" or "column"); all 0: the next cell of the figure's grid.
  double at_x = 0, at_y = 0, at_w = 0, at_h = 0;
};

struct SeriesFigure {
  std::string name, about, title;
  int width = 1000, height = 620;
  std::vector<SeriesPanel> panels;    // grid cells left to right, top to bottom
  int columns = 0;                    // grid columns; 0: all unplaced panels in one row
  double grid_width = 1.0;            // screen fraction the grid spans from the left; the
                                      // rest is the key column
};

// Data blocks and script of a series figure (one block per series). The key column holds
// the legend entries of the panels whose key is "column", from the top down to the highest
// panel placed in the column (an inset beside the plot), else to the bottom. When they do
// not all fit, the last entries that fit are replaced by one entry "+ N more not listed"
// (their series are still drawn) and PlotFiles::notes says so.
PlotFiles series_figure(const SeriesFigure &f);

// The height of one line of a legend (key spacing 1.25, the 12 pt font) as a fraction of a
// figure of height_px pixels, and the top of the key column: for a caller that places an
// inset below the legend.
double key_line_height(int height_px);
double key_column_top(const SeriesFigure &f);

// ---------------------------------------------------------------- bar charts

struct BarChart {
  std::string name, about, title, xlabel, ylabel;
  std::vector<std::string> labels;     // one bar each, drawn as x tic labels, literally
  std::vector<double> values;
  std::vector<double> errors;          // optional +- (same length)
  std::vector<std::string> colours;    // optional per bar; default plot_colour(0)
  bool show_values = true;             // print each value above its bar
  std::string value_format = "%.3g";   // gnuplot sprintf format of those values
  double ymin = NAN, ymax = NAN;
  std::vector<PlotGuide> guides;       // e.g. y = 1
  int width = 900, height = 560;
};

PlotFiles bar_chart(const BarChart &b);

}    // namespace granpen

#endif
