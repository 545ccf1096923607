#!/bin/bash
# Contact modes in space against the float 3-D peer of Huang, Cheng and Mason ("Efficient contact mode enumeration
# in 3D": the contact_modes repository, Python with qhull through pyhull, eps 1e-6 and float32 tolerances), on the
# contacts of bench/spatial_bench's scenes (box on a plane and peg in a square hole, k = 4, 8, 16, 32, square
# pyramids mu = 1/2), the box on k contacts in convex position ("disk"), the 4-contact box with one contact
# perturbed (corner 0 moved by 10^-e along x, or its normal tilted by 10^-e) and the box in a corner. Side by side in one run; per scene the best of R runs of each, CPU seconds: the peer
# timed inside Python around enum_sliding_sticking_3d_proj (imports excluded; bench/spatial_peer.py), contactcert
# as the whole `modes SCENE --json` process (user + sys, start-up included), their ratio (contactcert / peer: below
# 1, contactcert is faster) and net_ratio, contactcert's start-up (`modes` on a one-contact scene) taken off first.
# modes and c/s are contactcert's / the peer's counts of modes and of contacting/separating patterns; agree says
# whether the peer's modes mapped to our letters are exactly our list (bench/spatial_peer.py states the mapping).
# The peer's code is not part of this repository: fetch it into a folder and pass that folder; pyhull (not packaged
# by Debian) likewise, a copy of its source in PYHULL_DIR (default PEER_DIR/../pyhull), built here if needed.
#   bench/spatial_peer.sh PEER_DIR [CONTACTCERT (build/cli/contactcert)] [SPATIAL_BENCH (build-bench/bench/spatial_bench)] [R (3)]
# Needs python3-numpy and python3-scipy (Debian; installed here if missing and root) and a C compiler for pyhull.
set -euo pipefail
usage="usage: bench/spatial_peer.sh PEER_DIR [CONTACTCERT] [SPATIAL_BENCH] [R]"
[ -d "${1:-}" ] || { echo "no peer folder '${1:-}'; $usage" >&2; exit 2; }
peer=$(cd "$1" && pwd)
repo=$(cd "$(dirname "$0")/.." && pwd)
cc=${2:-$repo/build/cli/contactcert}
sb=${3:-$repo/build-bench/bench/spatial_bench}
runs=${4:-3}
py=/usr/bin/python3  # Debian's, where its numpy and scipy are
pyhull=${PYHULL_DIR:-$peer/../pyhull}
[ -f "$peer/python/src/contact_modes/modes_3d.py" ] || {
  echo "no python/src/contact_modes/modes_3d.py in $peer" >&2
  exit 2
}
[ -x "$cc" ] || { echo "no $cc (build first)" >&2; exit 2; }
[ -x "$sb" ] || { echo "no $sb (build with -DCONTACTCERT_BENCH=ON first)" >&2; exit 2; }
[ -f "$pyhull/pyhull/__init__.py" ] || {
  echo "no pyhull in $pyhull (a copy of the pyhull source; set PYHULL_DIR)" >&2
  exit 2
}
if ! "$py" -c 'import numpy, scipy' 2> /dev/null; then
  [ "$(id -u)" = 0 ] || { echo "python3-numpy and python3-scipy are missing" >&2; exit 2; }
  apt-get install -y --no-install-recommends python3-numpy python3-scipy > /dev/null
fi
if ! (cd "$pyhull" && "$py" -c 'import pyhull._pyhull') 2> /dev/null; then
  (cd "$pyhull" && "$py" setup.py build_ext --inplace > /dev/null 2>&1) || {
    echo "pyhull does not build in $pyhull" >&2
    exit 2
  }
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The best user + sys CPU seconds of `runs` runs of the command.
best_cpu() {
  "$py" "$repo/bench/best_cpu.py" "$runs" "$@"
}

"$sb" --scenes "$work" > /dev/null
# The perturbed boxes (no `box` key where a point leaves the box's surface); the box body on k contacts in convex
# position (rational points near the unit circle, at angles 2 pi (i + 1/2) / k: no contact's row is a combination
# of the others'); scenes/spatial_box_in_corner.json with square pyramids everywhere (its wall contacts keep their
# frames); one contact for contactcert's start-up.
"$py" - "$work" "$repo/scenes/spatial_box_in_corner.json" << 'PY'
import json, math, sys
from fractions import Fraction
work = sys.argv[1]
box = json.load(open(work + "/box_4.json"))
for k in (4, 8, 16, 32):
    disk = json.loads(json.dumps(box))
    del disk["body"]["box"]
    disk["contacts"] = []
    for i in range(k):
        t = Fraction(math.tan(math.pi * (i + 0.5) / k)).limit_denominator(50)  # tan of half the angle
        x, y = (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)
        disk["contacts"].append({"point": [str(x), str(y), 0], "normal": [0, 0, 1]})
    json.dump(disk, open("%s/disk_%d.json" % (work, k), "w"))
corner = json.load(open(sys.argv[2]))
for contact in corner["contacts"]:
    contact.pop("edges", None)
json.dump(corner, open(work + "/corner.json", "w"))
for e in (5, 6, 9):
    shift = json.loads(json.dumps(box))
    del shift["body"]["box"]
    shift["contacts"][0]["point"][0] = "%d/%d" % (10**e + 1, 10**e)
    json.dump(shift, open("%s/shift_%d.json" % (work, e), "w"))
for e in (4, 7, 9):
    tilt = json.loads(json.dumps(box))
    tilt["contacts"][0]["normal"] = ["-1/%d" % 10**e, 0, 1]
    json.dump(tilt, open("%s/tilt_%d.json" % (work, e), "w"))
one = json.loads(json.dumps(box))
one["contacts"] = one["contacts"][:1]
json.dump(one, open(work + "/one.json", "w"))
PY
start=$(best_cpu "$cc" modes "$work/one.json" --json)
echo "contactcert start-up (modes on one contact): $start s"
printf "%-9s %3s %12s %8s %10s %9s %14s %7s %9s\n" scene k modes c/s agree peer_s contactcert_s ratio net_ratio
row() {  # scene-file label k
  local f=$work/$1.json ours peer_modes peer_unique peer_cs peer_s agree cc_s ratio net
  "$cc" modes "$f" --json > "$work/ours.json"
  timeout 600 "$py" "$repo/bench/spatial_peer.py" "$peer" "$pyhull" "$f" "$work/ours.json" "$runs" > "$work/peer.txt" ||
    echo "? ? - - - - peer_timeout_or_crash" > "$work/peer.txt"
  read -r ours ours_cs peer_modes peer_unique peer_cs peer_s agree < "$work/peer.txt"
  cc_s=$(best_cpu "$cc" modes "$f" --json)
  ratio=-
  net=-
  if [ "$peer_s" != - ]; then
    ratio=$(awk -v a="$cc_s" -v b="$peer_s" 'BEGIN { printf "%.2f", a / b }')
    net=$(awk -v a="$cc_s" -v s="$start" -v b="$peer_s" 'BEGIN { printf "%.2f", (a - s) / b }')
  fi
  [ "$peer_unique" = "$peer_modes" ] || peer_modes="$peer_modes($peer_unique distinct)"
  printf "%-9s %3s %12s %8s %10s %9s %14s %7s %9s\n" "$2" "$3" "$ours/$peer_modes" "$ours_cs/$peer_cs" "$agree" \
    "$peer_s" "$cc_s" "$ratio" "$net"
  sed -n '2,$p' "$work/peer.txt"
}
for scene in box peg disk; do
  for k in 4 8 16 32; do row "${scene}_$k" "$scene" "$k"; done
done
for e in 5 6 9; do row "shift_$e" "shift1e-$e" 4; done
for e in 4 7 9; do row "tilt_$e" "tilt1e-$e" 4; done
row corner corner 6
