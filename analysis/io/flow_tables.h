// granpen analysis: the files granpen flow writes (flow.json and six CSV tables,
// docs/postprocess.md) from a flow study (core/flow_study.h) and what the command knew
// of its inputs. Text only: the caller writes it (io/atomic_file.h).
#ifndef GRANPEN_FLOW_TABLES_H
#define GRANPEN_FLOW_TABLES_H

#include "flow_study.h"
#include "json_writer.h"

#include <string>
#include <utility>
#include <vector>

namespace granpen {

// What the study was run on and where its parameters came from.
struct FlowProvenance {
  std::vector<std::string> dumps;
  std::string trace;                  // "" without a trace
  long long first_step = 0, last_step = 0;
  std::string D_source, d_g_source, rho_g_source, v0_source, g_source, z_s_source;
  int rod_type = 2;
  bool mass_column = false;
  std::string voronoi, stress, periodic;    // how phi and p were had, the periodic axes
  std::vector<std::string> notes;
};

// flow.json: every number with its error, the parameters and their sources, per frame.
Json flow_json(const FlowStudyParams &p, const FlowSummary &s, const std::vector<FlowFrameRecord> &frames,
               const FlowProvenance &how);

// (file name, text) of flow.json and the tables flow_fields.csv, flow_profile_below.csv,
// flow_edge_phi_I.csv, flow_strip.csv, flow_annulus.csv, flow_surface.csv.
std::vector<std::pair<std::string, std::string>> flow_files(const FlowStudyParams &p, const FlowSummary &s,
                                                            const std::vector<FlowFrameRecord> &frames,
                                                            const FlowProvenance &how);

}    // namespace granpen

#endif
