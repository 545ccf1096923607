# Contact frames on non-convex polygons (issue 29), sourced by hostile_inputs.sh: a fixel on the boundary takes the
# edge whose SEGMENT holds it, not the first edge whose line passes through it; explicit contacts likewise; at a
# vertex an explicit normal lies in the cone of the two edges' inward normals.

# lshape NAME FIXELS: the L of tests/cli/hostile/l_shape.json with other fixels, as $work/NAME.json.
lshape() {
  printf '{"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[4,0],[4,1],[2,1],[2,3],[0,3]]}},"mu_s":"1/3","fixels":[%s]}\n' \
    "$2" > "$work/$1.json"
}
# star NAME FIXELS: a four-pointed star (tips at radius 2 on the axes, reflex vertices at (+-1/2, +-1/2)).
star() {
  printf '{"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[2,0],["1/2","1/2"],[0,2],["-1/2","1/2"],[-2,0],["-1/2","-1/2"],[0,-2],["1/2","-1/2"]]}},"mu_s":"1/3","fixels":[%s]}\n' \
    "$2" > "$work/$1.json"
}
# same_json A B COMMAND ARGS...: `COMMAND A ARGS --json` and `COMMAND B ARGS --json` succeed with the same output
# (one case): a fixel given by position has the frame derived here by hand for the explicit contact.
same_json() {
  local a=$1 b=$2 command=$3
  shift 3
  cases=$((cases + 1))
  local out_a out_b
  out_a=$(timeout -s KILL 20 prlimit --as="$(numfmt --from=iec 2G)" -- "$cc" "$command" "$a" "$@" --json 2>&1)
  local rc=$?
  out_b=$(timeout -s KILL 20 prlimit --as="$(numfmt --from=iec 2G)" -- "$cc" "$command" "$b" "$@" --json 2>&1)
  if [ "$rc" -ne 0 ] || [ "$out_a" != "$out_b" ]; then
    failures=$((failures + 1))
    echo "FAIL: contactcert $command $a / $b $*: exit $rc or different outputs"
    echo "  $(head -c 300 <<< "$out_a")"
    echo "  $(head -c 300 <<< "$out_b")"
  fi
}

L=$h/l_shape.json
# the issue's L: both fixels on the edge x = 0 (normal (1,0)), so g = (-2, 1, 0) slides them (ll)
check 0 'verdict: unstable' stability "$L" --wrench=-2,1,0
check 0 "moves in mode 'll'" stability "$L" --wrench=-2,1,0
# frames as written (docs/formats.md section 3): a position's frame is stated with its unit normal
check 0 '"point":["0","1"],"normal":["1","0"]' stability "$L" --wrench=-2,1,0 --json
check 0 'fixel 0: touching at (0, 1), n = (1, 0)' cone "$L" --mode ll
check 0 '10 feasible modes of 2 fixels' modes "$L"
lshape l_explicit '{"point":[0,1],"normal":[1,0]},{"point":[0,2],"normal":[1,0]}'
same_json "$L" "$work/l_explicit.json" modes
same_json "$L" "$work/l_explicit.json" stability --wrench=-2,1,0
# the inner edge's frame at (0,1), as an explicit contact: refused, naming the edge that holds the point
lshape l_inner_normal '{"point":[0,1],"normal":[0,-2]},{"position":[0,2]}'
check 2 'l_inner_normal.json: $.fixels[0]: a normal perpendicular to edge 5' stability "$work/l_inner_normal.json" --wrench=-2,1,0
lshape l_outward '{"point":[0,2],"normal":[-1,0]}'
check 2 'a positive multiple of (3, 0)' modes "$work/l_outward.json"
# (1,1) is on the inner edge's line but inside the L
lshape l_inside '{"position":[1,1]}'
check 2 'l_inside.json: $.fixels[0].position: fixel at (1, 1) lies inside the polygon' modes "$work/l_inside.json"
lshape l_line_inside '{"point":[1,1],"normal":[0,-1]}'
check 2 'a point on the workpiece boundary, not (1, 1)' modes "$work/l_line_inside.json"
# (3,2) in the notch is 1 from (3,1) and from (2,2)
lshape l_notch '{"position":[3,2]}'
check 2 'is equally close to two points of the polygon' modes "$work/l_notch.json"
# (3, 5/2) is closer to the post (2, 5/2) than to the foot (3, 1); (3, 3/2) closer to the foot
lshape l_notch_post '{"position":["3","5/2"]},{"position":[0,1]}'
lshape l_notch_post_explicit '{"point":["2","5/2"],"normal":[-1,0],"gap":1},{"point":[0,1],"normal":[3,0]}'
same_json "$work/l_notch_post.json" "$work/l_notch_post_explicit.json" modes
lshape l_notch_foot '{"position":["3","3/2"]},{"position":[0,1]}'
lshape l_notch_foot_explicit '{"point":[3,1],"normal":["0","-1/2"],"gap":"1/2"},{"point":[0,1],"normal":[3,0]}'
same_json "$work/l_notch_foot.json" "$work/l_notch_foot_explicit.json" modes
# vertices: a position there has no unique normal; an explicit normal lies in the cone of the edges' normals,
# at the convex (0,0) and at the reflex (2,1) alike
lshape l_vertex '{"position":[2,1]}'
check 2 'touches polygon vertex 3' modes "$work/l_vertex.json"
lshape l_reflex_in '{"point":[2,1],"normal":[-1,-1]},{"position":[0,1]}'
check 0 'feasible modes of 2 fixels' modes "$work/l_reflex_in.json"
lshape l_reflex_out '{"point":[2,1],"normal":[1,-1]}'
check 2 'a normal that points into the polygon at vertex 3, in the cone of (0, -2) and (-2, 0)' modes "$work/l_reflex_out.json"
lshape l_convex_out '{"point":[0,0],"normal":[-1,1]}'
check 2 'at vertex 0' modes "$work/l_convex_out.json"
# off the L: the closest point (0,1) with normal (1,0) at gap 1; the vertex (4,1) with (-1,-1) at gap sqrt(2)
lshape l_outside '{"position":[-1,1]},{"position":[0,2]}'
lshape l_outside_explicit '{"point":[0,1],"normal":[1,0],"gap":1},{"point":[0,2],"normal":[3,0]}'
same_json "$work/l_outside.json" "$work/l_outside_explicit.json" modes
lshape l_corner '{"position":[5,2]},{"position":[-1,1]}'
check 0 '(0 touching, 2 with a gap)' modes "$work/l_corner.json"

# the star: (-2/5, 4/5) lies on edge 2 and on the line of edge 0; (4/5, -2/5) on edge 7 and the line of edge 1
star st_pos '{"position":["-2/5","4/5"]},{"position":["4/5","-2/5"]},{"position":["1/4","5/4"]}'
# the same frames by hand, written as a position's frame is stated (irrational length: the primitive direction)
star st_hand '{"point":["-2/5","4/5"],"normal":[3,-1]},{"point":["4/5","-2/5"],"normal":[-1,3]},{"point":["1/4","5/4"],"normal":[-3,-1]}'
same_json "$work/st_pos.json" "$work/st_hand.json" modes
same_json "$work/st_pos.json" "$work/st_hand.json" stability --wrench=0,-1,0
star st_line_normal '{"point":["-2/5","4/5"],"normal":["-1/2","-3/2"]}'
check 2 'a positive multiple of (3/2, -1/2)' modes "$work/st_line_normal.json"
star st_notch '{"position":[1,1]}'
check 2 'is equally close to two points of the polygon' modes "$work/st_notch.json"
star st_centre '{"position":[0,0]}'
check 2 'lies inside the polygon' modes "$work/st_centre.json"
star st_reflex '{"point":["1/2","1/2"],"normal":[0,-1]}'
check 2 'at vertex 1' modes "$work/st_reflex.json"

# disks: on the circle, outside along a Pythagorean direction, inside, irrational, a normal off the radius
disk() {
  printf '{"kind":"planar","workpiece":{"shape":{"type":"disk","center":[0,0],"radius":5}},"mu_s":"1/3","fixels":[%s]}\n' \
    "$2" > "$work/$1.json"
}
disk d_pos '{"position":[3,4]},{"position":[-6,-8]}'
disk d_hand '{"point":[3,4],"normal":[-3,-4]},{"point":[-3,-4],"normal":[6,8],"gap":5}'
same_json "$work/d_pos.json" "$work/d_hand.json" modes
disk d_inside '{"position":[1,1]}'
check 2 'lies inside the disk' modes "$work/d_inside.json"
disk d_irrational '{"position":[6,1]}'
check 2 'Pythagorean direction' modes "$work/d_irrational.json"
disk d_tangent '{"point":[3,4],"normal":[-4,3]}'
check 2 'a normal pointing at the disk centre' modes "$work/d_tangent.json"

# a quasistatic_scene on the L: contacts by position on the outer edge, no equilibrium under gravity (-2, 1)
printf '{"kind":"quasistatic_scene","workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[4,0],[4,1],[2,1],[2,3],[0,3]]}},"gravity":[-2,1],"contacts":[%s]}\n' \
  '{"position":[0,1],"mu":"1/3"},{"position":[0,2],"mu":"1/3"}' > "$work/qs_l.json"
check 0 'jammed (Y is empty)' ucp "$work/qs_l.json"
printf '{"kind":"quasistatic_scene","workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[4,0],[4,1],[2,1],[2,3],[0,3]]}},"gravity":[-2,1],"contacts":[%s]}\n' \
  '{"point":[0,1],"normal":[0,-1],"mu":"1/3"},{"position":[0,2],"mu":"1/3"}' > "$work/qs_l_inner.json"
check 2 'qs_l_inner.json: $.contacts[0].normal: a normal perpendicular to edge 5' ucp "$work/qs_l_inner.json"
