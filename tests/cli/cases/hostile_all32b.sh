# `assembly --ucp --all` and a jammed instant under `--all` (issue 32), sourced by hostile_inputs.sh. The pushed row
# of two boxes moves as one (both q_dot (1, 0, 0)), a unique motion whose motion_uniqueness certificate `check`
# verifies; a jammed assembly, a jammed problem file and a jammed scene all answer `no_motion` the same way (text and
# --json, 0 LPs, no uniqueness certificate written: the jamming certificate is the proof); the prefix tree's budget
# exits 3 with the LPs covered; --all's options without --ucp, without --all or on the float path exit 2.
ub=$work/hostile_all32b
rm -rf "$ub" && mkdir -p "$ub"
check 0 'the motion (mode ----rsr): body 0 (1, 0, 0), body 1 (1, 0, 0)' \
  assembly "$s/assembly_pushed_boxes.json" --ucp --all --uniqueness-certificate "$ub/row_u.json"
check 0 'motion_uniqueness certificate is VALID' check "$ub/row_u.json"
check 0 '"uniqueness":{"status":"unique","motions":[["1","0","0","1","0","0"]]' \
  assembly "$s/assembly_pushed_boxes.json" --ucp --all --json
no_motion='uniqueness: no motion (jammed, no solution: the jamming certificate is the proof'
check 0 "$no_motion" assembly "$s/assembly_overhang.json" --ucp --all --certificate "$ub/overhang_j.json" \
  --uniqueness-certificate "$ub/overhang_u.json"
check 0 'ucp_jammed certificate is VALID' check "$ub/overhang_j.json"
check 2 "$ub/overhang_u.json" check "$ub/overhang_u.json"
no_motion_json='"uniqueness":{"status":"no_motion","motions":[],"modes":[],"solution_modes":[],"unbounded":false,"lps":0}'
check 0 "$no_motion_json" assembly "$s/assembly_pushed_boxes_wall.json" --ucp --all --json
check 0 "$no_motion_json" ucp "$s/assembly_pushed_boxes_wall.json" --all --json
check 0 "$no_motion_json" ucp "$s/pang1994_dataset4.json" --all --json
check 0 "$no_motion" ucp "$s/pang1994_dataset4.json" --all
check 0 "$no_motion_json" ucp "$s/pang1994_dataset4_geometry.json" --all --json
check 3 "the uniqueness prefix tree's LP budget (--max-modes 5) ran out (covered: 5 lps)" \
  assembly "$s/assembly_pushed_boxes.json" --ucp --all --max-modes 5
check 2 "--all: an option of --ucp's uniqueness question" assembly "$s/assembly_two_boxes.json" --all
check 2 "--uniqueness-certificate: an option of --ucp's uniqueness question" \
  assembly "$s/assembly_two_boxes.json" --uniqueness-certificate "$ub/x.json"
check 2 "--max-modes: the budget of --all's uniqueness question; add --all" \
  assembly "$s/assembly_two_boxes.json" --ucp --max-modes 5
check 2 '--all: the uniqueness question is decided exactly' \
  assembly "$s/assembly_two_boxes.json" --ucp --all --arith float
