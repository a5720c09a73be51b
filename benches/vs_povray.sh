#!/usr/bin/env bash
# phong against POV-Ray 3.7, side by side in one run (issue 3, "Speed to reach"):
# the classic scene at 640×480, maximum level 5, no anti-aliasing, ONE thread.
#
#   1. trace time: phong's own (`--stats`, "traced … in S s") against POV-Ray's own ("Trace Time"
#      in its render statistics), the median of RUNS alternating runs of each;
#   2. whole-process wall time of both commands (hyperfine when installed, else a loop timed
#      with `date`), the PPM written to /tmp in both cases, and their CPU time (user + sys);
# each for phong in f64 and f32, by the wide (default) and the scalar engine.
#
# Targets: phong's trace time ≥ 4× faster than POV-Ray's, whole process ≥ 8× faster.
# Also: f64 against f32, and the wide engine on two threads against one.
# Usage: benches/vs_povray.sh [RUNS]   (default 7; needs `povray`, optionally `hyperfine`)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-7}
command -v povray >/dev/null || { echo "povray is not installed (apt-get install povray)" >&2; exit 2; }

cargo build --release --quiet
phong=target/release/phong
scene=scenes/classic.json
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$phong" export-pov "$scene" --max-level 5 --samples 1 -o "$work/classic.pov"
read -r width height < <(grep -o '+W[0-9]* +H[0-9]*' "$work/classic.pov" | head -1 | tr -d '+WH')
phong_cmd=("$phong" render "$scene" -o "$work/phong.ppm" --max-level 5 --samples 1 --threads 1)
# The same on two threads.
phong_cmd2=("${phong_cmd[@]:0:${#phong_cmd[@]}-1}" 2)
pov_cmd=(povray -D -A +Q9 File_Gamma=1.0 -GA -V +WT1 "+W$width" "+H$height" +FP "+O$work/povray.ppm" "$work/classic.pov")

# median
source benches/common.sh
# The best of the runs: on a shared machine noise only ever adds time, so the minimum is the
# steadier figure when the machine is busy (both are printed).
least() { sort -g | head -1; }
# The phong contenders of the whole-process runs: phong-PRECISION-ENGINE.
phongs="phong-f64-wide phong-f32-wide phong-f64-scalar phong-f32-scalar"
# Sets cmd to the command line of one contender: povray or one of $phongs.
command_for() {
  case $1 in
    povray) cmd=("${pov_cmd[@]}") ;;
    phong-*-*)
      local rest=${1#phong-}
      cmd=("${phong_cmd[@]}" --precision "${rest%-*}" --engine "${rest#*-}")
      ;;
  esac
}

echo "machine: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg); $(povray --version 2>&1 | grep -m1 '^POV-Ray')"
echo "phong:   ${phong_cmd[*]} --precision f64|f32 [--engine scalar] --stats"
echo "POV-Ray: ${pov_cmd[*]} (+ render statistics on stderr)"
echo

: >"$work/pov.txt"
: >"$work/pov-cpu.txt"
# The default (wide) engine and the scalar one, side by side.
engines="wide scalar"
for e in $engines; do for p in f64 f32; do : >"$work/phong-$p-$e.txt"; done; done
for p in f64 f32; do : >"$work/phong-$p-wide-2.txt"; done
for ((i = 0; i < runs; i++)); do
  for e in $engines; do
    for p in f64 f32; do
      "${phong_cmd[@]}" --precision "$p" --engine "$e" --stats 2>&1 |
        sed -n 's/.* in \([0-9.]*\) s: .*/\1/p' >>"$work/phong-$p-$e.txt"
    done
  done
  # The wide engine on two threads (the issue's "two threads ≥ 1.9× one").
  for p in f64 f32; do
    "${phong_cmd2[@]}" --precision "$p" --stats 2>&1 |
      sed -n 's/.* in \([0-9.]*\) s: .*/\1/p' >>"$work/phong-$p-wide-2.txt"
  done
  # POV-Ray: "Trace Time: 0 hours 0 minutes 0 seconds (0.688 seconds)", printed only with its
  # output streams on (-GA silences it), so this run drops -GA -V.
  "${pov_cmd[@]}" +GA +V 2>&1 | tr '\r' '\n' >"$work/pov-stats.txt"
  sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' "$work/pov-stats.txt" >>"$work/pov.txt"
  # "using 1 thread(s) with 0.545 CPU-seconds total", the line after the trace time.
  sed -n '/Trace Time/{n;s/.* with \([0-9.]*\) CPU-seconds.*/\1/p}' "$work/pov-stats.txt" >>"$work/pov-cpu.txt"
done
pov=$(median <"$work/pov.txt")
pov_best=$(least <"$work/pov.txt")
pov_cpu=$(median <"$work/pov-cpu.txt")
echo "trace time, one thread, median of $runs and best of $runs (seconds):"
printf '  %-16s %8.3f %8.3f   (its CPU time for the trace: %.3f s)\n' POV-Ray "$pov" "$pov_best" "$pov_cpu"
for e in $engines; do
  for p in f64 f32; do
    t=$(median <"$work/phong-$p-$e.txt")
    b=$(least <"$work/phong-$p-$e.txt")
    printf '  phong %s %-6s %8.3f %8.3f   POV-Ray / phong = %5.2f× (best: %5.2f×)   (target ≥ 4×)\n' \
      "$p" "$e" "$t" "$b" "$(echo "$pov / $t" | bc -l)" "$(echo "$pov_best / $b" | bc -l)"
  done
done
for e in $engines; do
  f64=$(median <"$work/phong-f64-$e.txt")
  f32=$(median <"$work/phong-f32-$e.txt")
  printf '  f64 / f32, %-6s  %5.2f× (best: %5.2f×)   (target for wide ≥ 1.7×)\n' "$e" \
    "$(echo "$f64 / $f32" | bc -l)" \
    "$(echo "$(least <"$work/phong-f64-$e.txt") / $(least <"$work/phong-f32-$e.txt")" | bc -l)"
done
echo
echo "trace time, wide engine, two threads (seconds):"
for p in f64 f32; do
  t=$(median <"$work/phong-$p-wide-2.txt")
  b=$(least <"$work/phong-$p-wide-2.txt")
  one=$(median <"$work/phong-$p-wide.txt")
  printf '  phong %s wide    %8.3f %8.3f   one thread / two = %5.2f× (best: %5.2f×)   (target ≥ 1.9×)\n' \
    "$p" "$t" "$b" "$(echo "$one / $t" | bc -l)" "$(echo "$(least <"$work/phong-$p-wide.txt") / $b" | bc -l)"
done
echo

echo "whole process, wall time:"
if command -v hyperfine >/dev/null; then
  named=(-n povray "${pov_cmd[*]}")
  for name in $phongs; do
    command_for "$name"
    named+=(-n "$name" "${cmd[*]}")
  done
  hyperfine --style basic --warmup 1 --runs "$runs" \
    --export-json "$work/wall.json" "${named[@]}" >/dev/null
  python3 - "$work/wall.json" <<'EOF'
import json, sys
r = {x["command"]: x for x in json.load(open(sys.argv[1]))["results"]}
pov = r["povray"]["median"]
sd = r["povray"]["stddev"]  # null with a single run
spread = f" ± {sd:.3f}" if sd is not None else ""
print(f"  {'POV-Ray':<16} {pov:8.3f} s (median; mean {r['povray']['mean']:.3f}{spread})")
for p in ("phong-f64-wide", "phong-f32-wide", "phong-f64-scalar", "phong-f32-scalar"):
    t = r[p]["median"]
    print(f"  {p:<16} {t:8.3f} s   POV-Ray / phong = {pov / t:5.2f}×   (target ≥ 8×)")
EOF
else
  for name in povray $phongs; do
    : >"$work/wall-$name.txt"
  done
  for ((i = 0; i < runs; i++)); do
    for name in povray $phongs; do
      command_for "$name"
      start=$(date +%s.%N)
      "${cmd[@]}" >/dev/null 2>&1
      echo "$(date +%s.%N) - $start" | bc -l >>"$work/wall-$name.txt"
    done
  done
  pw=$(median <"$work/wall-povray.txt")
  printf '  %-16s %8.3f s (median)\n' POV-Ray "$pw"
  for name in $phongs; do
    t=$(median <"$work/wall-$name.txt")
    printf '  %-16s %8.3f s   POV-Ray / phong = %5.2f×   (target ≥ 8×)\n' "$name" "$t" "$(echo "$pw / $t" | bc -l)"
  done
fi

# On a shared machine wall times include waiting for a core; CPU time (user + sys, from
# /usr/bin/time) of the whole process is steadier.
if [ -x /usr/bin/time ]; then
  echo
  echo "whole process, CPU time (user + sys), median of $runs:"
  for name in povray $phongs; do : >"$work/cpu-$name.txt"; done
  for ((i = 0; i < runs; i++)); do
    for name in povray $phongs; do
      command_for "$name"
      /usr/bin/time -f '%U %S' -o "$work/t" "${cmd[@]}" >/dev/null 2>&1
      awk '{print $1 + $2}' "$work/t" >>"$work/cpu-$name.txt"
    done
  done
  pc=$(median <"$work/cpu-povray.txt")
  printf '  %-16s %8.3f s\n' POV-Ray "$pc"
  for name in $phongs; do
    t=$(median <"$work/cpu-$name.txt")
    printf '  %-16s %8.3f s   POV-Ray / phong = %5.2f×\n' "$name" "$t" "$(echo "$pc / $t" | bc -l)"
  done
fi
