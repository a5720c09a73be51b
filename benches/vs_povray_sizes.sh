#!/usr/bin/env bash
# phong against POV-Ray 3.7 on the same scene at three sizes (issue 32, "Speed at scale"), side by
# side in one run, ONE thread: the many-spheres scene (`scenes/many_spheres.rs`: spheres on a
# reflective floor) with 6, 9,999 and 99,999 spheres, so 7, 10,000 and 100,000 objects with the
# floor, 640×480, maximum level 5, one sample per pixel. POV-Ray renders `phong export-pov`'s
# file of each (its pixels match phong's within 1 per channel).
#
# Each round runs, for each size, phong f64, phong f32 and POV-Ray once, alternating, so that a
# load on the machine falls on all of them; the figures are the medians of RUNS rounds:
#   - trace: phong's own ("traced … in S s", `--stats`) against POV-Ray's own ("Trace Time");
#   - phong's read + build ("read and validated in S s", "prepared … in S s"), and POV-Ray's
#     parse + bounding;
# and the ratios POV-Ray / phong of the trace (target ≥ 4× at every size), f64 / f32 of the
# trace (target ≥ 1.5×), and phong's read + build of 100,000 objects (target ≤ 0.1 s).
# Usage: benches/vs_povray_sizes.sh [RUNS]   (default 11; needs `povray` and `bc`)
# PHONG=path/to/phong uses that binary instead of building this tree's release binary (the scene
# generator is built here either way, in CARGO_TARGET_DIR if set).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-11}
command -v povray >/dev/null || { echo "povray is not installed (apt-get install povray)" >&2; exit 2; }

target=${CARGO_TARGET_DIR:-target}
[ -n "${PHONG:-}" ] || cargo build --release --quiet
cargo build --release --quiet --example many_spheres
phong=${PHONG:-$target/release/phong}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sizes="7 10000 100000"
for n in $sizes; do
  "$target/release/examples/many_spheres" $((n - 1)) >"$work/s$n.json"
  "$phong" export-pov "$work/s$n.json" --max-level 5 --samples 1 -o "$work/s$n.pov"
  for f in phong-f64 phong-f32 pov pov-parse phong-f64-rb phong-f32-rb; do : >"$work/$f-$n.txt"; done
done

# median, phong_times
source benches/common.sh

echo "machine: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg); $(povray --version 2>&1 | grep -m1 '^POV-Ray')"
echo "phong:   $phong render SCENE -o OUT.ppm --max-level 5 --samples 1 --threads 1 --precision f64|f32 --stats"
echo "POV-Ray: povray -D -A +Q9 File_Gamma=1.0 +GA +V +WT1 +W640 +H480 +FP +OOUT.ppm SCENE.pov"
echo "$runs alternating rounds; medians"
echo

for ((i = 0; i < runs; i++)); do
  for n in $sizes; do
    for p in f64 f32; do
      "$phong" render "$work/s$n.json" -o "$work/phong.ppm" --max-level 5 --samples 1 --threads 1 \
        --precision "$p" --stats 2>&1 | phong_times >"$work/t"
      read -r rd bd tr <"$work/t"
      echo "$tr" >>"$work/phong-$p-$n.txt"
      echo "$rd + $bd" | bc -l >>"$work/phong-$p-rb-$n.txt"
    done
    povray -D -A +Q9 File_Gamma=1.0 +GA +V +WT1 +W640 +H480 +FP "+O$work/pov.ppm" "$work/s$n.pov" 2>&1 |
      tr '\r' '\n' >"$work/pov-stats.txt"
    sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' "$work/pov-stats.txt" >>"$work/pov-$n.txt"
    # Parse and bounding, the counterpart of phong's read and build.
    awk '/Parse Time:|Bounding Time:/ {gsub(/[()]/, "", $0); for (i = 1; i <= NF; i++) if ($i == "seconds") s += $(i - 1)} END {print s}' \
      "$work/pov-stats.txt" >>"$work/pov-parse-$n.txt"
  done
done

printf '%-9s %10s %10s %10s %9s %9s %9s %11s %11s %11s\n' objects "POV trace" "f64 trace" "f32 trace" \
  "POV/f64" "POV/f32" "f64/f32" "POV parse" "f64 rd+bd" "f32 rd+bd"
for n in $sizes; do
  pov=$(median <"$work/pov-$n.txt")
  f64=$(median <"$work/phong-f64-$n.txt")
  f32=$(median <"$work/phong-f32-$n.txt")
  printf '%-9s %10.3f %10.3f %10.3f %8.2f× %8.2f× %8.2f× %11.3f %11.3f %11.3f\n' "$n" "$pov" "$f64" "$f32" \
    "$(echo "$pov / $f64" | bc -l)" "$(echo "$pov / $f32" | bc -l)" "$(echo "$f64 / $f32" | bc -l)" \
    "$(median <"$work/pov-parse-$n.txt")" "$(median <"$work/phong-f64-rb-$n.txt")" \
    "$(median <"$work/phong-f32-rb-$n.txt")"
done
echo
echo "targets: POV/phong trace ≥ 4× at every size; f64/f32 ≥ 1.5×; read + build of 100,000 objects ≤ 0.1 s"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
