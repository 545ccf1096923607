# A near-degenerate spatial scene (issue 34, found beside the float 3-D peer, bench/spatial_peer.sh), sourced by
# hostile_inputs.sh: the box on a plane with one normal tilted by 1e-9. Its rows are nearly dependent, the float
# simplex of the verified LP's integer fast path ended "unbounded" with no duals and `modes` crashed (exit 139);
# the verified LP now decides such a prefix. The exact answer: every one of the 2^4 contacting/separating patterns
# is feasible (the tilt makes the four normal rows independent), 444 modes, certificate VALID.

e34=$work/enum34
mkdir -p "$e34"
cat > "$e34/tilt.json" << 'SCENE'
{"kind":"spatial","name":"box on a plane, normal 0 tilted by 1e-9","mu":"1/2",
 "body":{"mass":1,"inertia":[["5/12",0,0],[0,"5/12",0],[0,0,"2/3"]],"com":[0,0,"1/2"],
         "box":{"center":[0,0,"1/2"],"half":[1,1,"1/2"]}},
 "contacts":[{"point":[1,1,0],"normal":["-1/1000000000",0,1]},{"point":[1,-1,0],"normal":[0,0,1]},
             {"point":[-1,-1,0],"normal":[0,0,1]},{"point":[-1,1,0],"normal":[0,0,1]}]}
SCENE
check 0 '444 feasible modes of 4 contacts' modes "$e34/tilt.json" --certificate "$e34/tilt.cert"
check 0 'spatial_modes certificate is VALID' check "$e34/tilt.cert"
check 0 'verdict: strongly_stable' stability "$e34/tilt.json" --wrench 0,0,-1,0,0,0
