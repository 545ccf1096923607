# Forged assembly_modes certificates (issue 31), sourced by forged_certificates.sh: the checker rebuilds each
# prefix's rows from the embedded assembly's re-verified frames, so a dropped or repeated branch, a mode with a
# wrong acceleration, a wrong Motzkin vector or a relabelled body are INVALID (exit 2), the genuine one VALID.

fm=$work/forged_assembly_modes
mkdir -p "$fm"
"$cc" modes "$s/assembly_two_boxes.json" --certificate "$fm/modes.json" > /dev/null
check 0 'assembly_modes certificate is VALID' check "$fm/modes.json"
edit() { python3 -c "import json, sys; c = json.load(open(sys.argv[1])); $3; json.dump(c, open(sys.argv[2], 'w'))" "$1" "$2"; }
edit "$fm/modes.json" "$fm/dropped_dead.json" 'del c["dead"][0]'
check 2 'are neither listed nor proven infeasible' check "$fm/dropped_dead.json"
edit "$fm/modes.json" "$fm/dropped_mode.json" 'del c["modes"][5]'
check 2 'are neither listed nor proven infeasible' check "$fm/dropped_mode.json"
edit "$fm/modes.json" "$fm/twice.json" 'c["modes"].append(c["modes"][0])'
check 2 'is listed twice' check "$fm/twice.json"
edit "$fm/modes.json" "$fm/inside.json" 'd = next(x for x in c["dead"] if len(x["prefix"]) < 4); c["dead"].append({"prefix": d["prefix"] + "s", "motzkin": d["motzkin"]})'
check 2 'extends the listed prefix' check "$fm/inside.json"
# a wrong acceleration: the bodies' accelerations swapped (a relabelled body)
edit "$fm/modes.json" "$fm/relabelled.json" 'a = c["modes"][0]["acceleration"]; c["modes"][0]["acceleration"] = a[3:] + a[:3]'
check 2 'does not realise it' check "$fm/relabelled.json"
edit "$fm/modes.json" "$fm/wrong_vector.json" 'm = c["dead"][0]["motzkin"]; m[0][1] = str(-int(m[0][1]))'
check 2 'does not verify' check "$fm/wrong_vector.json"
# a mode string of the wrong length or with a letter outside s l r n
edit "$fm/modes.json" "$fm/short.json" 'c["modes"][0]["mode"] = c["modes"][0]["mode"][:-1]'
check 2 '$.modes[0].mode' check "$fm/short.json"
edit "$fm/modes.json" "$fm/letter.json" 'c["dead"][0]["prefix"] = "x"'
check 2 '$.dead[0].prefix' check "$fm/letter.json"
# the scene changed under the digest
edit "$fm/modes.json" "$fm/scene.json" 'c["scene"] = c["scene"].replace("1/2", "1/3")'
check 2 'problem_sha256 is not the digest' check "$fm/scene.json"
