#!/usr/bin/env bash
# Forged certificates (issue 17; UCP in full, cone, G_goal, stability and modes): each forgery of a valid certificate must be INVALID (exit 2, with the
# reason) and each genuine one VALID (exit 0), under a memory and a time cap. The forgeries change the
# problem (with and without a recomputed digest), the digest, the format, the tree (cycles, shared children,
# unreachable or missing nodes, out-of-range indices), the Farkas vectors, the pair, and add unknown keys.
# Usage: forged_certificates.sh CONTACTCERT REPO_DIR WORK_DIR
set -u
cc=$1
repo=$2
work=$3
s=$repo/scenes
mkdir -p "$work"
source "$(dirname "$0")/case_lib.sh"
# forge NAME SED_SCRIPT FROM: NAME.json is FROM with the sed script applied to its whole text (sed -z).
forge() { sed -z "$2" "$3" > "$work/$1.json"; }
# digest FILE: the problem_sha256 that check computes for the embedded problem of FILE.
digest() { "$cc" check "$1" --json | sed 's/.*"problem_sha256":"\([0-9a-f]*\)".*/\1/'; }

jam=$work/jammed.json
sol=$work/solvable.json
"$cc" ucp "$s/pang1994_dataset4.json" --certificate "$jam" > /dev/null
"$cc" ucp "$s/pang1994_dataset1.json" --certificate "$sol" > /dev/null
"$cc" ucp --generate reduction --rows 2 --cols 4 --seed 5 --out "$work/red.json"
"$cc" ucp "$work/red.json" --certificate "$work/red_cert.json" > /dev/null

# ---- genuine certificates ----
check 0 'ucp_jammed certificate is VALID' check "$jam"
check 0 'problem sha256 ' check "$jam"
check 0 'VALID for' check "$jam" --problem "$s/pang1994_dataset4.json"
check 0 '"valid":true' check "$jam" --json --problem "$s/pang1994_dataset4.json"
check 0 'ucp_solvable certificate is VALID' check "$sol" --problem "$s/pang1994_dataset1.json"
check 0 'certificate is VALID' check "$work/red_cert.json" --problem "$work/red.json"
# the same problem respelt: numbers as other exact strings, keys reordered, another source: still the problem
sed -e 's/"201\/250"/"0.804"/g' -e 's/"source": *"[^"]*"/"source":"respelt"/' \
  "$s/pang1994_dataset4.json" > "$work/ds4_respelt.json"
check 0 'VALID for' check "$jam" --problem "$work/ds4_respelt.json"
forge relabelled 's/"source":"[^"]*"/"source":"a solvable scene"/' "$jam"
check 0 'certificate is VALID' check "$work/relabelled.json"

# ---- bound to its problem ----
check 2 'is about another problem than' check "$jam" --problem "$s/pang1994_dataset1.json"
check 2 'is about another problem than' check "$work/relabelled.json" --problem "$s/pang1994_dataset3.json"
check 2 'is about another problem than' check "$sol" --problem "$s/pang1994_dataset4.json"
check 2 'bt2002_section7_disk.json: $.kind' check "$jam" --problem "$s/bt2002_section7_disk.json"
check 2 'cannot open the file' check "$jam" --problem "$work/none.json"
forge p_changed 's/"P":\[\["201\/250"/"P":[["1"/' "$jam"
check 2 'problem_sha256 is not the digest of the embedded problem' check "$work/p_changed.json"
sed -z "s/\"problem_sha256\":\"[0-9a-f]*\"/\"problem_sha256\":\"$(digest "$work/p_changed.json")\"/" \
  "$work/p_changed.json" > "$work/p_changed_redigested.json"
check 2 'the Farkas vector for' check "$work/p_changed_redigested.json"
forge mu_changed 's/"mu":\["/"mu":["1+/' "$jam"
check 2 'is not an exact number' check "$work/mu_changed.json"
forge digest_zero 's/"problem_sha256":"[0-9a-f]*"/"problem_sha256":"0000000000000000000000000000000000000000000000000000000000000000"/' "$jam"
check 2 'problem_sha256 is not the digest' check "$work/digest_zero.json"
forge digest_upper 's/"problem_sha256":"\([0-9a-f]*\)"/"problem_sha256":"\U\1"/' "$jam"
check 2 'problem_sha256 is not the digest' check "$work/digest_upper.json"
forge digest_gone 's/"problem_sha256":"[0-9a-f]*",//' "$jam"
check 2 '$.problem_sha256: required field is missing' check "$work/digest_gone.json"
forge digest_number 's/"problem_sha256":"[0-9a-f]*"/"problem_sha256":12/' "$jam"
check 2 'expected a string' check "$work/digest_number.json"
forge format_1 's/"format":2/"format":1/' "$jam"
check 2 '$.format: expected an integer from 2 to 2' check "$work/format_1.json"
forge sol_digest 's/"problem_sha256": *"[0-9a-f]/"problem_sha256":"x/' "$sol"
check 2 'problem_sha256 is not the digest' check "$work/sol_digest.json"

# ---- unknown keys ----
forge extra_top 's/"kind":"ucp_jammed"/"kind":"ucp_jammed","trust_me":true/' "$jam"
check 2 '$.trust_me: unknown field' check "$work/extra_top.json"
forge extra_node 's/"empty":"/"note":"x","empty":"/' "$jam"
check 2 'unknown field' check "$work/extra_node.json"
forge extra_branch 's/"branch":/"skip":true,"branch":/' "$jam"
check 2 'unknown field' check "$work/extra_branch.json"
forge extra_sol 's/"kind": *"ucp_solvable"/"kind":"ucp_solvable","nodes":[]/' "$sol"
check 2 '$.nodes: unknown field' check "$work/extra_sol.json"
forge extra_problem 's/"kind":"quasistatic"/"kind":"quasistatic","mu_S":1/' "$jam"
check 2 'mu_S: unknown field' check "$work/extra_problem.json"

# ---- the tree ----
forge root_cycle 's/"x_zero":[0-9]*/"x_zero":0/' "$jam"
check 2 'reached twice' check "$work/root_cycle.json"
forge shared_child 's/"x_zero":\([0-9]*\),"y_zero":[0-9]*/"x_zero":\1,"y_zero":\1/' "$jam"
check 2 'certificate is INVALID' check "$work/shared_child.json"
forge child_range 's/"x_zero":[0-9]*/"x_zero":999999/' "$jam"
check 2 'expected an integer from 0 to' check "$work/child_range.json"
forge child_negative 's/"y_zero":[0-9]*/"y_zero":-1/' "$jam"
check 2 'expected an integer from 0 to' check "$work/child_negative.json"
forge child_huge 's/"y_zero":[0-9]*/"y_zero":18446744073709551616/' "$jam"
check 2 'expected an integer from 0 to' check "$work/child_huge.json"
forge child_fraction 's/"y_zero":[0-9]*/"y_zero":"3\/2"/' "$jam"
check 2 'expected an integer from 0 to' check "$work/child_fraction.json"
forge branch_range 's/"branch":[0-9]*/"branch":9/' "$jam"
check 2 '$.nodes[0].branch: expected an integer from 0 to 8' check "$work/branch_range.json"
forge branch_other 's/"branch":[0-9]*/"branch":0/' "$jam"
check 2 'certificate is INVALID' check "$work/branch_other.json"
forge no_nodes 's/"nodes":\[.*\]}/"nodes":[]}/' "$jam"
check 2 'the tree has no nodes' check "$work/no_nodes.json"
forge nodes_object 's/"nodes":\[.*\]}/"nodes":{}}/' "$jam"
check 2 'expected an array' check "$work/nodes_object.json"
forge unreachable 's/\]}\n$/,{"empty":"X","farkas":["1"]}]}\n/' "$jam"
check 2 'is not reachable from the root' check "$work/unreachable.json"
forge root_leaf 's/"nodes":\[.*\]}/"nodes":[{"empty":"X","farkas":["1","0","0","0","0","0"]}]}/' "$jam"
check 2 'certificate is INVALID' check "$work/root_leaf.json"
forge missing_child 's/"nodes":\[\({[^}]*}\).*\]}/"nodes":[\1]}/' "$jam"
check 2 'expected an integer from 0 to 0' check "$work/missing_child.json"

# ---- the Farkas vectors ----
forge side_swap 's/"empty":"X"/"empty":"Y"/' "$jam"
check 2 'the Farkas vector for Y fails' check "$work/side_swap.json"
forge side_bogus 's/"empty":"X"/"empty":"Z"/' "$jam"
check 2 'expected "X" or "Y"' check "$work/side_bogus.json"
forge farkas_long 's/"farkas":\[/"farkas":["7",/' "$jam"
check 2 'Farkas vector has' check "$work/farkas_long.json"
forge farkas_short 's/"farkas":\["[-0-9]*",/"farkas":[/' "$jam"
check 2 'Farkas vector has' check "$work/farkas_short.json"
forge farkas_zero 's/"farkas":\[[^]]*\]/"farkas":["0","0","0","0","0","0"]/' "$jam"
check 2 'fails' check "$work/farkas_zero.json"
forge farkas_negated 's/"farkas":\["\([0-9]\)/"farkas":["-\1/' "$jam"
check 2 'fails' check "$work/farkas_negated.json"
forge farkas_scaled 's/"farkas":\["\([1-9][0-9]*\)"/"farkas":["\1000001"/' "$jam"
check 2 'fails' check "$work/farkas_scaled.json"
forge farkas_float 's/"farkas":\["[-0-9]*"/"farkas":[0.1/' "$jam"
check 2 'certificate is INVALID' check "$work/farkas_float.json"
forge farkas_nan 's/"farkas":\["[-0-9]*"/"farkas":["nan"/' "$jam"
check 2 'is not an exact number' check "$work/farkas_nan.json"
forge farkas_digits "s/\"farkas\":\[\"[-0-9]*\"/\"farkas\":[\"$(head -c 5000 /dev/zero | tr '\0' 9)\"/" "$jam"
check 2 'more than 4096 digits' check "$work/farkas_digits.json"
forge farkas_missing 's/,"farkas":\[[^]]*\]//' "$jam"
check 2 'farkas: required field is missing' check "$work/farkas_missing.json"

# ---- the pair of a solvable certificate ----
forge x_changed 's/"x": *\[\n* *"\([^"]*\)"/"x":["\1+1"/' "$sol"
check 2 'is not an exact number' check "$work/x_changed.json"
forge x_bumped 's/"x": *\[\n* *"[^"]*"/"x":["12345"/' "$sol"
check 2 'certificate is INVALID' check "$work/x_bumped.json"
forge y_negative 's/"y": *\[\n* *"\([0-9]\)/"y":["-\1/' "$sol"
check 2 'certificate is INVALID' check "$work/y_negative.json"
forge x_short 's/"x": *\[\n* *"[^"]*",/"x":[/' "$sol"
check 2 '$.x: expected an array of' check "$work/x_short.json"
forge swap_xy 's/"x":/"tmp":/; s/"y":/"x":/; s/"tmp":/"y":/' "$sol"
check 2 'certificate is INVALID' check "$work/swap_xy.json"
forge kind_swap 's/"kind":"ucp_jammed"/"kind":"ucp_solvable"/' "$jam"
check 2 'unknown field' check "$work/kind_swap.json"
forge kind_other 's/"kind":"ucp_jammed"/"kind":"ucp_unsolvable"/' "$jam"
check 2 'expected a certificate kind' check "$work/kind_other.json"

# ---- a deep tree over many columns: the checker's memory stays O(n + depth), not O(n * depth) (each pair split
# once on a path, so depth <= n) ----
awk -v n=100000 -v depth=100000 -v digest=0 'BEGIN {
  printf "{\"kind\":\"ucp_jammed\",\"format\":2,\"problem_sha256\":\"%s\",\"problem\":{\"kind\":\"ucp\",\"n\":%d,", digest, n;
  for (side = 0; side < 2; side++) {
    printf "%s:{\"A\":[[", side ? ",\"Y\"" : "\"X\"";
    for (j = 0; j < n; j++) printf "%s1", j ? "," : "";
    printf "]],\"b\":[1]}";
  }
  printf "},\"nodes\":[";
  for (k = 0; k < depth; k++)
    printf "{\"branch\":%d,\"x_zero\":%d,\"y_zero\":%d},{\"empty\":\"Y\",\"farkas\":[\"-1\"]},", k % n, 2 * k + 2, 2 * k + 1;
  printf "{\"empty\":\"X\",\"farkas\":[\"1\"]}]}\n" }' > "$work/deep.json"
sed -i "s/\"problem_sha256\":\"[^\"]*\"/\"problem_sha256\":\"$(digest "$work/deep.json")\"/" "$work/deep.json"
check 2 'node 200000: the Farkas vector for X fails' check "$work/deep.json"

# ---- wrench cone certificates (cone --certificate): a Motzkin vector for an empty cone, a witness otherwise ----
ce=$work/cone_empty.json
cn=$work/cone_nonempty.json
"$cc" cone "$s/bt2002_section7_disk.json" --mode lr --certificate "$ce" > /dev/null
"$cc" cone "$s/bt2002_section4_disk.json" --mode na --certificate "$cn" > /dev/null
check 0 'cone_empty certificate is VALID' check "$ce" --problem "$s/bt2002_section7_disk.json"
check 0 'cone_nonempty certificate is VALID' check "$cn" --problem "$s/bt2002_section4_disk.json"
check 2 'is about another problem than' check "$ce" --problem "$s/bt2002_section4_disk.json"
forge ce_mode 's/"mode": "lr"/"mode": "nn"/' "$ce"
check 2 'certificate is INVALID' check "$work/ce_mode.json"
forge ce_bad_mode 's/"mode": "lr"/"mode": "lx"/' "$ce"
check 2 "mode: fixel 1's letter 'x'" check "$work/ce_bad_mode.json"
forge ce_zero 's/"motzkin": \[\n  \[\n   0,\n   "-1"/"motzkin": [[0, "0"/' "$ce"
check 2 '$.motzkin[0][1]: a non-zero integer weight' check "$work/ce_zero.json"
forge ce_negated 's/"motzkin": \[\n  \[\n   0,\n   "-1"/"motzkin": [[0, "1"/' "$ce"
check 2 'certificate is INVALID' check "$work/ce_negated.json"
forge ce_short 's/"motzkin": \[\n  \[\n   0,\n   "-1"\n  \],/"motzkin": [/' "$ce"
check 2 'certificate is INVALID' check "$work/ce_short.json"
forge ce_scene 's/\\"radius\\": 1}/\\"radius\\": 2}/' "$ce"
check 2 'problem_sha256 is not the digest of the embedded scene' check "$work/ce_scene.json"
forge cn_wrench 's/"wrench": \[\n *"1"/"wrench":["2"/' "$cn"
check 2 'K z != P g' check "$work/cn_wrench.json"
forge cn_z 's/"z": \[\n *"1"/"z":["-1"/' "$cn"
check 2 'violates its sign' check "$work/cn_z.json"
forge cn_names 's/"-a1n"/"a1n"/' "$cn"
check 2 'z_names differ' check "$work/cn_names.json"
forge cn_extra 's/"mode": "na"/"mode": "na", "empty": false/' "$cn"
check 2 '$.empty: unknown field' check "$work/cn_extra.json"
forge cn_kind 's/"cone_nonempty"/"cone_empty"/' "$cn"
check 2 'unknown field' check "$work/cn_kind.json"

# ---- the stability certificate's digest ----
"$cc" stability "$s/bt2002_section7_disk.json" --wrench 0,-1,0 --certificate "$work/st.json" > /dev/null
check 0 'stability certificate is VALID for' check "$work/st.json" --problem "$s/bt2002_section7_disk.json"
check 2 'is about another problem than' check "$work/st.json" --problem "$s/bt2002_section4_disk.json"
forge st_digest 's/"problem_sha256": "[0-9a-f]/"problem_sha256": "x/' "$work/st.json"
check 2 'problem_sha256 is not the digest of the embedded scene' check "$work/st_digest.json"
forge st_extra 's/"verdict"/"trusted": true, "verdict"/' "$work/st.json"
check 2 '$.trusted: unknown field' check "$work/st_extra.json"

# ---- G_goal certificates (design --insertable): the witness outside every set of Table 5, a push point ----
echo '{"candidates": [["7/5", 0], [2, "1/6"], [0, "7/5"]]}' > "$work/three.json"
"$cc" design "$s/bt2002_fig10_pentagon_insert.json" --candidates "$work/three.json" --goal-push --out "$work/goal" > /dev/null
gc=$work/goal/placement_1_goal.cert.json
check 0 'goal_nonempty certificate is VALID for' check "$gc" --problem "$work/goal/placement_1.json"
check 0 'holds the frictionless push at the push point' check "$gc"
check 2 'is about another problem than' check "$gc" --problem "$s/bt2002_fig10_pentagon_insert.json"
forge g_digest 's/"problem_sha256": "[0-9a-f]/"problem_sha256": "x/' "$gc"
check 2 'problem_sha256 is not the digest of the embedded scene' check "$work/g_digest.json"
forge g_extra 's/"outside"/"trusted": true, "outside"/' "$gc"
check 2 '$.trusted: unknown field' check "$work/g_extra.json"
forge g_extra_set 's/"motzkin"/"redundant": true, "motzkin"/' "$gc"
check 2 '$.outside[0].redundant: unknown field' check "$work/g_extra_set.json"
forge g_wrench 's/"wrench": \[\n  "[^"]*"/"wrench": [\n  "12345"/' "$gc"
check 2 'the wrench is not a positive multiple of the push at the push point' check "$work/g_wrench.json"
forge g_push_moved 's/"push": \[\n  "49\/46",\n  "89\/46"/"push": ["3\/2", "3\/2"/' "$gc"
check 2 'the wrench is not a positive multiple of the push at the push point' check "$work/g_push_moved.json"
forge g_push_vertex 's/"push": \[\n  "49\/46",\n  "89\/46"/"push": ["1", "2"/' "$gc"
check 2 'the push point is not a boundary point that is not a polygon vertex' check "$work/g_push_vertex.json"
forge g_push_inside 's/"push": \[\n  "49\/46",\n  "89\/46"/"push": ["1", "1"/' "$gc"
check 2 'the push point is not a point on the polygon boundary' check "$work/g_push_inside.json"
forge g_lifted 's/"wrench": \[[^]]*\],\n "push": \[[^]]*\]/"wrench": ["0", "1", "0"]/' "$gc"
check 2 'the Motzkin vector of sss in state 000 does not prove the wrench outside its cone' check "$work/g_lifted.json"
forge g_zero 's/"wrench": \[[^]]*\],\n "push": \[[^]]*\]/"wrench": ["0", "0", "0"]/' "$gc"
check 2 'the wrench is zero' check "$work/g_zero.json"
forge g_dropped 's/"outside": \[\n  {[^}]*},/"outside": [/' "$gc"
check 2 '"outside" has 25 sets, eq. (21) / Table 5 has 26' check "$work/g_dropped.json"
forge g_state 's/"state": "000"/"state": "111"/' "$gc"
check 2 'set 0 is not sss in state 000' check "$work/g_state.json"
forge g_motzkin_zero 's/"motzkin": \[\n    \[\n     0,\n     "1"/"motzkin": [[0, "0"/' "$gc"
check 2 '$.outside[0].motzkin[0][1]: a non-zero integer weight' check "$work/g_motzkin_zero.json"
forge g_motzkin_negated 's/"motzkin": \[\n    \[\n     0,\n     "1"/"motzkin": [[0, "-1"/' "$gc"
check 2 'the Motzkin vector of sss in state 000 does not prove' check "$work/g_motzkin_negated.json"
forge g_gap 's/\\"gap\\": \\"0\\"/\\"gap\\": \\"1\/100\\"/' "$gc"
sed -z "s/\"problem_sha256\": \"[0-9a-f]*\"/\"problem_sha256\": \"$(digest "$work/g_gap.json")\"/" "$work/g_gap.json" > "$work/g_gap_redigested.json"
check 2 'fixel 0 does not touch: the scene is not a goal configuration' check "$work/g_gap_redigested.json"
forge g_kind 's/"goal_nonempty"/"goal_empty"/' "$gc"
check 2 'expected a certificate kind' check "$work/g_kind.json"
# ---- vectors that hold only for wrong rows: the checker rebuilds Table 2's rows itself ----
# redigest FILE: sets FILE's problem_sha256 to the digest of its (changed) embedded scene.
redigest() { sed -i "s/\"problem_sha256\": *\"[0-9a-f]*\"/\"problem_sha256\": \"$(digest "$1")\"/" "$1"; }
# the kinetic friction of the embedded scene changed: the sliding modes' proofs were for the old rows
forge st_mu_k 's/\\"mu_k\\": \\"1.2\\"/\\"mu_k\\": \\"0.1\\"/' "$work/st.json"
redigest "$work/st_mu_k.json"
check 2 'does not verify' check "$work/st_mu_k.json"
# the static friction changed where g = (1, -2, 1) needs it (unstable at mu_s = 0.1): the resting forces leave
# their friction cones
"$cc" stability "$s/bt2002_section7_disk.json" --wrench 1,-2,1 --certificate "$work/st2.json" > /dev/null
check 0 'strongly_stable' check "$work/st2.json"
forge st_mu_s 's/\\"mu_s\\": \\"1.2\\"/\\"mu_s\\": \\"0.1\\"/' "$work/st2.json"
redigest "$work/st_mu_s.json"
check 2 'outside its static friction cone' check "$work/st_mu_s.json"
# l and r swapped in every proof (a sign flipped in each sliding row)
perl -0pe 's/("mode": ")([slrn]+)"/$1 . ($2 =~ tr{lr}{rl}r) . "\""/ge' "$work/st.json" > "$work/st_lr.json"
check 2 'certificate is INVALID' check "$work/st_lr.json"
# a cone witness with a friction force, for another friction coefficient; a witness for another inertia
"$cc" cone "$s/bt2002_section7_disk.json" --mode ns --certificate "$work/cone_ns.json" > /dev/null
check 0 'cone_nonempty certificate is VALID' check "$work/cone_ns.json"
forge cn_mu 's/\\"mu_s\\": \\"1.2\\"/\\"mu_s\\": \\"0.1\\"/' "$work/cone_ns.json"
redigest "$work/cn_mu.json"
check 2 'K z != P g' check "$work/cn_mu.json"
forge cn_inertia 's/\\"inertia\\": 1 }/\\"inertia\\": 2 }/' "$cn"
redigest "$work/cn_inertia.json"
check 2 'K z != P g' check "$work/cn_inertia.json"
# the modes of the mirror image (every l read as r): the accelerations do not realise them
"$cc" modes "$s/bt2002_section7_disk.json" --certificate "$work/modes.json" > /dev/null
check 0 'modes certificate is VALID' check "$work/modes.json" --problem "$s/bt2002_section7_disk.json"
forge modes_lr 's/"mode": "sl"/"mode": "sr"/' "$work/modes.json"
check 2 'does not realise it' check "$work/modes_lr.json"
forge modes_dead_lr 's/"prefix": "\([a-z]*\)l"/"prefix": "\1r"/' "$work/modes.json"
check 2 'certificate is INVALID' check "$work/modes_dead_lr.json"

# ---- cases by topic: tests/cli/cases/forged_*.sh, each sourced here with the variables and functions above ----
for cases_file in "$(dirname "$0")"/cases/forged_*.sh; do
  [ -e "$cases_file" ] && source "$cases_file"
done

summary forged_certificates
