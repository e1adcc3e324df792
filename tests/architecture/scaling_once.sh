#!/bin/sh
# scaling_once.sh: fails when one of the paper's scaling relations is written outside its
# kernel, src/scaling_laws.{h,cpp} (issue 32): t~ = (z / v0) sqrt(g / D) or its inverse
# z = t~ v0 sqrt(D / g) (a square root of g over a diameter, or the reverse), k_z or
# F_z = alpha mu rho_g g D^2 z (a product of mu and rho), the peak regime's end 0.35 D (a
# product with 0.35). Comments and string literals are not code. ctest
# architecture_scaling_once, with a self-test.
#   scaling_once.sh [--self-test] [ROOT]
# Exit: 0 none outside the kernel, 1 some (each printed as file:line: code), 2 usage.
# Needs only sh, find, awk and grep (and code_lines.sh beside it).
set -u
root=.
self_test=no
while [ $# -gt 0 ]; do
  case "$1" in
    --self-test) self_test=yes; shift ;;
    -h|--help) sed -n '2,9p' "$0"; exit 0 ;;
    -*) echo "scaling_once.sh: unknown option $1" >&2; exit 2 ;;
    *) root=$1; shift ;;
  esac
done

# the relations, as extended regular expressions on a line of code
T_TILDE='sqrt *\([^()]*\b(g|gmag)\b *\/ *[^()]*\b(D|dia|diameter)\b[^()]*\)|sqrt *\([^()]*\b(D|dia|diameter)\b *\/ *[^()]*\b(g|gmag)\b[^()]*\)'
F_Z='\bmu\b[^;=]*\*[^;=]*\brho(_g)?\b|\brho(_g)?\b[^;=]*\*[^;=]*\bmu\b'
PEAK_END='\b0\.35 *\*|\* *0\.35\b'

# code_lines ROOT EXCLUDE DIR...: FILE:LINE: CODE, comments and string literals blanked
. "$(dirname "$0")/code_lines.sh"

check() {
  [ -d "$1/src" ] || { echo "scaling_once.sh: $1 has no src/" >&2; return 2; }
  [ -f "$1/src/scaling_laws.cpp" ] || { echo "scaling_once.sh: $1 has no src/scaling_laws.cpp" >&2; return 2; }
  code=$(code_lines "$1" '(^|/)src/scaling_laws\.(h|cpp)$' src launcher analysis)
  bad=0
  for rel in "t~:$T_TILDE" "F_z:$F_Z" "peak end:$PEAK_END"; do
    name=${rel%%:*} pattern=${rel#*:}
    hits=$(printf '%s\n' "$code" | grep -E "$pattern")
    if [ -n "$hits" ]; then
      echo "$name written outside src/scaling_laws (call its function instead):"
      printf '%s\n' "$hits" | sed 's/^/  /'
      bad=1
    fi
  done
  [ $bad -eq 0 ] && echo "ok: t~, F_z and the peak regime's end are written only in src/scaling_laws"
  return $bad
}

if [ "$self_test" = yes ]; then
  # a fixture tree: the kernel itself (which writes every relation) and a caller pass; the
  # same relations in comments and strings pass; each planted copy fails, named
  tmp=$(mktemp -d) || exit 2
  trap 'rm -rf "$tmp"' EXIT
  t="$tmp/tree"
  mkdir -p "$t/src" "$t/analysis/core"
  cat > "$t/src/scaling_laws.cpp" <<'KERNEL'
double t_tilde(double z, double v0, double g, double D) { return z / v0 * std::sqrt(g / D); }
double depth_at_t_tilde(double t, double v0, double g, double D) { return t * v0 * std::sqrt(D / g); }
double k_z_from_alpha(double alpha, double mu, double rho_g, double g, double D) { return alpha * mu * rho_g * g * D * D; }
double peak_regime_end(double D) { return PEAK_END_PER_D * D; }
const double PEAK_END_PER_D = 0.35 * 1.0;
KERNEL
  cat > "$t/analysis/core/caller.cpp" <<'CALLER'
// t~ = (z / v0) sqrt(g / D), F_z = alpha mu rho_g g D^2 z, the peak: z <= 0.35 * D
/* sqrt(in.g / in.D)
   mu * rho */
const double t = t_tilde(z, in.v0, in.g, in.D), k = k_z_from_alpha(a, mu, rho, g, D);
const char *help = "t~ = (z/v0) sqrt(g/D), F_z = alpha * mu * rho_g, 0.35 * D";
const double speed = std::sqrt(vx * vx + vy * vy), I = gammadot * d_g / std::sqrt(p / rho_g);
double mg = mu * g * M;    // mu g M: no rho
CALLER
  out=$(check "$t") || { echo "$out"; echo "SELF-TEST FAILED: the kernel and a caller fail"; exit 1; }
  n=0
  for planted in 'const double scale = std::sqrt(c.g / c.D) / c.v0;' \
                 'vector[5] = depth / speed * std::sqrt(g / dia);' \
                 'p.zlo = w.tmin * tr.v0 * std::sqrt(tr.D / tr.g);' \
                 'k_z = o.alpha * mu * rho * t.tr.g * t.tr.D * t.tr.D;' \
                 'const double scale = p.mu * p.rho_g * p.g * p.D * p.D;' \
                 'if (z <= 0.35 * D) return "peak";' \
                 'const double zpeak = Dmax * 0.35;'; do
    n=$((n + 1))
    printf '%s\n' "$planted" > "$t/analysis/core/copy.cpp"
    out=$(check "$t"); rc=$?
    [ $rc -eq 1 ] || { echo "$out"; echo "SELF-TEST FAILED: a copy ($planted) gives exit $rc, 1 expected"; exit 1; }
    case "$out" in *"analysis/core/copy.cpp:1:"*) ;; *) echo "$out"; echo "SELF-TEST FAILED: the copy not named"; exit 1 ;; esac
  done
  rm "$t/analysis/core/copy.cpp"
  check "$t" > /dev/null || { echo "SELF-TEST FAILED: the tree without the copies fails"; exit 1; }
  echo "self-test passed: $n planted copies of t~, F_z and the peak end fail, the kernel and its callers pass"
  exit 0
fi

check "$root"
