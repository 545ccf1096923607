# Forged certificates of a step's uniqueness (motion_uniqueness, issue 32), sourced by forged_certificates.sh: the
# checker re-derives X, Y, P and h from the embedded problem and re-walks the prefix tree over the 4 letters per
# contact, so a dropped dead prefix, a wrong Farkas vector, a `unique` over a problem with two motions or a swapped
# witness are INVALID (exit 2), a malformed field exit 2 naming it, the genuine ones VALID.
fu=$work/forged_unique32
rm -rf "$fu" && mkdir -p "$fu"
"$cc" simulate "$s/motion_pushed_box.json" --steps 1 --certificates "$fu/tips" > /dev/null
sed 's/"tip": \[0, "3\/2"\]/"tip": [0, 1]/' "$s/motion_pushed_box.json" > "$fu/h1.json"
"$cc" simulate "$fu/h1.json" --steps 1 --certificates "$fu/h1" > /dev/null
"$cc" simulate "$s/motion_pushed_row.json" --steps 1 --certificates "$fu/row" > /dev/null
unique=$fu/tips/step-0-uniqueness.json
two=$fu/h1/step-0-uniqueness.json
check 0 'motion_uniqueness certificate is VALID' check "$unique"
check 0 'two solutions with different q_dot' check "$two"
check 0 'every solution has the same q_dot: ' check "$fu/row/step-0-uniqueness.json"
# edit IN OUT PYTHON: OUT is the certificate IN with the Python statement applied to its dict `c`.
edit_unique() {
  python3 -c "import json, sys; c = json.load(open(sys.argv[1])); $3; json.dump(c, open(sys.argv[2], 'w'))" "$1" "$2"
}
edit_unique "$unique" "$fu/dropped.json" 'del c["dead"][-1]'
check 2 "the prefix tree (one letter per contact, '?' for any): the modes starting with '---'" check "$fu/dropped.json"
edit_unique "$unique" "$fu/farkas.json" 'c["dead"][0]["farkas"] = [str(-int(v)) for v in c["dead"][0]["farkas"]]'
check 2 'the Farkas vector for' check "$fu/farkas.json"
edit_unique "$unique" "$fu/side.json" 'c["dead"][0]["empty"] = "Y" if c["dead"][0]["empty"] == "X" else "X"'
check 2 'the Farkas vector for' check "$fu/side.json"
edit_unique "$unique" "$fu/motion.json" 'c["motion"][0] = "7"'
check 2 'h^T y = ' check "$fu/motion.json"
edit_unique "$unique" "$fu/nobound.json" 'c["bounds"] = []'
check 2 'lies in no bounded mode' check "$fu/nobound.json"
# `unique` over the problem with two motions, its witnesses as the solution modes: the tree does not cover the modes
edit_unique "$two" "$fu/unique_two.json" \
  'w = c.pop("witnesses"); c["verdict"] = "unique"; c["motion"] = w[0]["u"][:3]; c["dead"] = []; c["bounds"] = []; c["solution_modes"] = [{"mode": x["mode"], "x": x["x"], "y": x["y"]} for x in w]'
check 2 "the modes starting with '??s' are neither listed" check "$fu/unique_two.json"
# the witnesses' x swapped: each x is no longer in its mode's face with its u
edit_unique "$two" "$fu/swapped.json" 'w = c["witnesses"]; w[0]["x"], w[1]["x"] = w[1]["x"], w[0]["x"]'
check 2 'is not a solution' check "$fu/swapped.json"
edit_unique "$two" "$fu/same.json" 'c["witnesses"][1] = c["witnesses"][0]'
check 2 'the two witnesses have the same q_dot' check "$fu/same.json"
edit_unique "$unique" "$fu/letter.json" 'c["dead"][0]["prefix"] = "x" + c["dead"][0]["prefix"][1:]'
check 2 '$.dead[0].prefix' check "$fu/letter.json"
edit_unique "$unique" "$fu/verdict.json" 'c["verdict"] = "maybe"'
check 2 '$.verdict' check "$fu/verdict.json"
edit_unique "$unique" "$fu/lowcount.json" 'c["bounds"][0]["low"].pop()'
check 2 '$.bounds[0].low' check "$fu/lowcount.json"
