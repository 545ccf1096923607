#!/usr/bin/env bash
# Every kind of picture contactcert writes renders in headless Chromium: the region and finger pictures of
# `stability`, a cone picture, `insert --svg`, `design --out`'s design.svg and the demo report (with its Figure 11
# plot). For each: the page has no XML error (Chromium shows the parse error as a <parsererror> element in the
# DOM) and the screenshot is not blank (more than 40 distinct pixel rows; a blank page has 2).
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
# Distinct rows of a PNG's decompressed scan lines (a uniform picture has at most 2: the first row's filter differs).
distinct_rows() {
  python3 - "$1" << 'PY'
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
print(len({raw[y * stride:(y + 1) * stride] for y in range(h)}))
PY
}
render() {
  local file=$1 name
  name=$(basename "$file")
  [ -s "$file" ] || { echo "MISSING: $file"; failures=$((failures + 1)); return; }
  chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking \
    --disable-component-update --disable-sync --user-data-dir="$work/profile" --window-size=1000,800 \
    --screenshot="$work/$name.png" --dump-dom "file://$file" > "$work/$name.dom" 2> /dev/null
  if grep -q parsererror "$work/$name.dom"; then
    echo "XML ERROR in Chromium: $file"
    grep -o 'error on line[^<]*' "$work/$name.dom" | head -3
    failures=$((failures + 1))
  fi
  local rows=0
  [ -s "$work/$name.png" ] && rows=$(distinct_rows "$work/$name.png")
  if [ "$rows" -gt 40 ]; then
    echo "ok: $name ($rows distinct rows)"
  else
    echo "BLANK OR NO SCREENSHOT: $file ($rows distinct rows)"
    failures=$((failures + 1))
  fi
}
run stability "$s/bt2002_section7_disk.json" --region --wrench 0,-1,0 --svg "$work/region.svg"
render "$work/region.svg"
run stability "$s/bt2002_fig10_pentagon_insert.json" --finger --svg "$work/finger.svg"
render "$work/finger.svg"
run cone "$s/bt2002_fig4d_peg_nn.json" --mode nn --svg "$work/cone.svg"
render "$work/cone.svg"
run insert "$s/bt2002_fig10_pentagon_insert.json" --svg "$work/insert.svg"
render "$work/insert.svg"
run design "$s/bt2002_fig10_pentagon_insert.json" --candidates 12 --stable-under 0,-1,0 --top 2 --out "$work/design"
render "$work/design/design.svg"
run demo --out "$work/demo"
render "$work/demo/index.html"
echo "render: $failures failures"
exit $((failures > 0))
