#!/usr/bin/env bash
# End-to-end comparison of `prt precompute` with a straightforward Embree-based precompute of the
# same work (bench/embree_precompute.cpp, built with -DPRT_BENCH_EMBREE=ON), as whole processes
# in alternation.
#
#   bench/precompute_vs_embree.sh [-n PAIRS] [-t THREADS] PRT BASELINE [MESH [ENV]]
#
# PRT is the prt binary, BASELINE the prt_embree_precompute binary. MESH and ENV default to
# ../shared/data/games202/mary/mary.obj and ../shared/data/games202/cubemap/GraceCathedral
# relative to the repository root. The work: shadowed transport, lmax 2, 1024 fibonacci
# directions per vertex, all threads (or -t THREADS, given to both).
#
# After one warm-up run of each, it times PAIRS pairs (default 7) of whole processes, alternating
# which of the two goes first, each writing into a fresh temporary folder:
#   phase 1: prt precompute --cache none (fair: the baseline writes no cache) against the baseline;
#   phase 2: prt precompute with its default cache (written each run: the folder is fresh)
#            against the baseline.
# Prints key=value lines: the CPU model, the threads, each side's median wall time, and
# ratio_prt_vs_embree_precompute = the median over the phase-1 pairs of (prt time / baseline
# time) (target: <= 0.8); ratio_prt_cache_vs_embree_precompute the same for phase 2. It also
# checks that the two transport.txt files agree (transport_max_abs_diff, 0 when identical), and
# with GNU time prints the median CPU times (user + system), and the load average before and
# after: on a machine shared with other work, wall times are only as good as the machine is idle.
set -euo pipefail

usage() {
  echo "usage: $0 [-n PAIRS] [-t THREADS] PRT BASELINE [MESH [ENV]]" >&2
  exit 2
}

pairs=7
threads=""
while getopts "n:t:h" opt; do
  case "$opt" in
    n) pairs="$OPTARG" ;;
    t) threads="$OPTARG" ;;
    *) usage ;;
  esac
done
shift $((OPTIND - 1))
[ $# -ge 2 ] && [ $# -le 4 ] || usage
[[ "$pairs" =~ ^[1-9][0-9]*$ ]] || { echo "$0: -n: expected a positive integer, got '$pairs'" >&2; exit 2; }
[ -z "$threads" ] || [[ "$threads" =~ ^[0-9]+$ ]] || { echo "$0: -t: expected an integer, got '$threads'" >&2; exit 2; }

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
prt="$1"
baseline="$2"
mesh="${3:-$root/../shared/data/games202/mary/mary.obj}"
env="${4:-$root/../shared/data/games202/cubemap/GraceCathedral}"

for bin in "$prt" "$baseline"; do
  [ -x "$bin" ] || { echo "$0: '$bin' is not an executable file (build prt and prt_embree_precompute, the latter with -DPRT_BENCH_EMBREE=ON)" >&2; exit 1; }
done
if [ ! -f "$mesh" ]; then
  echo "$0: mesh '$mesh' not found (the default is the GAMES202 'mary' model in ../shared/data/games202/mary/mary.obj next to the repository; give MESH explicitly)" >&2
  exit 1
fi
if [ ! -e "$env" ]; then
  echo "$0: environment '$env' not found (the default is the GAMES202 cubemap folder ../shared/data/games202/cubemap/GraceCathedral next to the repository; give ENV explicitly, e.g. a built-in name such as 'sky')" >&2
  exit 1
fi

work="$(mktemp -d "${TMPDIR:-/tmp}/prt-vs-embree.XXXXXX")"
trap 'rm -rf "$work"' EXIT

common=(--mesh "$mesh" --env "$env" --samples 1024 --quiet)
[ -z "$threads" ] || common+=(--threads "$threads")

# CPU time (user + system) of each run too, where /usr/bin/time (GNU time) is there: on a
# machine shared with other work the wall time also measures the others, the CPU time less so.
gnu_time=""
if [ -x /usr/bin/time ] && /usr/bin/time -f "%U" -o /dev/null true 2>/dev/null; then gnu_time=/usr/bin/time; fi

# Runs one whole process (which: prt | prt_cache | embree) into a fresh folder $work/out.<which>;
# prints its wall time in seconds, and appends its CPU time to $work/<which>.cpu. Fails the
# script, showing its output, if it fails.
run_one() {
  local which="$1" out="$work/out.$1" log="$work/log.$1" t0 t1
  rm -rf "$out"
  local cmd
  case "$which" in
    prt) cmd=("$prt" precompute "${common[@]}" --cache none --out "$out") ;;
    prt_cache) cmd=("$prt" precompute "${common[@]}" --out "$out") ;;
    embree) cmd=("$baseline" "${common[@]}" --out "$out") ;;
  esac
  [ -z "$gnu_time" ] || cmd=("$gnu_time" -f "%U %S" -o "$work/cpu.last" "${cmd[@]}")
  t0=$(date +%s.%N)
  if ! "${cmd[@]}" >"$log" 2>&1; then
    echo "$0: this run failed: ${cmd[*]}" >&2
    cat "$log" >&2
    exit 1
  fi
  t1=$(date +%s.%N)
  [ -z "$gnu_time" ] || awk '{ printf "%.2f\n", $1 + $2 }' "$work/cpu.last" >>"$work/$which.cpu"
  awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.6f\n", b - a }'
}

median() {  # of the numbers on stdin, one per line
  sort -g | awk '{ v[NR] = $1 } END { if (NR % 2) printf "%.6f\n", v[(NR + 1) / 2]; else printf "%.6f\n", (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

# One phase: PAIRS pairs of (prt variant, baseline), alternating which goes first. Fills
# $work/<variant>.times, $work/embree.<variant>.times and $work/<variant>.ratios.
phase() {
  local variant="$1" i tp te
  : >"$work/$variant.times"; : >"$work/embree.$variant.times"; : >"$work/$variant.ratios"
  for ((i = 0; i < pairs; i++)); do
    if ((i % 2 == 0)); then
      tp=$(run_one "$variant"); te=$(run_one embree)
    else
      te=$(run_one embree); tp=$(run_one "$variant")
    fi
    echo "$tp" >>"$work/$variant.times"
    echo "$te" >>"$work/embree.$variant.times"
    awk -v p="$tp" -v e="$te" 'BEGIN { printf "%.6f\n", p / e }' >>"$work/$variant.ratios"
  done
}

cpu_model="$(lscpu 2>/dev/null | sed -n 's/^Model name:[[:space:]]*//p' | head -n 1)"
[ -n "$cpu_model" ] || cpu_model="$(sed -n 's/^model name[[:space:]]*:[[:space:]]*//p' /proc/cpuinfo | head -n 1)"
echo "cpu_model=${cpu_model:-unknown}"
echo "threads=${threads:-$(nproc) (all)}"
echo "mesh=$mesh"
echo "env=$env"
echo "pairs=$pairs"

echo "loadavg_before=$(cut -d ' ' -f 1-3 /proc/loadavg 2>/dev/null || echo unknown)"

# Warm-up (page cache, first-touch of the binaries and data), and the outputs checked.
run_one prt >/dev/null
run_one embree >/dev/null
run_one prt_cache >/dev/null
rm -f "$work"/*.cpu  # the warm-up's CPU times are not counted
cmp -s "$work/out.prt/light.txt" "$work/out.embree/light.txt" && echo "light_identical=yes" || echo "light_identical=no"
if cmp -s "$work/out.prt/transport.txt" "$work/out.embree/transport.txt"; then
  echo "transport_identical=yes"
else
  echo "transport_identical=no"
fi
paste -d ' ' "$work/out.prt/transport.txt" "$work/out.embree/transport.txt" | awk '
  NR == 1 { if ($1 != $2) bad = 1; next }
  { h = NF / 2; if (h != int(h)) bad = 1
    for (i = 1; i <= h; i++) { d = $i - $(i + h); if (d < 0) d = -d; if (d > m) m = d; if (d > 0) n++ } }
  END { printf "transport_max_abs_diff=%g\ntransport_numbers_differing=%d\n", m, n; if (bad) print "transport_layout_differs=yes" }'

phase prt
phase prt_cache

echo "median_prt_s=$(median <"$work/prt.times")"
echo "median_embree_s=$(median <"$work/embree.prt.times")"
echo "ratio_prt_vs_embree_precompute=$(median <"$work/prt.ratios")"
echo "median_prt_cache_s=$(median <"$work/prt_cache.times")"
echo "median_embree_s_cache_phase=$(median <"$work/embree.prt_cache.times")"
echo "ratio_prt_cache_vs_embree_precompute=$(median <"$work/prt_cache.ratios")"
if [ -n "$gnu_time" ]; then
  echo "median_prt_cpu_s=$(median <"$work/prt.cpu")"
  echo "median_prt_cache_cpu_s=$(median <"$work/prt_cache.cpu")"
  echo "median_embree_cpu_s=$(median <"$work/embree.cpu")"
fi
echo "loadavg_after=$(cut -d ' ' -f 1-3 /proc/loadavg 2>/dev/null || echo unknown)"
echo "ratios_prt=$(paste -sd ' ' "$work/prt.ratios")"
echo "ratios_prt_cache=$(paste -sd ' ' "$work/prt_cache.ratios")"
