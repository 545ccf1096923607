# --snap TOL (issue 33 item 3), sourced by hostile_inputs.sh: float input made exact on purpose. Fixels placed on a
# unit disk with cos/sin are refused without --snap (irrational distance) and accepted with it, each snap reported
# on stderr; a point farther than TOL from the boundary is refused with its field named; a bad TOL is a usage error.

# A unit disk held by three fixels at angles 0.3, 2.4, 4.5 written as Python's cos/sin floats.
printf '{"kind":"planar","workpiece":{"shape":{"type":"disk","center":[0,0],"radius":1},"mass":1,"inertia":"1/2"},"mu_s":0.30000000000000004,"fixels":[{"position":[0.955336489125606,0.29552020666133955]},{"position":[-0.7373937155412454,0.675463180551151]},{"position":[-0.2107957994307797,-0.977530117665097]}]}\n' \
  > "$work/snap_disk.json"
# A unit square whose explicit contact point lies 1/1000 below the bottom edge.
printf '{"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[1,0],[1,1],[0,1]]}},"mu_s":"1/2","fixels":[{"point":[0.5,-0.001],"normal":[0,1],"gap":0},{"position":[0,0.5]},{"position":[1,0.5]}]}\n' \
  > "$work/snap_square.json"

check 2 'lies inside the disk' cone "$work/snap_disk.json" --mode sss
check 0 'snapped $.fixels[0].position' cone "$work/snap_disk.json" --mode sss --snap 1e-9
check 0 'snapped $.mu_s: 7500000000000001/25000000000000000 -> 3/10' cone "$work/snap_disk.json" --mode sss --snap 1e-9
check 0 'snapped $.fixels[2].position' cone "$work/snap_disk.json" --mode nnn --snap 1e-9 --json
check 0 '"verdict"' stability "$work/snap_disk.json" --wrench 0,-1,0 --snap 1e-9 --json
check 0 'snapped $.fixels[1].position' modes "$work/snap_disk.json" --snap 1e-9
check 0 'snapped $.fixels[0].position' insert "$work/snap_disk.json" --snap 1e-9
check 2 '--snap' cone "$work/snap_disk.json" --mode sss --snap 0
check 2 '--snap' cone "$work/snap_disk.json" --mode sss --snap -1e-9
check 2 '--snap' stability "$work/snap_disk.json" --wrench 0,-1,0 --snap tiny
check 2 '$.fixels[0].point' cone "$work/snap_square.json" --mode sss --snap 1e-9
check 0 'snapped $.fixels[0].point: [1/2, -1/1000] -> [1/2, 0]' cone "$work/snap_square.json" --mode sss --snap 1e-2
# The certificate embeds the snapped scene: `check` verifies it on its own.
check 0 '"verdict"' stability "$work/snap_disk.json" --wrench 0,-1,0 --snap 1e-9 --json --certificate "$work/snap_cert.json"
check 0 '"valid":true' check "$work/snap_cert.json" --json
# Hostile sizes stay bounded: a tolerance of 1e-4000, a point at 1e300.
printf '{"kind":"planar","workpiece":{"shape":{"type":"disk","center":[0,0],"radius":1}},"mu_s":"1/2","fixels":[{"position":[0.8,0.6000000001]},{"point":[-0.6,-0.8000000001],"normal":[0.6,0.8],"gap":0}]}\n' \
  > "$work/snap_far.json"
check 2 '$.fixels[1].point: a point within < 1e-308 of the disk boundary' cone "$work/snap_far.json" --mode ss --snap 1e-4000
check 0 'snapped $.fixels[1].point' cone "$work/snap_far.json" --mode ss --snap 1e-9
printf '{"kind":"planar","workpiece":{"shape":{"type":"disk","center":[0,0],"radius":1}},"mu_s":"1/2","fixels":[{"point":[1e300,1e300],"normal":[0.6,0.8],"gap":0}]}\n' \
  > "$work/snap_huge.json"
check 2 '$.fixels[0].point' cone "$work/snap_huge.json" --mode s --snap 1e-9
