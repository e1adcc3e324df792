// granpen analysis: a friction-calibration sweep folder (beds/*.info, traces/*.csv, as
// granpen sweep writes it) read and fitted into the beds and pushes core/calibration.h
// tabulates, and the files granpen calibration writes from its table: calibration.csv,
// calibration.json, calibration.md and calibration.gp (a gnuplot script, data inline).
#ifndef GRANPEN_CALIBRATION_SWEEP_H
#define GRANPEN_CALIBRATION_SWEEP_H

#include "calibration.h"

#include <string>
#include <utility>
#include <vector>

namespace granpen {

struct CalibrationSweep {
  std::vector<CalibrationBed> beds;
  std::vector<CalibrationPush> pushes;
  std::vector<std::string> info_files, trace_files;    // what was read
  std::vector<std::string> problems;                   // unreadable or unfittable inputs, each named
  std::vector<std::string> notes;                      // defaults taken, mismatches
};

// Every bed and push of the sweep folder dir, k_z fitted over z = zmin..zmax (core/trace_fit.h).
CalibrationSweep read_calibration_sweep(const std::string &dir, double zmin, double zmax);

// The table as markdown (the summary granpen calibration prints).
std::string calibration_markdown(const std::vector<CalibrationRow> &rows, double zmin, double zmax);

// (path in out_dir, text) of calibration.csv, .json, .md and .gp
std::vector<std::pair<std::string, std::string>> calibration_files(const std::vector<CalibrationRow> &rows,
                                                                   const std::string &sweep, double zmin, double zmax,
                                                                   const std::vector<std::string> &problems,
                                                                   const std::string &out_dir);

}    // namespace granpen

#endif
