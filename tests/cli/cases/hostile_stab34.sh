# `stability` on a spatial scene (issue 34; docs/formats.md section 3b), sourced by hostile_inputs.sh: the verdicts of
# the bundled box on a plane (strongly stable under gravity, sliding past atan(mu), tipping with its weight outside
# the support), their certificates checked, and the options that do not apply refused (exit 2 naming them).

st=$work/stab34
mkdir -p "$st"
box=$s/spatial_box_on_plane.json
check 0 'verdict: strongly_stable' stability "$box" --wrench 0,0,-1,0,0,0 --certificate "$st/rest.json"
check 0 'spatial_stability certificate is VALID' check "$st/rest.json" --problem "$box"
check 0 "moves in mode 'EEEE' with vdot = (1/10, 0, 0, 0, 0, 0)" stability "$box" --wrench 3/5,0,-1,0,0,0
check 0 '"verdict":"unstable"' stability "$box" --wrench 0,0,-1,0,2,0 --json
check 0 'verdict: weakly_stable' stability "$s/spatial_peg_in_hole.json" --wrench 0,0,-1,0,0,0
# options that do not apply, a planar wrench, float, and the time limit (exit 3)
check 2 'a spatial scene needs --wrench fx,fy,fz,tx,ty,tz' stability "$box"
check 2 '--region: a spatial scene takes one --wrench' stability "$box" --region
check 2 '--margin' stability "$box" --wrench 0,0,-1,0,0,0 --margin
check 2 '--arith: strong stability in space is decided exactly' stability "$box" --wrench 0,0,-1,0,0,0 --arith float
check 3 'time limit of 0.001 s reached' stability "$box" --wrench 0,0,-1,0,0,0 --time-limit 0.001
# `cone` on a spatial scene: the all-separating cone of the box (four strict rows, lineality 3), refusals
check 0 'dimension 6; face form' cone "$box" --mode ssss
check 0 '"kind":"spatial","mode":"ffff"' cone "$box" --mode ffff --json
check 2 '--mode: one letter per contact (4)' cone "$box" --mode ssz
check 2 '--route: a spatial scene' cone "$box" --mode ssss --route project
check 2 '--svg: a spatial scene' cone "$box" --mode ssss --svg "$st/cone.svg"
check 2 '--arith: a spatial wrench cone is computed exactly' cone "$box" --mode ssss --arith float
