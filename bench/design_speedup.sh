#!/usr/bin/env bash
# Speed-up of `contactcert design` at np = 2 against np = 1 (run by hand on an otherwise idle machine):
# the ratchet pawl, N candidates (default 60: C(60, 3) = 34 220 placements), strongly stable under gravity and
# insertable. Prints the wall time of each run, the ratio, every rank's CPU time (user + system, from
# /usr/bin/time), the ratio of the serial CPU time to the busiest rank's (what the wall ratio is on idle cores)
# and whether both runs printed the same result.
# Usage: bench/design_speedup.sh [N] [CONTACTCERT]   (default N = 60, CONTACTCERT = build/cli/contactcert)
set -eu
n=${1:-60}
cc=$(realpath "${2:-build/cli/contactcert}")
repo=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=(design "$repo/scenes/design_ratchet_pawl.json" --candidates "$n" --stable-under 0,-1,0 --insertable --top 3 --json)

# run NP: wall seconds of one mpirun; each rank's CPU seconds go to $work/cpu_NP.rank
run() {
  local np=$1 start end
  start=$(date +%s.%N)
  mpirun --oversubscribe --allow-run-as-root -np "$np" bash -c \
    '/usr/bin/time -f "%U %S" -o "$0/cpu_$1.$OMPI_COMM_WORLD_RANK" "${@:2}" --out "$0/out"' \
    "$work" "$np" "$cc" "${args[@]}" > "$work/result_$np.json"
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN { print b - a }' 
}

echo "design on the pawl, $n candidates, $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
wall1=$(run 1)
wall2=$(run 2)
for np in 1 2; do
  for f in "$work"/cpu_$np.*; do
    printf 'np = %d, rank %s: CPU %.2f s\n' "$np" "${f##*.}" "$(awk '{print $1 + $2}' "$f")"
  done
done
cpu1=$(awk '{print $1 + $2}' "$work"/cpu_1.0)
cpu2=$(cat "$work"/cpu_2.* | awk '{t = $1 + $2; if (t > m) m = t} END {print m}')
printf 'CPU: np = 1 %.2f s, busiest rank at np = 2 %.2f s, ratio %.2fx (the wall speed-up on two idle cores)\n' \
  "$cpu1" "$cpu2" "$(awk -v a="$cpu1" -v b="$cpu2" 'BEGIN { print a / b }')"
printf 'wall: np = 1 %.2f s, np = 2 %.2f s, speed-up %.2fx (target >= 1.8x)\n' "$wall1" "$wall2" \
  "$(awk -v a="$wall1" -v b="$wall2" 'BEGIN { print a / b }')"
if cmp -s "$work/result_1.json" "$work/result_2.json"; then echo "results: identical"; else echo "results: DIFFER"; exit 1; fi
