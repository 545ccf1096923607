#!/usr/bin/env bash
# Every SVG contactcert writes is well-formed XML (xmllint --noout): the region and finger pictures of
# `stability`, the cone pictures, `insert --svg`, the demo report (index.html is well-formed XML with its inline
# SVG) and, when BENCH=1, the bench plots. Also: the labels of a cone picture stay on its canvas and do not sit
# on top of each other, the demo report plots Figure 11, no bench table is wider than 12 columns, no number in a
# bench table may wrap, and the time-vs-error plot has its strip for errors of exactly 0.
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
run simulate "$s/motion_block_wall.json" --compare --svg "$work/simulate.svg"
lint "$work/simulate.svg"
# Labels of a cone picture: inside the canvas once the drawing's translate() is applied, no two at one spot.
labels_ok() {
  awk -v file="$1" '
    /^<svg/ { match($0, /width="[0-9.]+"/); W = substr($0, RSTART + 7, RLENGTH - 8) + 0
              match($0, /height="[0-9.]+"/); H = substr($0, RSTART + 8, RLENGTH - 9) + 0 }
    /^<g transform="translate\(/ && !inlegend { match($0, /translate\([-0-9.]+,[-0-9.]+\)/)
              split(substr($0, RSTART + 10, RLENGTH - 11), t, ","); dx = t[1]; dy = t[2]; ingroup = 1; next }
    /^<\/g>/ { ingroup = 0; inlegend = 1 }
    ingroup && /^<text/ { match($0, /x="[-0-9.]+"/); x = substr($0, RSTART + 3, RLENGTH - 4) + dx
              match($0, /y="[-0-9.]+"/); y = substr($0, RSTART + 3, RLENGTH - 4) + dy
              if (x < 0 || y < 10 || x > W - 5 || y > H) { print file ": label off the canvas at " x "," y; bad = 1 }
              key = int(x / 8) "," int(y / 8); if (key in seen) { print file ": two labels at " x "," y; bad = 1 }
              seen[key] = 1 }
    END { exit bad }' "$1"
}
for spec in section4_disk fig4c_peg_lra fig4d_peg_nn; do
  labels_ok "$work/cone_$spec.svg" || failures=$((failures + 1))
done
run insert "$s/bt2002_fig10_pentagon_insert.json" --svg "$work/insert.svg"
lint "$work/insert.svg"
for spatial in box_on_plane box_in_corner peg_in_hole; do
  run modes "$s/spatial_$spatial.json" --svg "$work/spatial_$spatial.svg"
  lint "$work/spatial_$spatial.svg"
done
run assembly "$s/assembly_pushed_box_weak.json" --svg "$work/assembly.svg"
lint "$work/assembly.svg"
run assembly --ucp "$s/assembly_pushed_boxes.json" --svg "$work/assembly_ucp.svg"
lint "$work/assembly_ucp.svg"
run demo --out "$work/demo"
lint "$work/demo/index.html"
grep -q 'Figure 11: pushes that seat the part' "$work/demo/index.html" || { echo "demo: no Figure 11 plot"; failures=$((failures + 1)); }
if [ "$bench" = 1 ]; then
  run bench --suite paper --quick --out "$work/bench"
  for f in "$work"/bench/*.svg "$work/bench/index.html"; do lint "$f"; done
  widest=$(sed 's/<tr>/\n<tr>/g' "$work/bench/index.html" | awk '/^<tr>/ { n = gsub(/<t[hd][ >]/, "&"); if (n > m) m = n } END { print m + 0 }')
  echo "bench: widest table has $widest columns"
  [ "$widest" -le 12 ] || failures=$((failures + 1))
  # A number never breaks inside its cell ("4.7e-17"): no cell holding one is a wrapping text cell (class "t").
  if grep -qE '<td class="t">-?[0-9.]+e[-+][0-9]+x?</td>' "$work/bench/index.html" ||
    ! grep -q 'td,th{[^}]*white-space:nowrap' "$work/bench/index.html"; then
    echo "WRAPPABLE NUMBER CELL in the bench report"
    failures=$((failures + 1))
  fi
  # Errors of exactly 0 have their own strip in the time-vs-error plot.
  grep -q '>exactly 0<' "$work/bench/time_vs_error.svg" || { echo "NO ERROR-0 STRIP"; failures=$((failures + 1)); }
fi
echo "svg: $failures failures"
exit $((failures > 0))
