# `contactcert simulate` with several bodies (issue 32), sourced by hostile_inputs.sh: a scene with both
# "workpiece" and "bodies" (or neither), two bodies with one name, a non-convex body are refused naming the field;
# bodies that overlap at time 0 end the run at once (exit 0, `overlap`); the bundled row's steps each carry a
# certificate embedding the step's assembly, which `check` accepts.
row=$s/motion_pushed_row.json
sed 's/"bodies": \[/"workpiece": {"shape": {"type": "polygon", "vertices": [[0, 0], [1, 0], [1, 1]]}}, "bodies": [/' \
  "$row" > "$work/sim_both.json"
check 2 'sim_both.json: $: exactly one of "workpiece" (one body) or "bodies"' simulate "$work/sim_both.json"
sed 's/"box 1"/"box 0"/' "$row" > "$work/sim_same_name.json"
check 2 'sim_same_name.json: $.bodies[1].name: a name no other body has' simulate "$work/sim_same_name.json"
sed 's/\[\["3\/2", "1\/2"\], \["7\/4", 0\]/[["3\/2", "1\/2"], ["2", "1\/2"], ["7\/4", 0]/' "$row" > "$work/sim_reflex.json"
check 2 'sim_reflex.json: $.bodies[1].shape' simulate "$work/sim_reflex.json"
sed 's/\[\["3\/2", "1\/2"\]/[["1\/2", "1\/2"]/' "$row" > "$work/sim_overlap.json"
check 0 'overlap (the box 0 overlaps the box 1 at time 0)' simulate "$work/sim_overlap.json"
rm -rf "$work/sim_row_certs"
check 0 '3 of 3 steps' simulate "$row" --steps 3 --uniqueness off --certificates "$work/sim_row_certs"
check 0 'ucp_solvable certificate is VALID' check "$work/sim_row_certs/step-2.json"
# The `_approx` views are the nearest doubles (exact::nearest_double): 1/10 prints as 0.1, 2/5 as 0.4 (GMP's get_d
# truncates to 0.09999999999999999 and 0.39999999999999997).
check 0 '"dt_approx":0.1,' simulate "$s/motion_pushed_box.json" --steps 1 --json
check 0 '"dt_approx":0.4,' simulate "$s/motion_block_wall.json" --steps 1 --json
# Box 3 lifted off the floor: no contact holds it (a quasistatic body needs one), and the run says which body.
sed 's/\[\["9\/2", "1\/2"\], \["19\/4", 0\], \["11\/2", 0\], \["11\/2", 1\], \["19\/4", 1\]\]/[["9\/2", "3\/2"], ["19\/4", 1], ["11\/2", 1], ["11\/2", 2], ["19\/4", 2]]/' \
  "$row" > "$work/sim_lifted.json"
check 0 'no_contact (no contact holds the box 3' simulate "$work/sim_lifted.json"
