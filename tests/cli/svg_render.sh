#!/usr/bin/env bash
# Every kind of picture contactcert writes renders in headless Chromium: the region and finger pictures of
# `stability`, a cone picture, `insert --svg`, `design --out`'s design.svg and the demo report (with its Figure 11
# plot). The page holding them has no XML error (Chromium shows a parse error as a <parsererror> element in the
# DOM) and no picture's screenshot is blank (more than 40 distinct pixel rows; a blank one has 2). One Chromium
# run for all (each run costs ~2.5 s of CPU). Also the pictures of `assembly --svg` (issue 31) and of `simulate`
# with four bodies (issue 32), and of `modes --svg` on a spatial scene (issue 34).
# Usage: svg_render.sh CONTACTCERT REPO_DIR WORK_DIR. Exit 77 (skipped) without chromium or python3.
set -u
cc=$1 repo=$2 work=$3
s=$repo/scenes
command -v chromium > /dev/null && command -v python3 > /dev/null || { echo "chromium or python3 missing: skipped"; exit 77; }
rm -rf "$work" && mkdir -p "$work"
failures=0
run() {
  if ! "$cc" "$@" > "$work/out" 2> "$work/err"; then
    echo "FAILED: contactcert $*"
    cat "$work/err"
    failures=$((failures + 1))
  fi
}
# The pictures, each in a band of 500 px of one XHTML page (the SVGs inline, so any XML error in one is a parse
# error of the page; the demo report in an iframe), rendered by one Chromium run; then per band the distinct rows.
pictures=()
add() {
  [ -s "$1" ] || { echo "MISSING: $1"; failures=$((failures + 1)); return; }
  pictures+=("$1")
}
run stability "$s/bt2002_section7_disk.json" --region --wrench 0,-1,0 --svg "$work/region.svg"
add "$work/region.svg"
run stability "$s/bt2002_fig10_pentagon_insert.json" --finger --svg "$work/finger.svg"
add "$work/finger.svg"
run cone "$s/bt2002_fig4d_peg_nn.json" --mode nn --svg "$work/cone.svg"
add "$work/cone.svg"
run insert "$s/bt2002_fig10_pentagon_insert.json" --svg "$work/insert.svg"
add "$work/insert.svg"
run design "$s/bt2002_fig10_pentagon_insert.json" --candidates 12 --stable-under 0,-1,0 --top 2 --out "$work/design"
add "$work/design/design.svg"
run simulate "$s/motion_pushed_box.json" --compare --svg "$work/simulate.svg"
add "$work/simulate.svg"
run simulate "$s/motion_pushed_row.json" --compare --uniqueness off --svg "$work/simulate_row.svg"
add "$work/simulate_row.svg"
run assembly "$s/assembly_corbel_arch.json" --svg "$work/assembly.svg"
add "$work/assembly.svg"
run modes "$s/spatial_box_in_corner.json" --svg "$work/spatial.svg"
add "$work/spatial.svg"
run demo --out "$work/demo"
add "$work/demo/index.html"
page=$work/pictures.xhtml
{
  echo '<html xmlns="http://www.w3.org/1999/xhtml"><body style="margin:0">'
  for f in "${pictures[@]}"; do
    echo '<div style="height:500px;overflow:hidden">'
    case $f in
      *.svg) sed '/^<?xml/d' "$f" ;;
      *) echo "<iframe src=\"file://$f\" width=\"1000\" height=\"500\" style=\"border:0\"></iframe>" ;;
    esac
    echo '</div>'
  done
  echo '</body></html>'
} > "$page"
chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking \
  --disable-component-update --disable-sync --user-data-dir="$work/profile" --window-size=1000,$((500 * ${#pictures[@]})) \
  --screenshot="$work/pictures.png" --dump-dom "file://$page" > "$work/pictures.dom" 2> /dev/null
if grep -q parsererror "$work/pictures.dom"; then
  echo "XML ERROR in Chromium:"
  grep -o 'error on line[^<]*' "$work/pictures.dom" | head -3
  failures=$((failures + 1))
fi
if [ ! -s "$work/pictures.png" ]; then
  echo "NO SCREENSHOT"
  failures=$((failures + 1))
else
  # Distinct rows of the decompressed scan lines in each band (a blank band has at most 2).
  python3 - "$work/pictures.png" "${pictures[@]}" << 'PY' || failures=$((failures + 1))
import struct, sys, zlib
data = open(sys.argv[1], 'rb').read()
pos, idat, h = 8, b'', 0
while pos + 8 <= len(data):
    n, kind = struct.unpack('>I4s', data[pos:pos + 8])
    if kind == b'IHDR': h = struct.unpack('>I', data[pos + 12:pos + 16])[0]
    if kind == b'IDAT': idat += data[pos + 8:pos + 8 + n]
    pos += 12 + n
raw = zlib.decompress(idat)
stride = len(raw) // h
bad = 0
for k, name in enumerate(sys.argv[2:]):
    rows = len({raw[y * stride:(y + 1) * stride] for y in range(500 * k, min(h, 500 * (k + 1)))})
    print(('ok: ' if rows > 40 else 'BLANK: ') + name + ' (%d distinct rows)' % rows)
    bad += rows <= 40
sys.exit(bad > 0)
PY
fi
echo "render: $failures failures"
exit $((failures > 0))
