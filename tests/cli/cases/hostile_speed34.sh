# `modes SPATIAL --svg FILE` (issue 34), sourced by hostile_inputs.sh: the picture of a spatial scene is written and
# named (text and --json), a planar scene's or an assembly's is refused (exit 2 naming --svg), an unwritable path is
# exit 2, and a budget stop writes no picture.

sv=$work/speed34
mkdir -p "$sv"
check 0 "picture: $sv/box.svg" modes "$s/spatial_box_on_plane.json" --svg "$sv/box.svg"
check 0 "\"svg\":\"$sv/peg.svg\"" modes "$s/spatial_peg_in_hole.json" --json --svg "$sv/peg.svg"
check 2 '--svg' modes "$s/bt2002_fig4a_lla.json" --svg "$sv/planar.svg"
check 2 '--svg' modes "$s/assembly_two_boxes.json" --svg "$sv/assembly.svg"
check 2 'no-such-dir' modes "$s/spatial_box_on_plane.json" --svg "$sv/no-such-dir/box.svg"
check 3 'node budget of 50 prefixes' modes "$s/spatial_box_on_plane.json" --max-nodes 50 --svg "$sv/budget.svg"
cases=$((cases + 1))
if [ -e "$sv/budget.svg" ]; then
  echo "FAIL: a budget stop wrote a picture"
  failures=$((failures + 1))
fi
