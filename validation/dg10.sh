#!/usr/bin/env bash
# The D/d_g = 10 runs (docs/presets.md, "dg10"; issue: physics at the paper's grain size
# ratio), as a campaign of validation/campaign.sh (its header says how units are cut,
# committed and resumed): the three beds, poured as 5 x 5 cm tiles of about 33500 grains
# replicated 2 x 2 (in.pour -var tile 2, the preset's value), then the pushes of dg10_peak,
# dg10_flow and dg10_D (inputs/sweeps/), committed to data/sims/dg10.
#
#   validation/dg10.sh [--out DIR] [--units N] [--ranks N] [--commit] [--status]
#
# The longest unit, the dg10_flow push at 40 cm/s, is 1.4 to 2.3 core-hours (docs/presets.md).
# Any option of campaign.sh may follow (--data, --sweeps: another folder and sweep files, for tests).
ROOT=$(cd "$(dirname "$0")/.." && pwd)
S=$ROOT/inputs/sweeps
exec "$ROOT/validation/campaign.sh" --data "$ROOT/data/sims/dg10" \
  --sweeps "$S/dg10_peak.sweep $S/dg10_flow.sweep $S/dg10_D.sweep" "$@"
