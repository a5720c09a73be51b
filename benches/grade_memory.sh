#!/usr/bin/env bash
# `phong grade`'s peak memory for a header and 1,000,000 rows (issue 30, item 1): the rows of
# benches/grade.rs (right answers, the 4.2 slip, the intended readings, wrong answers with no
# slip, 8-bit answers, malformed rows; one student a row, the worst case for the per-student
# totals), graded into each report format, with --summary and --by-student once. The figure is
# the maximum resident set size that GNU time reports; the budget is 300 MB for every format.
# This is a measurement, not a test: nothing is timed, and the time shown is for information.
#
# Usage: benches/grade_memory.sh [PHONG]   (default: target/release/phong, built here; needs
#        GNU time at /usr/bin/time and python3 to write the file)
# Exit: 0 when every format is within the budget, 1 otherwise.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -ge 1 ]; then
  phong=$1
else
  cargo build --release --quiet --bin phong
  phong=target/release/phong
fi
[ -x /usr/bin/time ] || { echo "GNU time is not installed (apt-get install time)" >&2; exit 2; }
budget_kb=$((300 * 1000))
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 - "$work/1m.csv" <<'PY'
import sys
answers = [("4.1", "0.5 0.7 0.3"), ("4.2", "0.245 0.28 0.21"),
           ("4.2", '"0.299, 0.361, 0.318"'), ("4.2", "0 0 0"), ("4.3", "(0.52 0.03 0)"),
           ("4.3", "0.9 0.9 0.9"), ("4.1", "#80B34D"), ("spot-inside", "0.79 0.95 0.85"),
           ("several-lights", "0.5 0.5 0.5"), ("4.1", "not an answer")]
with open(sys.argv[1], "w") as f:
    f.write("student,exercise,answer\n")
    for i in range(1_000_000):
        exercise, answer = answers[i % len(answers)]
        f.write(f"student{i},{exercise},{answer}\n")
PY
status=0
run() {
  local label=$1; shift
  /usr/bin/time -v "$phong" grade "$work/1m.csv" --exercises exercises "$@" 2> "$work/time.txt" \
    || { echo "$label: phong failed"; cat "$work/time.txt"; status=1; return; }
  local kb wall
  kb=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/time.txt")
  wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$work/time.txt")
  printf '%-34s %6d MB  (%s)\n' "$label" $((kb / 1000)) "$wall"
  [ "$kb" -le "$budget_kb" ] || { echo "  over the 300 MB budget"; status=1; }
}
for format in csv json junit gradescope xlsx; do
  run "--format $format" --format "$format" -o "$work/out.$format"
done
run "--format csv --summary --by-student" -o "$work/out.csv" --summary "$work/summary.csv" \
  --by-student "$work/students.csv"
exit $status
