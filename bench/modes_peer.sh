#!/bin/bash
# Contact modes from rest against the float MATLAB peer contact_mode_enumeration_2d (XianyiCheng, tol 1e-6) run in
# Octave, on the same contacts: a convex polygon with k = 4 ... 64 fixels in convex position on its lower chain
# (bench/modes_polygons.py), touching; and the same fixels at a gap, which only contactcert enumerates (the peer
# takes touching contacts). Side by side in one run; per k the best of R runs of each, CPU seconds: the peer timed
# inside Octave around contact_mode_enumeration (start-up excluded), contactcert as the whole `modes` process
# (user + sys, start-up included), and their ratio (contactcert / peer: below 1, contactcert is faster); net_ratio
# takes contactcert's start-up (`modes` on a two-fixel scene) off its time first. The peer's code is not part of
# this repository: fetch it into a folder and pass that folder.
#   bench/modes_peer.sh PEER_DIR [CONTACTCERT (build/cli/contactcert)] [R (3)]
# Needs octave-cli (Debian: apt-get install --no-install-recommends octave; installed here if missing and root).
set -euo pipefail
peer=$(cd "${1:?usage: bench/modes_peer.sh PEER_DIR [CONTACTCERT] [R]}" && pwd)
repo=$(cd "$(dirname "$0")/.." && pwd)
cc=${2:-$repo/build/cli/contactcert}
runs=${3:-3}
[ -f "$peer/contact_mode_enumeration.m" ] || { echo "no contact_mode_enumeration.m in $peer" >&2; exit 2; }
[ -x "$cc" ] || { echo "no $cc (build first)" >&2; exit 2; }
if ! command -v octave-cli > /dev/null; then
  [ "$(id -u)" = 0 ] || { echo "octave-cli is missing" >&2; exit 2; }
  apt-get install -y --no-install-recommends octave > /dev/null
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The best user + sys CPU seconds of `runs` runs of the command.
best_cpu() {
  python3 "$repo/bench/best_cpu.py" "$runs" "$@"
}

# contactcert's own start-up (a scene of two fixels), taken off its times in the net column: the peer's times have none.
python3 "$repo/bench/modes_polygons.py" 2 touching "$work/two.json"
start=$(best_cpu "$cc" modes "$work/two.json")
echo "contactcert start-up (modes on two fixels): $start s"
printf "%-10s %4s %8s %10s %14s %8s %10s\n" scene k modes peer_s contactcert_s ratio net_ratio
for k in 4 8 16 32 64; do
  python3 "$repo/bench/modes_polygons.py" "$k" touching "$work/poly$k.json" "$work/poly$k.m"
  python3 "$repo/bench/modes_polygons.py" "$k" gap "$work/gap$k.json"
  cat > "$work/run$k.m" << OCTAVE
addpath('$peer'); source('$work/poly$k.m');
best = inf;
for r = 1:$runs
  t0 = cputime; M = contact_mode_enumeration(P, N, false); best = min(best, cputime - t0);
end
printf('%d %.4f\n', size(M, 2), best);
OCTAVE
  read -r peer_modes peer_s < <(octave-cli --no-gui -q "$work/run$k.m" 2> /dev/null | tail -1)
  cc_s=$(best_cpu "$cc" modes "$work/poly$k.json")
  cc_modes=$("$cc" modes "$work/poly$k.json" --json | python3 -c 'import json,sys; print(len(json.load(sys.stdin)["modes"]))')
  printf "%-10s %4d %8s %10s %14s %8s %10s\n" touching "$k" "$cc_modes/$peer_modes" "$peer_s" "$cc_s" \
    "$(awk -v a="$cc_s" -v b="$peer_s" 'BEGIN { printf "%.2f", a / b }')" \
    "$(awk -v a="$cc_s" -v s="$start" -v b="$peer_s" 'BEGIN { printf "%.2f", (a - s) / b }')"
done
for k in 4 8 16 32 64; do
  cc_s=$(best_cpu "$cc" modes "$work/gap$k.json")
  cc_modes=$("$cc" modes "$work/gap$k.json" --json | python3 -c 'import json,sys; print(len(json.load(sys.stdin)["modes"]))')
  printf "%-10s %4d %8s %10s %14s %8s %10s\n" gap "$k" "$cc_modes" "-" "$cc_s" "-" "-"
done
