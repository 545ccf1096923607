# Forged spatial_stability certificates (issue 34), sourced by forged_certificates.sh: the checker
# (checker/spatial_stability_check.h) rebuilds every row from the embedded spatial scene, so a dropped proof (a mode
# or a dead prefix), a changed Motzkin weight or resting force, a vector reused on rows it does not prove, a witness
# that does not move, forces its letter does not allow, a claimed verdict the evidence does not support, or a changed
# scene are INVALID (exit 2), a reference to a vector that does not exist or a malformed vector refused (exit 2
# naming the field), and the genuine certificates VALID.

fz=$work/forged_stab34
mkdir -p "$fz"
"$cc" stability "$s/spatial_box_on_plane.json" --wrench 0,0,-1,0,0,0 --certificate "$fz/rest.json" > /dev/null
"$cc" stability "$s/spatial_box_on_plane.json" --wrench 3/5,0,-1,0,0,0 --certificate "$fz/slide.json" > /dev/null
check 0 'spatial_stability certificate is VALID' check "$fz/rest.json"
check 0 'spatial_stability certificate is VALID' check "$fz/slide.json"
python3 - "$fz" <<'PY'
import json, sys
out = sys.argv[1]
# one forgery a line: its name, the certificate it edits (rest or slide), a statement on that certificate's dict c
spec = r"""
no_proof rest del c["modes"][-1]
no_dead rest del c["dead"][0]
weight rest m = c["vectors"][c["modes"][-1]["vector"]]["motzkin"]; m[0][1] = str(-int(m[0][1]))
resting rest c["resting"]["weights"][0] = "1"
negative rest c["resting"]["weights"][1] = "-1/5"; c["resting"]["weights"][0] = "2/5"
claim rest c["verdict"] = "weakly_stable"
sticking rest c["modes"].append({"mode": "ffff", "vector": 0})
no_vector rest c["modes"][0]["vector"] = len(c["vectors"])
dynamics rest c["dead"][0]["vectors"][0] = c["modes"][0]["vector"]
elsewhere rest d = min(c["dead"], key=lambda d: len(d["parent"])); d["vectors"][0] = next(i for i, v in enumerate(c["vectors"]) if any(r[0] > len(d["parent"]) and (r[1:] != ["s", 0] or int(dict(v["motzkin"]).get(n, "0")) > 0) for n, r in enumerate(v["rows"])))
twice rest v = c["vectors"][0]; v["rows"].append(v["rows"][0]); v["motzkin"].append([len(v["rows"]) - 1, "1"])
unweighted rest v = c["vectors"][0]; v["rows"].append([0, "s", 0])
letter_z rest c["vectors"][0]["rows"][0][1] = "Z"
still slide c["moving"]["acceleration"] = ["0"] * 6
letter slide c["moving"]["weights"][0] = "1/8"
farkas slide m = c["resting"]["motzkin"]; m[0][1] = str(-int(m[0][1]))
scene slide c["scene"] = c["scene"].replace('"mu": "1/2"', '"mu": "1/3"')
extra slide c["dead"] = [{"parent": "", "letters": "s", "vectors": [0]}]
"""
def dump(c, path):
    """c in the certificate's line layout (docs/formats.md section 5c): a member a line, a list's element a line."""
    entries = []
    for k, v in c.items():
        if k in ("vectors", "dead", "modes"):
            items = ["  " + json.dumps(e, separators=(",", ":")) for e in v]
            entries.append([f' "{k}": ['] + [x + "," for x in items[:-1]] + items[-1:] + [" ]"])
        else:
            entries.append([f' "{k}": ' + json.dumps(v, separators=(",", ":"))])
    lines = ["{"]
    for i, e in enumerate(entries):
        lines += e[:-1] + [e[-1] + ("," if i + 1 < len(entries) else "")]
    open(path, "w").write("\n".join(lines + ["}"]) + "\n")
for line in spec.strip().splitlines():
    name, base, statement = line.split(" ", 2)
    c = json.load(open(f"{out}/{base}.json"))
    exec(statement)
    dump(c, f"{out}/{name}.json")
c = json.load(open(f"{out}/rest.json"))
json.dump(c, open(f"{out}/one_line.json", "w"))  # the same certificate in another layout
dump(c, f"{out}/relaid.json")  # and in the line layout again, by this script: VALID
PY
# the line layout itself: a comma dropped, a list check does not know
sed '0,/^  {"rows".*},$/s//&/; 0,/^\(  {"rows".*}\),$/s//\1/' "$fz/rest.json" > "$fz/comma.json"
sed 's/^ "modes": \[$/ "proofs": [/' "$fz/rest.json" > "$fz/unknown_list.json"
check 0 'spatial_stability certificate is VALID' check "$fz/relaid.json"
check 2 'a spatial_stability certificate in lines, as stability writes it' check "$fz/one_line.json"
check 2 "a ',' at the end of the line: more follows" check "$fz/comma.json"
check 2 'a known list, found "proofs"' check "$fz/unknown_list.json"
# each forgery and the reason check gives (exit 2)
while IFS='|' read -r name reason; do
  check 2 "$reason" check "$fz/$name.json"
done <<'CASES'
no_proof|no proof covers the moving modes
no_dead|no proof covers the moving modes
weight|does not verify
resting|the resting forces: Newton-Euler does not hold
negative|the resting forces: a negative weight
claim|the evidence supports strongly_stable
sticking|a proof for f..f is not evidence
no_vector|$.vector: expected an integer from 0 to
dynamics|the kinematic proof for prefix
elsewhere|does not verify
twice|is weighed twice
unweighted|a row the vector weighs
letter_z|a letter of contact
still|the moving witness does not move
letter|which letter E does not allow
farkas|no resting solution exists does not verify
scene|problem_sha256 is not the digest
extra|the proofs are extra entries
CASES
