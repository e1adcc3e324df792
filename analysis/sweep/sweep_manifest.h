// granpen sweep, the manifest of a sweep's runs (sweep_runner.cpp): DIR/manifest.json
// (docs/sweeps.md), read back on resume and rewritten as runs end. Internal to the sweep
// library.
#ifndef GRANPEN_SWEEP_MANIFEST_H
#define GRANPEN_SWEEP_MANIFEST_H

#include "json_writer.h"    // Json
#include "sweep_jobs.h"

#include <string>
#include <vector>

namespace granpen {
namespace sweep_run {

// The runs of DIR/manifest.json: its "runs", or, when the file is not valid JSON (written
// by hand, or by a granpen older than the atomic write), every line that is one run's
// record on its own (the writer puts each run on one line); a warning names the file.
std::vector<Json> manifest_runs(const std::string &path);

// Runs of other sweep files with the same name (sharing its beds, e.g. a v0 and a g sweep)
// stay in the manifest, keyed by their ids; so do the records of runs another process holds.
void keep_other_runs(Sweep &sw);

// one run's record of the manifest
Json manifest_run(const Sweep &sw, const Job &j);

// DIR/manifest.json, every run one line; a run another process holds keeps the record
// that process wrote.
Json manifest_json(const Sweep &sw);

// Writes DIR/manifest.json through io/atomic_file (a temporary of this process's own:
// SLURM tasks of one sweep write it too; every step checked). Returns "" or what failed.
std::string write_manifest_file(const Sweep &sw);

}    // namespace sweep_run
}    // namespace granpen

#endif
