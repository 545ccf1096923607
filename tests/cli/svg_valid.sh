#!/usr/bin/env bash
# Every SVG contactcert writes is well-formed XML (xmllint --noout): the region and finger pictures of
# `stability`, the cone pictures, `insert --svg`, the demo report (index.html is well-formed XML with its inline
# SVG) and, when BENCH=1, the bench plots. A scene name with XML specials checks that text is escaped.
# Usage: svg_valid.sh CONTACTCERT REPO_DIR WORK_DIR [BENCH]
set -u
cc=$1 repo=$2 work=$3 bench=${4:-0}
s=$repo/scenes
mkdir -p "$work"
failures=0
lint() {
  if ! xmllint --noout "$1" 2> "$work/lint.err"; then
    echo "NOT WELL-FORMED: $1"
    head -5 "$work/lint.err"
    failures=$((failures + 1))
  else
    echo "ok: $1"
  fi
}
run() {
  if ! "$cc" "$@" > "$work/out" 2> "$work/err"; then
    echo "FAILED: contactcert $*"
    cat "$work/err"
    failures=$((failures + 1))
  fi
}
run stability "$s/bt2002_section7_disk.json" --region --wrench 0,-1,0 --svg "$work/region.svg"
lint "$work/region.svg"
run stability "$s/bt2002_fig10_pentagon_insert.json" --finger --svg "$work/finger_pentagon.svg"
lint "$work/finger_pentagon.svg"
run stability "$s/bt2002_section7_disk.json" --finger --svg "$work/finger_disk.svg"
lint "$work/finger_disk.svg"
for spec in section4_disk:na fig4a_lla:lla fig4b_nnn:nnn fig4c_peg_lra:lra fig4d_peg_nn:nn; do
  run cone "$s/bt2002_${spec%%:*}.json" --mode "${spec##*:}" --svg "$work/cone_${spec%%:*}.svg"
  lint "$work/cone_${spec%%:*}.svg"
done
run insert "$s/bt2002_fig10_pentagon_insert.json" --svg "$work/insert.svg"
lint "$work/insert.svg"
run demo --out "$work/demo"
lint "$work/demo/index.html"
if [ "$bench" = 1 ]; then
  run bench --suite paper --quick --out "$work/bench"
  for f in "$work"/bench/*.svg "$work/bench/index.html"; do lint "$f"; done
fi
echo "svg: $failures failures"
exit $((failures > 0))
