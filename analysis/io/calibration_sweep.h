// granpen analysis: a friction-calibration sweep folder (beds/*.info, traces/*.csv, as
// granpen sweep writes it) read into the beds and pushes of core/calibration_study.h (which
// fits and tabulates them), and the files granpen calibration writes from its table:
// calibration.csv, calibration.json, calibration.md, and its figures (io/plot_writer.h):
// calibration_phi0 and calibration_kz.
#ifndef GRANPEN_CALIBRATION_SWEEP_H
#define GRANPEN_CALIBRATION_SWEEP_H

#include "calibration.h"
#include "calibration_study.h"
#include "plot_writer.h"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace granpen {

struct CalibrationSweep {
  std::vector<CalibrationBed> beds;
  std::vector<CalibrationTrace> pushes;                // read, to be fitted by the study
  std::vector<std::string> push_files;                 // the file of each push
  std::vector<std::string> info_files, trace_files;    // what was read
  std::vector<std::string> problems;                   // unreadable inputs, each named
  std::vector<std::string> notes;                      // defaults taken, mismatches
  // where each push's fit messages go among the problems and notes (after those of its
  // reading), so that calibration_messages keeps every file's messages together
  std::vector<std::size_t> problems_at, notes_at;
};

// Every bed and push of the sweep folder dir.
CalibrationSweep read_calibration_sweep(const std::string &dir);

// The problems and notes of the reading and of the study's fits (a push without k_z a
// problem, one without alpha a note, each naming its file), in the order of the files.
void calibration_messages(const CalibrationSweep &sw, const CalibrationStudy &st, std::vector<std::string> &problems,
                          std::vector<std::string> &notes);

// The table as markdown (the summary granpen calibration prints).
std::string calibration_markdown(const std::vector<CalibrationRow> &rows, double zmin, double zmax);

// (path in out_dir, text) of calibration.csv, .json and .md
std::vector<std::pair<std::string, std::string>> calibration_files(const std::vector<CalibrationRow> &rows,
                                                                   const std::string &sweep, double zmin, double zmax,
                                                                   const std::vector<std::string> &problems,
                                                                   const std::string &out_dir);

// The table's figures: calibration_phi0 (phi_0 of each bed and their mean +- sd against mu)
// and calibration_kz (k_z of each push and their mean +- sd against mu, per v0).
std::vector<PlotFiles> calibration_figures(const std::vector<CalibrationRow> &rows);

}    // namespace granpen

#endif
