# Forged spatial_modes certificates (issue 34), sourced by forged_certificates.sh: the checker
# (checker/spatial_modes_check.h) rebuilds every row from the embedded spatial scene, so a dropped mode or dead
# prefix, a witness that does not realise its mode, a changed Motzkin weight, a vector used on a prefix it does not
# prove (weighing a contact past the prefix other than by its row n . A vdot >= 0 with a weight <= 0), a foreign letter or a changed scene are INVALID (exit 2), a reference to a vector that does not exist or an
# unknown member refused (exit 2 naming the field), the same certificate in another layout refused, and the genuine
# certificate VALID. Each forgery edits one line of the text (the line layout, docs/formats.md section 5c).

fs=$work/forged_spatial
mkdir -p "$fs"
"$cc" modes "$s/spatial_box_on_plane.json" --certificate "$fs/box.json" > /dev/null
check 0 'spatial_modes certificate is VALID' check "$fs/box.json"
# every forgery at once (name|the reason check gives|the edit): FORGED/<name>.json is the certificate with one line
# edited: the statement applied to the JSON value x of element i of list L (L i statement; i = short: the dead line
# with the shortest parent), or of the head member L (L - statement); x = None drops the line
python3 - "$fs" <<'PY'
import json, sys
out = sys.argv[1]
spec = r"""
no_mode|are neither listed nor proven infeasible|modes 7 x = None
no_dead_line|are neither listed nor proven infeasible|dead 11 x = None
no_dead|are neither listed nor proven infeasible|dead 0 x["letters"] = x["letters"][1:]; x["vectors"] = x["vectors"][1:]
witness|does not realise it|modes 3 x["acceleration"][2] = "-1"
weight|does not verify|vectors 0 m = x["motzkin"]; m[0][1] = str(-int(m[0][1]))
twice|is listed twice|modes 0 x = [x, x]
letter|each s, f or A..|dead 1 x["parent"] = "Z"
no_vector|$.vectors[0]: expected an integer from 0 to|dead 0 x["vectors"][0] = vectors
elsewhere|does not verify|dead short x["vectors"][0] = next(i for i, v in enumerate(c["vectors"]) if any(r[0] > len(x["parent"]) and (r[1:] != ["s", 0] or int(dict(v["motzkin"]).get(n, "0")) > 0) for n, r in enumerate(v["rows"])))
scene|problem_sha256 is not the digest|scene - x = x.replace('"mu": "1/2"', '"mu": "1/3"')
moved||scene - x = x.replace('[1, 1, 0], "normal"', '[1, "1/2", 0], "normal"')
extra|extra|problem_sha256 - x = [x, 1]
"""
text = open(f"{out}/box.json").read()
c = json.loads(text)  # for looking up (the forgeries edit the text)
vectors = len(c["vectors"])
lines = text.split("\n")
cases = open(f"{out}/cases", "w")
for spec_line in spec.strip().splitlines():
    name, reason, edit = spec_line.split("|")
    list_name, i, statement = edit.split(" ", 2)
    if reason:
        cases.write(f"{name}|{reason}\n")
    key = f' "{list_name}": '
    if i == "short":  # the dead line with the shortest parent
        i = str(min(range(len(c["dead"])), key=lambda n: len(c["dead"][n]["parent"])))
    at = next(n for n, l in enumerate(lines) if l.startswith(key)) + (0 if i == "-" else int(i) + 1)
    line = lines[at]
    comma = line.endswith(",")
    start = len(key) if i == "-" else 2
    x = json.loads(line[start:len(line) - comma])
    exec(statement)
    forged = list(lines)
    if x is None:  # the line dropped (a list's last element: the comma before it too)
        del forged[at]
        if not comma:
            forged[at - 1] = forged[at - 1][:-1]
    elif name == "twice":  # the element written twice
        forged[at:at + 1] = [line if line.endswith(",") else line + ","] + [line]
    elif name == "extra":  # a member added after problem_sha256
        forged[at:at + 1] = [line[:start] + json.dumps(x[0]) + ",", ' "extra": 1,']
    else:
        forged[at] = line[:start] + json.dumps(x, separators=(",", ":")) + ("," if comma else "")
    open(f"{out}/{name}.json", "w").write("\n".join(forged))
json.dump(c, open(f"{out}/one_line.json", "w"))  # the same certificate in another layout
PY
# each forgery and the reason check gives (exit 2)
while IFS='|' read -r name reason; do check 2 "$reason" check "$fs/$name.json"; done < "$fs/cases"
check 2 'a spatial_modes certificate in lines, as modes writes it' check "$fs/one_line.json"
# a corner moved with the digest redone: the listed vectors no longer prove their prefixes
sed -i "s/\"problem_sha256\": *\"[0-9a-f]*\"/\"problem_sha256\": \"$(digest "$fs/moved.json")\"/" "$fs/moved.json"
check 2 'certificate is INVALID' check "$fs/moved.json"
