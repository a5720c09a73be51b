# Shared by the bench scripts (sourced, not run): the median and phong's own times.

# The median of the numbers on standard input, one a line.
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }

# phong's `--stats` line, "read and validated in A s, … prepared … in B s, traced … in C s":
# "A B C".
phong_times() {
  sed -n 's/.*validated in \([0-9.]*\) s, .* in \([0-9.]*\) s, traced .* in \([0-9.]*\) s: .*/\1 \2 \3/p'
}

# The trace time C of phong's `--stats` line.
trace_time() { phong_times | cut -d' ' -f3; }
