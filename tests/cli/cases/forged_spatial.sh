# Forged spatial_modes certificates (issue 34), sourced by forged_certificates.sh: the checker
# (checker/spatial_modes_check.h) rebuilds every row from the embedded spatial scene, so a dropped mode or dead
# prefix, a witness that does not realise its mode, a changed Motzkin weight, a foreign letter or a changed scene are
# INVALID (exit 2) and the genuine certificate VALID.

fs=$work/forged_spatial
mkdir -p "$fs"
"$cc" modes "$s/spatial_box_on_plane.json" --certificate "$fs/box.json" > /dev/null
check 0 'spatial_modes certificate is VALID' check "$fs/box.json"
sedit() { python3 -c "import json, sys; c = json.load(open(sys.argv[1])); $3; json.dump(c, open(sys.argv[2], 'w'))" "$1" "$2"; }
sedit "$fs/box.json" "$fs/no_mode.json" 'del c["modes"][7]'
check 2 'are neither listed nor proven infeasible' check "$fs/no_mode.json"
sedit "$fs/box.json" "$fs/no_dead.json" 'del c["dead"][11]'
check 2 'are neither listed nor proven infeasible' check "$fs/no_dead.json"
sedit "$fs/box.json" "$fs/witness.json" 'c["modes"][3]["acceleration"][2] = "-1"'
check 2 'does not realise it' check "$fs/witness.json"
sedit "$fs/box.json" "$fs/weight.json" 'm = c["dead"][0]["motzkin"]; m[0][1] = str(-int(m[0][1]))'
check 2 'does not verify' check "$fs/weight.json"
sedit "$fs/box.json" "$fs/twice.json" 'c["modes"].append(c["modes"][0])'
check 2 'is listed twice' check "$fs/twice.json"
sedit "$fs/box.json" "$fs/letter.json" 'c["dead"][0]["prefix"] = "Z"'
check 2 'each s, f or A..' check "$fs/letter.json"
sedit "$fs/box.json" "$fs/scene.json" 'c["scene"] = c["scene"].replace("\"mu\": \"1/2\"", "\"mu\": \"1/3\"")'
check 2 'problem_sha256 is not the digest' check "$fs/scene.json"
# a scene changed with its digest redone: the corner moved, so the listed vectors no longer prove their prefixes
sedit "$fs/box.json" "$fs/moved.json" 'c["scene"] = c["scene"].replace("[1, 1, 0], \"normal\"", "[1, \"1/2\", 0], \"normal\"")'
sed -i "s/\"problem_sha256\": *\"[0-9a-f]*\"/\"problem_sha256\": \"$(digest "$fs/moved.json")\"/" "$fs/moved.json"
check 2 'certificate is INVALID' check "$fs/moved.json"
sedit "$fs/box.json" "$fs/extra.json" 'c["extra"] = 1'
check 2 'extra' check "$fs/extra.json"
