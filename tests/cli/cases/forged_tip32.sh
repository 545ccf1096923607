# Forged not_unique certificates of the unbounded case (issue 32; tests/cli/uniqueness/free_square.json, a vertex
# and vertex + ray as the two witnesses), sourced by forged_certificates.sh: the checker refuses (exit 2) two
# witnesses with one q_dot, a witness off X's equations and one whose force breaks its mode.
ft=$work/forged_tip32
rm -rf "$ft" && mkdir -p "$ft"
"$cc" ucp "$repo/tests/cli/uniqueness/free_square.json" --all --uniqueness-certificate "$ft/free.json" > /dev/null
check 0 'two solutions with different q_dot' check "$ft/free.json"
# forge_tip32 NAME PYTHON: $ft/NAME.json is the certificate with the Python statement applied to its dict `c`.
forge_tip32() {
  python3 -c "import json, sys; c = json.load(open(sys.argv[1])); $2; json.dump(c, open(sys.argv[2], 'w'))" \
    "$ft/free.json" "$ft/$1.json"
}
forge_tip32 same 'c["witnesses"][1]["u"] = ["0", "0", "0"]; c["witnesses"][1]["x"] = ["0", "0", "0"]'
check 2 'the two witnesses have the same q_dot' check "$ft/same.json"
forge_tip32 off 'c["witnesses"][1]["u"] = ["-2", "0", "0"]'
check 2 'witness 1 (mode s) is not a solution: P u is not B x + h' check "$ft/off.json"
forge_tip32 force 'c["witnesses"][1]["y"] = ["1", "0", "0"]'
check 2 'witness 1 (mode s) is not a solution: y[0] is not 0 in this mode' check "$ft/force.json"
