# Forged spatial_modes certificates (issue 34), sourced by forged_certificates.sh: the checker
# (checker/spatial_modes_check.h) rebuilds every row from the embedded spatial scene, so a dropped mode or dead
# prefix, a witness that does not realise its mode, a changed Motzkin weight, a foreign letter or a changed scene are
# INVALID (exit 2) and the genuine certificate VALID.

fs=$work/forged_spatial
mkdir -p "$fs"
"$cc" modes "$s/spatial_box_on_plane.json" --certificate "$fs/box.json" > /dev/null
check 0 'spatial_modes certificate is VALID' check "$fs/box.json"
# every forgery at once: FORGED/<name>.json is the certificate with the statement applied to its dict c
python3 - "$fs" <<'PY'
import json, sys
out = sys.argv[1]
forgeries = {
    "no_mode": 'del c["modes"][7]',
    "no_dead": 'del c["dead"][11]',
    "witness": 'c["modes"][3]["acceleration"][2] = "-1"',
    "weight": 'm = c["dead"][0]["motzkin"]; m[0][1] = str(-int(m[0][1]))',
    "twice": 'c["modes"].append(c["modes"][0])',
    "letter": 'c["dead"][0]["prefix"] = "Z"',
    "scene": 'c["scene"] = c["scene"].replace("\\"mu\\": \\"1/2\\"", "\\"mu\\": \\"1/3\\"")',
    "moved": 'c["scene"] = c["scene"].replace("[1, 1, 0], \\"normal\\"", "[1, \\"1/2\\", 0], \\"normal\\"")',
    "extra": 'c["extra"] = 1',
}
for name, statement in forgeries.items():
    c = json.load(open(f"{out}/box.json"))
    exec(statement)
    json.dump(c, open(f"{out}/{name}.json", "w"))
PY
check 2 'are neither listed nor proven infeasible' check "$fs/no_mode.json"
check 2 'are neither listed nor proven infeasible' check "$fs/no_dead.json"
check 2 'does not realise it' check "$fs/witness.json"
check 2 'does not verify' check "$fs/weight.json"
check 2 'is listed twice' check "$fs/twice.json"
check 2 'each s, f or A..' check "$fs/letter.json"
check 2 'problem_sha256 is not the digest' check "$fs/scene.json"
check 2 'extra' check "$fs/extra.json"
# a corner moved with the digest redone: the listed vectors no longer prove their prefixes
sed -i "s/\"problem_sha256\": *\"[0-9a-f]*\"/\"problem_sha256\": \"$(digest "$fs/moved.json")\"/" "$fs/moved.json"
check 2 'certificate is INVALID' check "$fs/moved.json"
