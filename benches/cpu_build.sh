#!/usr/bin/env bash
# What building for the machine's own CPU buys (issue 32: "f32 buys speed in the binary users
# install"): the release binary `cargo install --path .` builds (`.cargo/config.toml`:
# -C target-cpu=native, AVX2 lanes on this machine) against a build for any x86-64 CPU
# (RUSTFLAGS="-C target-cpu=x86-64": SSE2, two halves per 256-bit register), side by side in one
# run, ONE thread: the classic scene and the many-spheres scene with 7, 10,000 and 100,000
# objects (`scenes/many_spheres.rs`, as benches/vs_povray_sizes.sh), 640×480, level 5, one
# sample, f64 and f32. Each round runs every case once with each build, alternating; the
# figures are the medians of RUNS rounds of phong's own trace time (`--stats`), and the ratios
# portable / native (each precision) and f64 / f32 (each build; the issue's target ≥ 1.5× for
# the installed build). The images of both builds are compared byte for byte on the way.
# Usage: benches/cpu_build.sh [RUNS]   (default 11; builds both binaries first, minutes each)
# NATIVE=path PORTABLE=path MANY_SPHERES=path use those binaries instead of building them.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-11}

[ -n "${NATIVE:-}" ] || cargo build --release --quiet
[ -n "${MANY_SPHERES:-}" ] || cargo build --release --quiet --example many_spheres
many=${MANY_SPHERES:-target/release/examples/many_spheres}
[ -n "${PORTABLE:-}" ] ||
  RUSTFLAGS="-C target-cpu=x86-64" CARGO_TARGET_DIR=target/portable cargo build --release --quiet
native=${NATIVE:-target/release/phong}
portable=${PORTABLE:-target/portable/release/phong}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cases="classic s7 s10000 s100000"
cp scenes/classic.json "$work/classic.json"
for n in 7 10000 100000; do
  "$many" $((n - 1)) >"$work/s$n.json"
done

# median, trace_time
source benches/common.sh

echo "machine: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo "native:   $native (.cargo/config.toml: -C target-cpu=native)"
echo "portable: $portable (RUSTFLAGS=\"-C target-cpu=x86-64\")"
echo "each: phong render SCENE -o OUT.ppm --max-level 5 --samples 1 --threads 1 --precision P --stats"
echo "$runs alternating rounds; medians of the trace time"
echo

for ((i = 0; i < runs; i++)); do
  for c in $cases; do
    for p in f64 f32; do
      for b in native portable; do
        bin=$native
        [ "$b" = portable ] && bin=$portable
        "$bin" render "$work/$c.json" -o "$work/$b.ppm" --max-level 5 --samples 1 --threads 1 \
          --precision "$p" --stats 2>&1 | trace_time >>"$work/$b-$p-$c.txt"
      done
      cmp -s "$work/native.ppm" "$work/portable.ppm" ||
        { echo "the two builds wrote different images: $c, $p" >&2; exit 1; }
    done
  done
done

printf '%-9s %9s %9s %9s %9s %11s %11s %11s %11s\n' scene "nat f64" "nat f32" "port f64" "port f32" \
  "port/nat64" "port/nat32" "f64/f32 nat" "f64/f32 port"
for c in $cases; do
  n64=$(median <"$work/native-f64-$c.txt")
  n32=$(median <"$work/native-f32-$c.txt")
  p64=$(median <"$work/portable-f64-$c.txt")
  p32=$(median <"$work/portable-f32-$c.txt")
  printf '%-9s %9.4f %9.4f %9.4f %9.4f %10.2f× %10.2f× %10.2f× %10.2f×\n' "$c" "$n64" "$n32" "$p64" "$p32" \
    "$(echo "$p64 / $n64" | bc -l)" "$(echo "$p32 / $n32" | bc -l)" \
    "$(echo "$n64 / $n32" | bc -l)" "$(echo "$p64 / $p32" | bc -l)"
done
echo
echo "the images of the two builds: the same bytes in every case"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
