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
# The per-step search budget, really hit: Pang, Trinkle and Lo's Data Set 4 (scenes/pang1994_dataset4_geometry.json)
# as a motion scene (each finger's frame velocity written in world axes): the first step is jammed only by a search
# tree of 9 nodes (neither X nor Y is empty), so one node ends the run unknown, exit 3, with the steps covered.
ds4='"workpiece":{"shape":{"type":"polygon","vertices":[["-1655/201","-24"],["932/707","-24"],["1909442/170387","-343494/24341"],["2062/973","24"],["-24","24"],["-24","-1604/595"]]},"com":[0,0]}'
f0='{"name":"f0","tip":["-16184800/1000441","-13271660/1000441"],"mu":"0.7","schedule":[{"velocity":["38893/40000","58259/250000"]}]}'
f1='{"name":"f1","tip":["7200/707","-10700/707"],"mu":"0.9","schedule":[{"velocity":["-3909003/10000000","9207261/10000000"]}]}'
f2='{"name":"f2","tip":["4175990/1000553","15392160/1000553"],"mu":"0.9","schedule":[{"velocity":["-4953089/5000000","705959/5000000"]}]}'
printf '{"kind":"quasistatic_scene",%s,"gravity":[0,-1],"obstacles":[],"fingers":[%s,%s,%s],"motion":{"dt":"1/10","steps":3}}\n' \
  "$ds4" "$f0" "$f1" "$f2" > "$work/sim_dataset4.json"
check 0 'jammed (jammed at step 0: search tree)' simulate "$work/sim_dataset4.json" --uniqueness off
check 3 'step 0: node budget of 1 exhausted (covered: 1 steps)' simulate "$work/sim_dataset4.json" --max-nodes 1
# --json too: the limit only (stderr), no answer with status unknown.
check 3 'step 0: node budget of 8 exhausted (covered: 1 steps)' simulate "$work/sim_dataset4.json" --max-nodes 8 --json
# The block pushed into a wall: jammed at step 3 (exit 0, the reason), each step's certificate checks.
check 0 'jammed (jammed at step 3' simulate "$s/motion_block_wall.json" --certificates "$work/sim_certs"
check 0 '"valid":true' check "$work/sim_certs/step-3.json" --json
check 0 '"kind":"ucp_jammed"' check "$work/sim_certs/step-3.json" --json
check 0 '"valid":true' check "$work/sim_certs/step-0.json" --json
check 0 'float run' simulate "$box" --steps 2 --compare
# The float run steps by the double nearest to the scene's 1/10 (GMP's get_d would give 0.09999999999999999).
check 0 'step 0 t = ~0.0 h = ~0.1: solvable' simulate "$box" --steps 1 --arith float
check 0 '"divergences"' simulate "$box" --steps 2 --compare --json --uniqueness off
# Outputs that cannot be written: named.
check 2 'x.svg: cannot open the file for writing' simulate "$box" --steps 1 --svg "$work/no_such_dir/x.svg"
check 2 '--certificates: a folder that can be created' simulate "$box" --steps 1 --certificates "$box"
