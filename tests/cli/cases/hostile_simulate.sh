# `contactcert simulate` (issue 32), sourced by hostile_inputs.sh: bad steps and step sizes are usage errors naming
# the option; a bad motion scene names its file and field; a run stopped by the time limit exits 3 with the steps
# done; a jamming proof ends the run with exit 0, the reason, and a certificate that `check` accepts.
box=$s/motion_pushed_box.json
check 2 '--steps' simulate "$box" --steps 0
check 2 '--steps' simulate "$box" --steps -3
check 2 '--steps' simulate "$box" --steps 1e3
check 2 '--steps' simulate "$box" --steps 1000001
check 2 '--dt: a step size > 0' simulate "$box" --dt 0
check 2 '--dt: a step size > 0' simulate "$box" --dt -1/10
check 2 '--dt: a step size > 0' simulate "$box" --dt tenth
check 2 '--dt: a step size > 0' simulate "$box" --dt 1/0
check 2 '--uniqueness' simulate "$box" --uniqueness maybe
check 2 '--max-modes' simulate "$box" --max-modes 0
check 2 '--certificates: a certificate needs --arith exact or verified' simulate "$box" --arith float \
  --certificates "$work/sim_float_certs"
check 2 '--compare' simulate "$box" --arith float --compare
check 2 'no_such_scene.json' simulate "$work/no_such_scene.json"
# A motion scene without a finger's schedule, with a zero step, or a planar scene (no "motion").
printf '{"kind":"quasistatic_scene","workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[2,0],[2,2],[0,2]]}},"obstacles":[{"vertices":[[-9,-1],[9,-1],[9,0],[-9,0]],"mu":1}],"fingers":[{"tip":[0,1],"mu":0}],"motion":{"dt":"1/10","steps":3}}\n' \
  > "$work/sim_no_schedule.json"
check 2 'sim_no_schedule.json: $.fingers[0].schedule' simulate "$work/sim_no_schedule.json"
sed 's/"mu":0}/"mu":0,"schedule":[{"velocity":[1,0]}]}/; s/"dt":"1\/10"/"dt":0/' "$work/sim_no_schedule.json" \
  > "$work/sim_zero_dt.json"
check 2 'sim_zero_dt.json: $.motion.dt' simulate "$work/sim_zero_dt.json"
check 2 'bt2002_fig4a_lla.json: $.motion' simulate "$s/bt2002_fig4a_lla.json"
# Budgets: the time limit passes before the first step (exit 3, the steps done); one node of search per step.
check 3 'time limit after 0 steps (covered: 0 steps)' simulate "$box" --steps 1000000 --time-limit 1e-9
check 0 '"status":"completed"' simulate "$box" --steps 2 --json
# The block pushed into a wall: jammed at step 3 (exit 0, the reason), each step's certificate checks.
check 0 'jammed (jammed at step 3' simulate "$s/motion_block_wall.json" --certificates "$work/sim_certs"
check 0 '"valid":true' check "$work/sim_certs/step-3.json" --json
check 0 '"kind":"ucp_jammed"' check "$work/sim_certs/step-3.json" --json
check 0 '"valid":true' check "$work/sim_certs/step-0.json" --json
check 0 'float run' simulate "$box" --steps 2 --compare
check 0 '"divergences"' simulate "$box" --steps 2 --compare --json --uniqueness off
# Outputs that cannot be written: named.
check 2 'x.svg: cannot open the file for writing' simulate "$box" --steps 1 --svg "$work/no_such_dir/x.svg"
check 2 '--certificates: a folder that can be created' simulate "$box" --steps 1 --certificates "$box"
