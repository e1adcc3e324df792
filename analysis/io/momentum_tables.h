// granpen analysis: the files granpen momentum writes (momentum.json,
// momentum_classes.csv, momentum_drag.csv; docs/postprocess.md) from a momentum study
// (core/momentum_study.h). Text only: the caller writes it (io/atomic_file.h).
#ifndef GRANPEN_MOMENTUM_TABLES_H
#define GRANPEN_MOMENTUM_TABLES_H

#include "json_writer.h"
#include "momentum_study.h"

#include <string>
#include <utility>
#include <vector>

namespace granpen {

// What the study was run on and where its parameters came from.
struct MomentumProvenance {
  std::vector<std::string> dumps;
  std::string trace;
  std::string D_source, mu_source, rho_g_source, z_s_source, class_source;
  double rho_g = 0.0;
  bool mass_column = false;
  int rod_type = 2;
  std::string periodic;
  std::vector<std::string> notes;
};

Json momentum_json(const MomentumStudyParams &p, const std::vector<MomentumFrameRecord> &frames,
                   const DragComparison &drag, const MomentumProvenance &how);

// (file name, text) of momentum.json, momentum_classes.csv and momentum_drag.csv
std::vector<std::pair<std::string, std::string>> momentum_files(const MomentumStudyParams &p,
                                                                const std::vector<MomentumFrameRecord> &frames,
                                                                const DragComparison &drag,
                                                                const MomentumProvenance &how);

}    // namespace granpen

#endif
