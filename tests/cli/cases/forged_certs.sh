# Certificates mean exactly what they say (issue 29, item 2): every list of a certificate holds each entry once
# and nothing else (modes, dead prefixes, stability proofs, G_goal sets, cone components, UCP tree nodes), and
# Motzkin vectors are sparse [[row, "weight"], ...] lists with rows strictly increasing and in range, weights
# non-zero primitive integers (docs/formats.md section 5). Sourced by forged_certificates.sh: uses check, forge,
# $cc, $work, $s and the certificates it wrote ($jam, $sol, $ce, $cn, $gc, $work/st.json, $work/modes.json).

# jforge NAME FROM CODE: NAME.json is FROM with the Python statements CODE applied to its JSON object `c`.
jforge() {
  python3 -c 'import json, sys
c = json.load(open(sys.argv[1]))
exec(sys.argv[3])
json.dump(c, open(sys.argv[2], "w"), indent=1)' "$2" "$work/$1.json" "$3"
}

# ---- modes: the disk of section 7 (10 modes of 2 fixels) and the peg of Figure 4c (a dead prefix "ll" of 3) ----
md=$work/modes.json
mp=$work/modes_peg.json
"$cc" modes "$s/bt2002_fig4c_peg_lra.json" --certificate "$mp" > /dev/null
check 0 '13 feasible modes, ' check "$mp" --problem "$s/bt2002_fig4c_peg_lra.json"
check 0 'every feasible mode is listed once' check "$md"
jforge m_twice "$md" 'c["modes"].append(c["modes"][3])'
check 2 "'sn' is listed twice" check "$work/m_twice.json"
# the forgery: a mode listed 1000 more times, counted as 1010 modes of a disk with 10
jforge m_1000 "$md" 'c["modes"] += [c["modes"][0]] * 1000'
check 2 "'ss' is listed twice" check "$work/m_1000.json"
jforge m_dropped "$md" 'del c["modes"][4]'
check 2 "the modes starting with 'ls' are neither listed nor proven infeasible" check "$work/m_dropped.json"
jforge m_last_dropped "$md" 'c["modes"].pop()'
check 2 "the modes starting with 'nn' are neither listed" check "$work/m_last_dropped.json"
jforge m_dead_twice "$md" 'c["dead"].append(c["dead"][0])'
check 2 "'lr' is listed twice" check "$work/m_dead_twice.json"
jforge m_dead_dropped "$md" 'del c["dead"][2]'
check 2 "the modes starting with 'rl' are neither listed" check "$work/m_dead_dropped.json"
jforge m_dead_inside "$mp" 'd = next(x for x in c["dead"] if x["prefix"] == "ll"); c["dead"].append({"prefix": "lls", "motzkin": d["motzkin"]})'
check 2 "'lls' extends the listed prefix 'll', which accounts for its modes already" check "$work/m_dead_inside.json"
jforge m_dead_is_mode "$md" 'c["dead"].append({"prefix": "ss", "motzkin": [[0, "1"], [1, "1"]]})'
check 2 'the certificate of dead prefix ss does not verify' check "$work/m_dead_is_mode.json"
jforge m_mode_in_dead "$md" 'c["modes"].append({"mode": "lr", "acceleration": c["modes"][4]["acceleration"]})'
check 2 'does not realise it' check "$work/m_mode_in_dead.json"
jforge m_dead_extra_key "$md" 'c["dead"][0]["count"] = 1'
check 2 '$.dead[0].count: unknown field' check "$work/m_dead_extra_key.json"
jforge m_mode_extra_key "$md" 'c["modes"][0]["times"] = 1000'
check 2 '$.modes[0].times: unknown field' check "$work/m_mode_extra_key.json"
# sparse Motzkin vectors
jforge m_row_twice "$md" 'y = c["dead"][0]["motzkin"]; y.insert(1, list(y[0]))'
check 2 '$.dead[0].motzkin[1][0]: a row above 0: rows strictly increasing, each weighted row once (row 0 is repeated)' check "$work/m_row_twice.json"
jforge m_row_range "$md" 'c["dead"][0]["motzkin"].append([4, "1"])'
check 2 '$.dead[0].motzkin[4][0]: expected an integer from 0 to 3, found 4' check "$work/m_row_range.json"
jforge m_row_huge "$md" 'c["dead"][0]["motzkin"][3][0] = "18446744073709551616"'
check 2 '$.dead[0].motzkin[3][0]: expected an integer from 0 to 3' check "$work/m_row_huge.json"
jforge m_row_negative "$md" 'c["dead"][0]["motzkin"][0][0] = -1'
check 2 '$.dead[0].motzkin[0][0]: expected an integer from 0 to 3, found -1' check "$work/m_row_negative.json"
jforge m_row_fraction "$md" 'c["dead"][0]["motzkin"][1][0] = "1/2"'
check 2 '$.dead[0].motzkin[1][0]: expected an integer' check "$work/m_row_fraction.json"
jforge m_rows_swapped "$md" 'y = c["dead"][0]["motzkin"]; y[0], y[1] = y[1], y[0]'
check 2 '$.dead[0].motzkin[1][0]: a row above 1' check "$work/m_rows_swapped.json"
jforge m_weight_zero "$md" 'c["dead"][1]["motzkin"][2][1] = "0"'
check 2 '$.dead[1].motzkin[2][1]: a non-zero integer weight' check "$work/m_weight_zero.json"
jforge m_weight_fraction "$md" 'c["dead"][1]["motzkin"][2][1] = "1/3"'
check 2 '$.dead[1].motzkin[2][1]: a non-zero integer weight' check "$work/m_weight_fraction.json"
jforge m_not_primitive "$md" 'c["dead"][1]["motzkin"] = [[r, str(2 * int(w))] for r, w in c["dead"][1]["motzkin"]]'
check 2 '$.dead[1].motzkin: a primitive integer vector: the weights have the common factor 2' check "$work/m_not_primitive.json"
jforge m_empty "$md" 'c["dead"][1]["motzkin"] = []'
check 2 '$.dead[1].motzkin: a Motzkin vector: at least one [row, weight] pair' check "$work/m_empty.json"
jforge m_dense "$md" 'c["dead"][1]["motzkin"] = ["-1", "1", "-1", "-1"]'
check 2 '$.dead[1].motzkin[0]: a pair [row, weight]' check "$work/m_dense.json"
jforge m_triple "$md" 'c["dead"][1]["motzkin"][0].append("7")'
check 2 '$.dead[1].motzkin[0]: a pair [row, weight]' check "$work/m_triple.json"
jforge m_row_dropped "$md" 'del c["dead"][1]["motzkin"][0]'
check 2 'the certificate of dead prefix ln does not verify' check "$work/m_row_dropped.json"
jforge m_row_moved "$md" 'c["dead"][1]["motzkin"][0][0] = 1; del c["dead"][1]["motzkin"][1]'
check 2 'the certificate of dead prefix ln does not verify' check "$work/m_row_moved.json"

# ---- stability: the disk of section 7 strongly stable under (0, -1, 0); the peg of Figure 4c unstable ----
st=$work/st.json
su=$work/st_unstable.json
sw=$work/st_weak.json
"$cc" stability "$s/bt2002_fig4c_peg_lra.json" --wrench 0,-1,0 --certificate "$su" > /dev/null
"$cc" stability "$s/bt2002_section7_disk.json" --wrench -1,-1,0 --certificate "$sw" > /dev/null
check 0 'stability certificate is VALID' check "$su"
check 0 'weakly_stable' check "$sw"
jforge s_proof_twice "$st" 'c["proofs"].append(c["proofs"][1])'
check 2 "'sl' is listed twice" check "$work/s_proof_twice.json"
jforge s_dead_twice "$st" 'c["proofs"].append(next(p for p in c["proofs"] if p["kinematic"]))'
check 2 "'lr' is listed twice" check "$work/s_dead_twice.json"
jforge s_proof_dropped "$st" 'del c["proofs"][0]'
check 2 "no proof covers the moving modes that start with 'ss'" check "$work/s_proof_dropped.json"
jforge s_dead_dropped "$st" 'c["proofs"] = [p for p in c["proofs"] if p["mode"] != "rn"]'
check 2 "no proof covers the moving modes that start with 'rn'" check "$work/s_dead_dropped.json"
# a moving mode's proof for a mode that a dead prefix already covers (the same vector verifies it)
jforge s_mode_in_dead "$st" 'd = next(p for p in c["proofs"] if p["mode"] == "lr"); c["proofs"].append({"mode": "lr", "kinematic": False, "motzkin": d["motzkin"]})'
check 2 "'lr' is listed twice" check "$work/s_mode_in_dead.json"
jforge s_proofs_beside_witness "$sw" 'c["proofs"] = [{"mode": "s", "kinematic": True, "motzkin": [[0, "1"]]}]'
check 2 'the proofs are extra entries' check "$work/s_proofs_beside_witness.json"
jforge s_proofs_unstable "$su" 'c["proofs"] = [{"mode": "s", "kinematic": True, "motzkin": [[0, "1"]]}]'
check 2 'the proofs are extra entries' check "$work/s_proofs_unstable.json"
jforge s_row_twice "$st" 'y = c["proofs"][0]["motzkin"]; y.insert(2, list(y[1]))'
check 2 '$.proofs[0].motzkin[2][0]: a row above 1: rows strictly increasing, each weighted row once (row 1 is repeated)' check "$work/s_row_twice.json"
jforge s_row_range "$st" 'c["proofs"][9]["motzkin"][-1][0] = 4'
check 2 '$.proofs[9].motzkin[3][0]: expected an integer from 0 to 3, found 4' check "$work/s_row_range.json"
jforge s_not_primitive "$st" 'c["proofs"][1]["motzkin"] = [[r, str(3 * int(w))] for r, w in c["proofs"][1]["motzkin"]]'
check 2 '$.proofs[1].motzkin: a primitive integer vector: the weights have the common factor 3' check "$work/s_not_primitive.json"
jforge s_rest_twice "$su" 'y = c["resting"]["motzkin"]; y.append(list(y[-1]))'
check 2 'rows strictly increasing, each weighted row once' check "$work/s_rest_twice.json"
jforge s_rest_range "$su" 'c["resting"]["motzkin"].append([15, "1"])'
check 2 '$.resting.motzkin[' check "$work/s_rest_range.json"
jforge s_rest_zero "$su" 'c["resting"]["motzkin"][0][1] = "0"'
check 2 '$.resting.motzkin[0][1]: a non-zero integer weight' check "$work/s_rest_zero.json"
jforge s_rest_dense "$su" 'c["resting"]["motzkin"] = ["1"] * 15'
check 2 '$.resting.motzkin[0]: a pair [row, weight]' check "$work/s_rest_dense.json"
jforge s_rest_both "$st" 'c["resting"]["motzkin"] = [[0, "1"]]'
check 2 '$.resting.motzkin: unknown field' check "$work/s_rest_both.json"
jforge s_proof_key "$st" 'c["proofs"][0]["weight"] = 2'
check 2 '$.proofs[0].weight: unknown field' check "$work/s_proof_key.json"
jforge s_moving_key "$sw" 'c["moving"]["note"] = "x"'
check 2 '$.moving.note: unknown field' check "$work/s_moving_key.json"

# ---- cone_empty (section 7, mode lr: 4 rows) and cone_nonempty (section 4, mode na) ----
jforge c_row_twice "$ce" 'y = c["motzkin"]; y.insert(1, list(y[0]))'
check 2 '$.motzkin[1][0]: a row above 0' check "$work/c_row_twice.json"
jforge c_row_range "$ce" 'c["motzkin"][-1][0] = 4'
check 2 '$.motzkin[3][0]: expected an integer from 0 to 3, found 4' check "$work/c_row_range.json"
jforge c_not_primitive "$ce" 'c["motzkin"] = [[r, str(5 * int(w))] for r, w in c["motzkin"]]'
check 2 '$.motzkin: a primitive integer vector: the weights have the common factor 5' check "$work/c_not_primitive.json"
jforge c_fraction "$ce" 'c["motzkin"][0][1] = "-1/2"'
check 2 '$.motzkin[0][1]: a non-zero integer weight' check "$work/c_fraction.json"
jforge c_empty "$ce" 'c["motzkin"] = []'
check 2 '$.motzkin: a Motzkin vector: at least one [row, weight] pair' check "$work/c_empty.json"
jforge c_dense "$ce" 'c["motzkin"] = ["-1", "-1", "1", "-1"]'
check 2 '$.motzkin[0]: a pair [row, weight]' check "$work/c_dense.json"
jforge c_dropped "$ce" 'del c["motzkin"][2]'
check 2 'cone_empty certificate is INVALID' check "$work/c_dropped.json"
jforge n_z_extra "$cn" 'c["z"].append("0")'
check 2 '$.z: expected an array of 3 numbers, found 4' check "$work/n_z_extra.json"
jforge n_z_dropped "$cn" 'c["z"].pop()'
check 2 '$.z: expected an array of 3 numbers, found 2' check "$work/n_z_dropped.json"
jforge n_name_extra "$cn" 'c["z_names"].append("c0n")'
check 2 'z_names differ' check "$work/n_name_extra.json"
jforge n_name_twice "$cn" 'c["z_names"][2] = c["z_names"][1]'
check 2 'z_names differ' check "$work/n_name_twice.json"
jforge n_wrench_extra "$cn" 'c["wrench"].append("0")'
check 2 '$.wrench: expected an array of 3 numbers, found 4' check "$work/n_wrench_extra.json"

# ---- goal_nonempty: exactly the 26 sets of Table 5, in order, each vector sparse and primitive ----
jforge g_set_twice "$gc" 'c["outside"].append(c["outside"][0])'
check 2 '"outside" has 27 sets, eq. (21) / Table 5 has 26' check "$work/g_set_twice.json"
jforge g_last_dropped "$gc" 'c["outside"].pop()'
check 2 '"outside" has 25 sets' check "$work/g_last_dropped.json"
jforge g_sets_swapped "$gc" 'o = c["outside"]; o[1], o[2] = o[2], o[1]'
check 2 'set 1 is not suu in state 100' check "$work/g_sets_swapped.json"
jforge g_set_repeated "$gc" 'c["outside"][2] = c["outside"][1]'
check 2 'set 2 is not' check "$work/g_set_repeated.json"
jforge g_row_twice "$gc" 'y = c["outside"][0]["motzkin"]; y.insert(1, list(y[0]))'
check 2 '$.outside[0].motzkin[1][0]: a row above 0' check "$work/g_row_twice.json"
jforge g_row_range "$gc" 'c["outside"][1]["motzkin"][0][0] = 9'
check 2 '$.outside[1].motzkin[0][0]: expected an integer from 0 to' check "$work/g_row_range.json"
jforge g_not_primitive "$gc" 'c["outside"][0]["motzkin"] = [[r, str(7 * int(w))] for r, w in c["outside"][0]["motzkin"]]'
check 2 '$.outside[0].motzkin: a primitive integer vector: the weights have the common factor 7' check "$work/g_not_primitive.json"
jforge g_fraction "$gc" 'c["outside"][0]["motzkin"][0][1] = "1/2"'
check 2 '$.outside[0].motzkin[0][1]: a non-zero integer weight' check "$work/g_fraction.json"
jforge g_dense "$gc" 'c["outside"][0]["motzkin"] = ["1", "1", "1"]'
check 2 '$.outside[0].motzkin[0]: a pair [row, weight]' check "$work/g_dense.json"

# ---- ucp_jammed: each pair split once on a path, each node once, Farkas vectors primitive integers ----
# node 0 splits a pair, its y_zero child (a split node) splits it again
jforge u_split_again "$jam" 'n = c["nodes"]; n[n[0]["y_zero"]]["branch"] = n[0]["branch"]'
check 2 'node 2: branches on 8, which this path has fixed already' check "$work/u_split_again.json"
jforge u_farkas_double "$jam" 'f = c["nodes"][1]["farkas"]; c["nodes"][1]["farkas"] = [str(2 * int(x)) for x in f]'
check 2 'node 1: the Farkas vector for X fails: it is not a primitive integer vector' check "$work/u_farkas_double.json"
jforge u_farkas_fraction "$jam" 'c["nodes"][1]["farkas"][0] += "/2"'
check 2 'it is not a primitive integer vector' check "$work/u_farkas_fraction.json"
jforge u_leaf_again "$jam" 'c["nodes"].append(c["nodes"][1])'
check 2 'is not reachable from the root' check "$work/u_leaf_again.json"
jforge u_child_twice "$jam" 'c["nodes"][0]["y_zero"] = c["nodes"][0]["x_zero"]'
check 2 'reached twice' check "$work/u_child_twice.json"
jforge x_extra "$sol" 'c["x"].append("0")'
check 2 '$.x: expected an array of' check "$work/x_extra.json"
jforge y_extra "$sol" 'c["y"].append("0")'
check 2 '$.y: expected an array of' check "$work/y_extra.json"
