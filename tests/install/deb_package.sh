#!/usr/bin/env bash
# The Debian binary package of granpen (CPack):
#   contents BUILD_DIR SOURCE_DIR WORK_DIR: cpack -G DEB builds granpen_VERSION_ARCH.deb; its
#     control file names the runtime dependencies (lammps, Open MPI, gnuplot, and liblammps
#     through dpkg-shlibdeps); it holds the programs, decks, examples and docs under /usr; and
#     unpacked (dpkg-deb -x, no install) its lmp_granpen reproduces the examples' logs and its
#     granpen-cli runs.
#   install BUILD_DIR SOURCE_DIR WORK_DIR: installs the package with apt-get on this machine,
#     runs /usr/bin/granpen-demo from the installed files, and removes the package again. Only
#     when GRANPEN_DEB_INSTALL=1 and run as root (CI and shared machines: skipped, exit 77),
#     and meant for a fresh Debian 12 (a container).
# Exit: 0 pass, 1 fail, 2 usage, 77 skipped.
set -uo pipefail
[ $# -eq 4 ] || { sed -n '2,13p' "$0"; exit 2; }
mode=$1 build=$(cd "$2" && pwd) src=$(cd "$3" && pwd) work=$4
fail() { echo "FAIL: $*"; exit 1; }
if [ "$mode" = install ] && { [ "${GRANPEN_DEB_INSTALL:-0}" != 1 ] || [ "$(id -u)" != 0 ]; }; then
  echo "skipped: installing a package needs GRANPEN_DEB_INSTALL=1 and root (a fresh Debian 12 container)"; exit 77
fi
rm -rf "$work"; mkdir -p "$work"; work=$(cd "$work" && pwd)
(cd "$build" && cpack -G DEB -B "$work" > "$work/cpack.log" 2>&1) || { tail -20 "$work/cpack.log"; fail "cpack -G DEB"; }
deb=$(ls "$work"/granpen_*.deb 2>/dev/null | head -1)
[ -n "$deb" ] || fail "cpack wrote no granpen_*.deb: $(tail -5 "$work/cpack.log")"
depends=$(dpkg-deb -f "$deb" Depends)
for d in lammps openmpi-bin gnuplot-nox liblammps0; do
  echo "$depends" | grep -qw "$d" || fail "Depends lacks $d: $depends"
done
dpkg-deb -c "$deb" | awk '{print $NF}' > "$work/contents.txt"
for f in ./usr/bin/lmp_granpen ./usr/bin/granpen-cli ./usr/bin/granpen-demo ./usr/share/granpen/inputs/in.push \
    ./usr/share/granpen/examples/in.rod_flow ./usr/share/granpen/plugin.lmp ./usr/share/doc/granpen/LICENSE; do
  grep -qxF "$f" "$work/contents.txt" || fail "the package lacks $f"
done
if [ "$mode" = contents ]; then
  dpkg-deb -x "$deb" "$work/root" || fail "dpkg-deb -x"
  "$work/root/usr/bin/granpen-cli" --help > /dev/null 2>&1 || fail "the unpacked granpen-cli --help"
  "$src/tests/examples/lammps_examples.sh" --current "$work/root/usr/bin/lmp_granpen" "$work/root/usr/share/granpen/examples" ||
    fail "the unpacked lmp_granpen and examples"
  echo "ok: $(basename "$deb"): Depends $depends; $(wc -l < "$work/contents.txt") entries; unpacked, it runs the examples"
  exit 0
fi
# install: on a fresh Debian 12 with the package's dependencies available from apt
apt-get install -y "$deb" > "$work/apt.log" 2>&1 || { tail -20 "$work/apt.log"; fail "apt-get install $deb"; }
(cd "$work" && /usr/bin/granpen-demo demo-out) > "$work/demo.log" 2>&1; rc=$?
apt-get remove -y granpen > "$work/remove.log" 2>&1 || true
[ $rc = 0 ] || { tail -20 "$work/demo.log"; fail "granpen-demo from the installed package"; }
[ -s "$work/demo-out/force_depth.png" ] || fail "granpen-demo wrote no force_depth.png"
echo "ok: $(basename "$deb") installed with apt-get, granpen-demo ran from /usr, package removed"
