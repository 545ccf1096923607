# Forged spatial_cone certificates (issue 34), sourced by forged_certificates.sh: the checker
# (checker/spatial_cone_check.h) rebuilds the mode's rows from the embedded spatial scene and checks both written
# forms itself, so a dropped generator, a dropped or changed facet, a strict row written as an inequality, another
# mode, a changed Motzkin weight or a relabelled contact are INVALID (exit 2) and the genuine certificates VALID.

fc=$work/forged_cone34
mkdir -p "$fc"
"$cc" cone "$s/spatial_box_on_plane.json" --mode ffff --certificate "$fc/stick.json" > /dev/null
"$cc" cone "$s/spatial_box_on_plane.json" --mode ssss --certificate "$fc/lift.json" > /dev/null
"$cc" cone "$s/spatial_box_on_plane.json" --mode ffss --certificate "$fc/tip.json" > /dev/null
"$cc" cone "$s/spatial_box_on_plane.json" --mode sAsB --certificate "$fc/empty.json" > /dev/null
for c in stick lift tip empty; do check 0 'spatial_cone certificate is VALID' check "$fc/$c.json"; done
check 0 '"rays":16' check "$fc/stick.json" --json
python3 - "$fc" <<'PY'
import json, sys
out = sys.argv[1]
# one forgery a line: its name, the certificate it edits, a statement on that certificate's dict c
spec = r"""
no_ray stick del c["cone"]["span"]["rays"][3]; del c["rays"][3]
no_point stick del c["rays"][3]
no_facet stick del c["cone"]["face"]["inequalities"][0]; del c["inequalities"][0]
wrong_facet stick c["cone"]["face"]["inequalities"][0][2] = "5"
weight stick m = c["inequalities"][2]; m[0][1] = str(-int(m[0][1]))
mode stick c["mode"] = "fffB"
kept lift c["cone"]["face"]["inequalities"] = [c["cone"]["face"]["strict"].pop(0)]; c["inequalities"] = [c["strict"].pop(0)]; del c["cone"]["open_faces"][3]
empty empty c["mode"] = "ffff"
relabel tip sc = json.loads(c["scene"]); sc["contacts"][0], sc["contacts"][2] = sc["contacts"][2], sc["contacts"][0]; c["scene"] = json.dumps(sc)
"""
for line in spec.strip().splitlines():
    name, base, statement = line.split(" ", 2)
    c = json.load(open(f"{out}/{base}.json"))
    exec(statement)
    json.dump(c, open(f"{out}/{name}.json", "w"))
PY
# the relabelled scene with its own digest (check reports the embedded scene's digest): only its rows betray it
digest=$("$cc" check "$fc/relabel.json" --json | python3 -c 'import json,sys; print(json.load(sys.stdin)["problem_sha256"])')
python3 -c 'import json,sys; c=json.load(open(sys.argv[1])); c["problem_sha256"]=sys.argv[2]; json.dump(c, open(sys.argv[1], "w"))' \
  "$fc/relabel.json" "$digest"
# each forgery and the reason check gives (exit 2)
while IFS='|' read -r name reason; do
  check 2 "$reason" check "$fc/$name.json"
done <<'CASES'
no_ray|the written cone: inequality 5 is not a facet
no_point|expected one point per ray (16)
no_facet|is no row of the face form
wrong_facet|the written cone: inequality 0 is not a facet
weight|the proof of inequality 2 does not verify
mode|is not a solution of the mode
kept|no point of the cone is given on the face of the closure through rays 0 1,
empty|does not prove mode ffff kinematically infeasible
relabel|is not a solution of the mode
CASES
