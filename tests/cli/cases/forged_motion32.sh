# Forged step certificates of a simulation with several bodies (issue 32), sourced by forged_certificates.sh: each
# step's certificate embeds the step's assembly, from which the checker re-derives the problem and re-verifies
# every contact frame; a changed load, a contact point moved off a boundary or a body-body contact dropped from the
# embedded assembly are INVALID (exit 2), the genuine one VALID.
fm=$work/forged_motion32
rm -rf "$fm" && mkdir -p "$fm"
"$cc" simulate "$s/motion_pushed_row.json" --steps 3 --uniqueness off --certificates "$fm" > /dev/null
check 0 'ucp_solvable certificate is VALID' check "$fm/step-2.json"
# edit IN OUT PYTHON: OUT is the certificate IN with the Python statement applied to its dict `c` (its embedded
# assembly `a`, written back).
edit_assembly() {
  python3 -c "import json, sys; c = json.load(open(sys.argv[1])); a = json.loads(c['assembly']); $3; c['assembly'] = json.dumps(a); json.dump(c, open(sys.argv[2], 'w'))" "$1" "$2"
}
edit_assembly "$fm/step-2.json" "$fm/load.json" 'a["bodies"][1]["load"] = ["0", "-2", "0"]'
check 2 'not the quasistatic problem of the embedded assembly: d[14] is -1' check "$fm/load.json"
edit_assembly "$fm/step-2.json" "$fm/moved.json" \
  'k = [i for i, x in enumerate(a["contacts"]) if x["from"] == {"body": 0}][0]; a["contacts"][k]["point"] = ["3/2", "3/4"]'
check 2 'a point on the boundary of `to`' check "$fm/moved.json"
edit_assembly "$fm/step-2.json" "$fm/dropped.json" 'a["contacts"] = [x for x in a["contacts"] if x["from"] != {"body": 0}]'
check 2 'are not the assembly' check "$fm/dropped.json"
