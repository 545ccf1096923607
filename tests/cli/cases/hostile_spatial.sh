# `modes` on a spatial scene (issue 34; docs/formats.md section 3b), sourced by hostile_inputs.sh: the modes of a body
# in space with their certificate, the reader's refusals (exit 2 naming the field), the options that do not apply
# refused, the budgets (exit 3 with what was covered), and `stability` with a planar wrench refused.

sd=$work/spatial
mkdir -p "$sd"
box=$s/spatial_box_on_plane.json
check 0 '340 feasible modes of 4 contacts of a body in space' modes "$box"
check 0 '99 keep every contact, 1 separate every contact' modes "$box"
check 0 '"counts":{"modes":340,"all_separating":1,"all_touching":99}' modes "$box" --json --certificate "$sd/box.cert"
check 0 'spatial_modes certificate is VALID for' check "$sd/box.cert" --problem "$box"
check 0 '"dead_prefixes":2199' check "$sd/box.cert" --json
check 0 '740 feasible modes of 6 contacts' modes "$s/spatial_box_in_corner.json"
# budgets: exit 3 with the coverage
check 3 'node budget of 50 prefixes' modes "$box" --max-nodes 50
check 3 'output budget of 10 modes' modes "$box" --max-modes 10
# options that do not apply, and float
check 2 '--unions' modes "$box" --unions
check 2 '--table2' modes "$box" --table2 printed
check 2 '--snap' modes "$box" --snap 1e-9
check 2 '--arith' modes "$box" --arith float
check 2 'expected 6 comma-separated numbers' stability "$box" --wrench 0,0,0
# the reader: each defect names its field
spatial_case() {  # spatial_case NAME PYTHON-EDIT EXPECTED-TEXT
  python3 -c "import json, sys; c = json.load(open(sys.argv[1])); $2; json.dump(c, open(sys.argv[2], 'w'))" "$box" "$sd/$1.json"
  check 2 "$3" modes "$sd/$1.json"
}
spatial_case mass0 'c["body"]["mass"] = 0' '$.body.mass'
spatial_case inertia 'c["body"]["inertia"][2][2] = "-1"' '$.body.inertia: a positive definite matrix'
spatial_case asym 'c["body"]["inertia"][0][1] = 1' '$.body.inertia: a symmetric'
spatial_case normal0 'c["contacts"][1]["normal"] = [0, 0, 0]' '$.contacts[1].normal: a non-zero normal'
spatial_case outward 'c["contacts"][1]["normal"] = [0, 0, -1]' '$.contacts[1].normal: a normal pointing into the box'
spatial_case off 'c["contacts"][2]["point"] = [1, 1, 5]' '$.contacts[2].point: a point on the body'
spatial_case irrational 'c["contacts"][0]["normal"] = [0, 0, "sqrt(2)"]' '$.contacts[0].normal'
spatial_case frame 'c["contacts"][0]["tangent"] = [[1, 0, 0], [1, 1, 0]]' '$.contacts[0].tangent'
spatial_case three 'c["contacts"][0]["edges"] = [[1, 0], [0, 1], [-1, -1]]' '$.contacts[0].edges: 4 to 13 edges'
spatial_case clockwise 'c["contacts"][0]["edges"] = [[1, 0], [0, -1], [-1, 0], [0, 1]]' '$.contacts[0].edges: edges counterclockwise'
spatial_case twice 'c["contacts"][0]["edges"] = [[1, 0], [0, 1], [-1, 0], [0, -1]] * 2' 'once around the normal'
spatial_case flat 'c["contacts"][0]["edges"] = [[2, 0], [1, 1], [0, 2], [-1, 0], [0, -1]]' 'strictly convex polygon'
spatial_case nomu 'del c["mu"]' '$.contacts[0]: edges, or a friction coefficient mu'
spatial_case both 'c["contacts"][0]["edges"] = [[1, 0], [0, 1], [-1, 0], [0, -1]]; c["contacts"][0]["mu"] = 1' '$.contacts[0].mu'
spatial_case typo 'c["contacts"][0]["Normal"] = [0, 0, 1]' 'Normal'
spatial_case none 'c["contacts"] = []' '$.contacts: at least one contact'
# 3000 contacts at one point: the run stops at the time limit (exit 3; the walk's own stop names the prefixes
# covered, the watchdog's stops an LP of ~9 000 rows, which no deadline interrupts)
python3 -c "import json, sys; json.dump({'kind': 'spatial', 'body': {'mass': 1, 'inertia': [[1, 0, 0], [0, 1, 0], [0, 0, 1]], 'com': [0, 0, 1]}, 'mu': 1, 'contacts': [{'point': [1, 1, 0], 'normal': [0, 0, 1]}] * 3000}, open(sys.argv[1], 'w'))" "$sd/many.json"
check 3 'time limit of 1 s reached' modes "$sd/many.json" --time-limit 1
