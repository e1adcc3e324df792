#!/bin/sh
# granpen gap: the adaptive plan on a gap outside the library (issue 37, "the plan stops once
# no candidate can pass"), over more than one realization, checked against a second route:
# the selftest's outside case CASE (fake_lmp's buried layer; its beds are the seeds' own, so
# each seed set is one realization) is diagnosed on each measured seed set FIRST..FIRST+7
# twice, with the fixture's signature prior (the plan skips what its bound rules out) and
# with --prior none (every knot simulated and fitted). Each candidate the first
# run skipped is looked up in the second run's ranking: skipped on its likelihood ratio's
# bound, it must stay below its threshold there; skipped by the explain gate (gap_adaptive.h),
# it must not both pass its threshold and explain between_knots_min_explained (0.25) of the
# gap. Prints per seed set the verdicts of both runs, the costs, how many were skipped (by
# the gate) and how many of them wrongly; exits 1 on a wrong skip, on a plan that spent as
# much as buying everything, on a case the selftest scores wrong (a confident wrong answer),
# and with MODE gate also when the verdict is not unexplained or the gate skipped nothing.
#   tests/analysis/gap/outside_layer.sh SYNTH CLI FAKE_LMP INPUTS SELFTEST CASE MODE FIRST...
#   (MODE: skips or gate; SYNTH: the gap_synthetic fixture's folder, whose cache and prior it uses)
set -u
synth=$1 cli=$2 lmp=$3 inputs=$4 selftest=$5 case=$6 mode=$7
shift 7
fails=0 sets=$#
tab=$(printf '\t')
for first in "$@"; do
  seeds="$first $((first + 1)) $((first + 2)) $((first + 3)) $((first + 4)) $((first + 5)) $((first + 6)) $((first + 7))"
  for route in prior full; do
    w=${synth}_${case}_${first}_$route
    rm -rf "$w" && mkdir -p "$w/tiny" && ln -s "$synth/tiny/cache" "$w/tiny/cache" && ln -s "$synth/tiny/prior_cache" "$w/tiny/prior_cache"
    if [ "$route" = prior ]; then set -- --prior-seeds "41 42"; else set -- --no-prior; fi
    GRANPEN_LMP=$lmp GRANPEN_CLI=$cli GRANPEN_INPUTS=$inputs GRANPEN_SELFTEST_WORK=$w bash "$selftest" --scenario tiny \
      --jobs 2 --v0 "50 100 200" --seeds "$seeds" --cases "$case" "$@" > "$w/log" 2>&1 \
      || { echo "$case on seeds $first ($route): the selftest failed or scored it wrong: $w/log"; fails=$((fails + 1)); }
  done
  p=${synth}_${case}_${first}_prior/tiny/diag_$case/diagnosis.json f=${synth}_${case}_${first}_full/tiny/diag_$case/diagnosis.json
  [ -r "$p" ] && [ -r "$f" ] || { echo "$case on seeds $first: no diagnosis"; fails=$((fails + 1)); continue; }
  "$cli" get "$f" 'ranking[*].effect' 'ranking[*].likelihood_ratio' 'ranking[*].lr_threshold' 'ranking[*].explained_fraction' \
    'ranking[*].magnitude' > "${synth}_${case}_${first}_full/ranking.tsv"
  IFS=$tab read -r fverdict fspent <<EOF
$("$cli" get "$f" verdict plan.spent)
EOF
  # the push-only candidates' decisions, then the pour-level ones' (both bought on the bound)
  line=$(for g in push_only pour_level; do
      "$cli" get "$p" verdict plan.spent "plan.$g[*].effect" "plan.$g[*].simulated" "plan.$g[*].bound" \
        "plan.$g[*].needed" "plan.$g[*].gain" "plan.$g[*].gain_needed" --missing 0 | awk -F '\t' '$3 != "0"'
    done |
    awk -F '\t' -v ranking="${synth}_${case}_${first}_full/ranking.tsv" -v fv="$fverdict" -v fs="$fspent" -v first="$first" \
        -v mode="$mode" -v name="$case" '
      BEGIN { while ((getline r < ranking) > 0) { split(r, x, "\t"); lr[x[1]] = x[2]; th[x[1]] = x[3]; ex[x[1]] = x[4]; mg[x[1]] = x[5] } }
      { v = $1; s = $2; n++
        if ($4 == "false") {
          skipped++
          gated = $8 > 0 && $7 < $8
          gate += gated
          # the same candidate with its knots simulated: it could have changed the verdict? (the
          # chain skipped is its knots beyond its 2 ms filter: its filtered part was fitted, so
          # only a full fit beyond 2 ms tells against the skip)
          if (($3 != "measurement_chain" || mg[$3] > 2) && (gated ? (lr[$3] >= th[$3] && ex[$3] >= 0.25) : lr[$3] >= th[$3])) {
            wrong++; bad = bad " " $3 }
        } }
      END { ok = !wrong && s < fs && (mode != "gate" || (v == "unexplained" && gate > 0))
            printf "%s on seeds %d: verdict %s (all bought: %s), spent %.2f of %.2f, %d of %d skipped (%d by the explain gate), %d wrongly%s: %s\n",
                   name, first, v, fv, s, fs, skipped, n, gate, wrong, bad, ok ? "ok" : "FAILED"
            exit !ok }') || fails=$((fails + 1))
  echo "$line"
done
echo "outside_layer: $case, $sets realization(s), $fails failed"
[ "$fails" = 0 ]
