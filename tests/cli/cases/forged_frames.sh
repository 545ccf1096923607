# Certificates that hold only for a wrong contact frame (issue 29), sourced by forged_certificates.sh: every checker
# derives and verifies the frames of its embedded scene itself (checker/frame_check.h), so evidence
# computed with the frame of an inner edge's line, or with a frame that is not the geometry's, is INVALID.

fr=$work/frames
mkdir -p "$fr"
# embed CERT SCENE OUT: OUT is CERT with its embedded scene replaced by the text of SCENE and its digest redone.
embed() {
  SCENE="$2" perl -0pe 'BEGIN { local $/; open my $f, "<", $ENV{SCENE} or die; $t = <$f>; $t =~ s/\s+$//;
    $t =~ s/(["\\])/\\$1/g; $t =~ s/\n/\\n/g } s/"scene": *"(?:[^"\\]|\\.)*"/"scene": "$t"/' "$1" > "$3"
  redigest "$3"
}
# planar NAME VERTICES FIXELS: a scene with the com and I/m fixed, so that evidence moves between workpieces.
planar() {
  printf '{"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":%s},"com":["3/2","5/4"],"mass":1,"inertia":"3/2"},"mu_s":"1/3","fixels":[%s]}\n' \
    "$2" "$3" > "$fr/$1.json"
}
lv='[[0,0],[4,0],[4,1],[2,1],[2,3],[0,3]]'
# A: a workpiece whose real edges give the fixels at (0,1) and (0,2) the L's old wrong frames, (0,-2) on the edge
# from (1,1) to (-1,1) and (3/2,0) on the edge from (0,3) to (0,3/2): strongly stable under (-2, 1, 0).
av='[[-1,0],[2,0],[2,3],[0,3],[0,"3/2"],[1,"3/2"],[1,1],[-1,1]]'
planar l "$lv" '{"position":[0,1]},{"position":[0,2]}'
planar a "$av" '{"position":[0,1]},{"position":[0,2]}'
"$cc" stability "$fr/l.json" --wrench=-2,1,0 --certificate "$fr/l_st.json" > /dev/null
"$cc" stability "$fr/a.json" --wrench=-2,1,0 --certificate "$fr/a_st.json" > /dev/null
check 0 'stability certificate is VALID for' check "$fr/l_st.json" --problem "$fr/l.json"
check 0 'evidence verifies exactly: unstable' check "$fr/l_st.json"
check 0 'evidence verifies exactly: strongly_stable' check "$fr/a_st.json" --problem "$fr/a.json"
# A's strongly stable evidence with the L embedded: the checker's frames are (1,0) at both fixels
embed "$fr/a_st.json" "$fr/l.json" "$fr/a_on_l.json"
check 2 'stability certificate is INVALID' check "$fr/a_on_l.json"
check 2 'is about another problem than' check "$fr/a_st.json" --problem "$fr/l.json"
# the old wrong frames written out as explicit contacts on the L: refused by the checker, naming the fixel
planar l_old "$lv" '{"point":[0,1],"normal":[0,-2]},{"point":[0,2],"normal":[3,0]}'
embed "$fr/a_st.json" "$fr/l_old.json" "$fr/a_on_l_old.json"
check 2 'the frame of fixel 0 of the scene: the normal (0, -2) is not a positive multiple of the inward normal (3, 0) of edge 5' \
  check "$fr/a_on_l_old.json"
# fixels the solver refuses, in a certificate: inside, equally close to two points, on a vertex, off the boundary
planar l_inside "$lv" '{"position":[1,1]},{"position":[0,2]}'
embed "$fr/l_st.json" "$fr/l_inside.json" "$fr/st_inside.json"
check 2 'the frame of fixel 0 of the scene: the fixel at (1, 1) is inside the polygon' check "$fr/st_inside.json"
planar l_notch "$lv" '{"position":[0,1]},{"position":[3,2]}'
embed "$fr/l_st.json" "$fr/l_notch.json" "$fr/st_notch.json"
check 2 'fixel 1 of the scene: the point (2, 2) of edge 3 is as close to the fixel at (3, 2) as (3, 1)' check "$fr/st_notch.json"
planar l_vertex "$lv" '{"position":[2,1]},{"position":[0,2]}'
embed "$fr/l_st.json" "$fr/l_vertex.json" "$fr/st_vertex.json"
check 2 'touches vertex 3, where the normal is not unique' check "$fr/st_vertex.json"
planar l_reflex "$lv" '{"point":[2,1],"normal":[1,-1]},{"position":[0,2]}'
embed "$fr/l_st.json" "$fr/l_reflex.json" "$fr/st_reflex.json"
check 2 'is not in the cone of its edges' check "$fr/st_reflex.json"
planar l_off "$lv" '{"point":[1,1],"normal":[0,-1]},{"position":[0,2]}'
embed "$fr/l_st.json" "$fr/l_off.json" "$fr/st_off.json"
check 2 'the point (1, 1) is on no edge segment of the polygon' check "$fr/st_off.json"
# the modes and cone certificates of A, about the L: the accelerations and Motzkin vectors were for A's frames
"$cc" modes "$fr/a.json" --certificate "$fr/a_modes.json" > /dev/null
check 0 'modes certificate is VALID' check "$fr/a_modes.json" --problem "$fr/a.json"
embed "$fr/a_modes.json" "$fr/l.json" "$fr/a_modes_on_l.json"
check 2 'modes certificate is INVALID' check "$fr/a_modes_on_l.json"
embed "$fr/a_modes.json" "$fr/l_old.json" "$fr/a_modes_on_l_old.json"
check 2 'the frame of fixel 0 of the scene' check "$fr/a_modes_on_l_old.json"
"$cc" cone "$fr/a.json" --mode ll --certificate "$fr/a_cone.json" > /dev/null
check 0 'certificate is VALID' check "$fr/a_cone.json"
embed "$fr/a_cone.json" "$fr/l_old.json" "$fr/a_cone_on_l_old.json"
check 2 'the frame of fixel 0 of the scene' check "$fr/a_cone_on_l_old.json"
# a disk scene with a fixel inside, and with an explicit normal off the radius
printf '{"kind":"planar","workpiece":{"shape":{"type":"disk","center":[0,0],"radius":5}},"mu_s":"1/3","fixels":[%s]}\n' \
  '{"position":[3,4]},{"position":[-3,4]}' > "$fr/d.json"
"$cc" stability "$fr/d.json" --wrench=0,-1,0 --certificate "$fr/d_st.json" > /dev/null
check 0 'stability certificate is VALID for' check "$fr/d_st.json" --problem "$fr/d.json"
sed 's/"position":\[-3,4\]/"position":[-3,3]/' "$fr/d.json" > "$fr/d_inside.json"
embed "$fr/d_st.json" "$fr/d_inside.json" "$fr/d_st_inside.json"
check 2 'the fixel at (-3, 3) is inside the disk' check "$fr/d_st_inside.json"
sed 's/{"position":\[-3,4\]}/{"point":[-3,4],"normal":[4,3]}/' "$fr/d.json" > "$fr/d_tangent.json"
embed "$fr/d_st.json" "$fr/d_tangent.json" "$fr/d_st_tangent.json"
check 2 'is not a positive multiple of (3, -4), from the point to the disk centre' check "$fr/d_st_tangent.json"
# UCP: the checker builds an embedded or --problem quasistatic_scene with its own frames
qs() {
  printf '{"kind":"quasistatic_scene","workpiece":{"shape":{"type":"polygon","vertices":%s},"com":["3/2","5/4"]},"gravity":[-2,1],"contacts":[%s]}\n' \
    "$2" "$3" > "$fr/$1.json"
}
qs qs_l "$lv" '{"position":[0,1],"mu":"1/3"},{"position":[0,2],"mu":"1/3"}'
qs qs_a "$av" '{"position":[0,1],"mu":"1/3"},{"position":[0,2],"mu":"1/3"}'
qs qs_l_old "$lv" '{"point":[0,1],"normal":[0,-2],"mu":"1/3"},{"position":[0,2],"mu":"1/3"}'
"$cc" ucp "$fr/qs_l.json" --certificate "$fr/qs_l_cert.json" > /dev/null
"$cc" ucp "$fr/qs_a.json" --certificate "$fr/qs_a_cert.json" > /dev/null
check 0 'ucp_jammed certificate is VALID for' check "$fr/qs_l_cert.json" --problem "$fr/qs_l.json"
check 0 'ucp_solvable certificate is VALID for' check "$fr/qs_a_cert.json" --problem "$fr/qs_a.json"
check 2 'is about another problem than' check "$fr/qs_a_cert.json" --problem "$fr/qs_l.json"
check 2 'qs_l_old.json: $.contacts[0].normal: the normal (0, -2) is not a positive multiple' \
  check "$fr/qs_l_cert.json" --problem "$fr/qs_l_old.json"
# the scene itself embedded as the certificate's problem: its frames are the checker's
# embed_qs CERT SCENE OUT: OUT is the UCP certificate CERT with SCENE as its problem, digest redone.
embed_qs() {
  QS="$2" perl -0pe 'BEGIN { local $/; open my $f, "<", $ENV{QS} or die; $t = <$f>; $t =~ s/\s+$// }
    s/"problem":\{.*?\},"reason"/"problem":$t,"reason"/s' "$1" > "$3"
  redigest "$3" 2> /dev/null  # an unreadable embedded scene has no digest; check then says why
}
embed_qs "$fr/qs_l_cert.json" "$fr/qs_l.json" "$fr/qs_l_embedded.json"
check 0 'ucp_jammed certificate is VALID' check "$fr/qs_l_embedded.json"
embed_qs "$fr/qs_l_cert.json" "$fr/qs_a.json" "$fr/qs_a_embedded.json"
check 2 'ucp_jammed certificate is INVALID' check "$fr/qs_a_embedded.json"
embed_qs "$fr/qs_l_cert.json" "$fr/qs_l_old.json" "$fr/qs_l_old_embedded.json"
check 2 '$.problem.contacts[0].normal: the normal (0, -2) is not a positive multiple' check "$fr/qs_l_old_embedded.json"
