# The walk's contact order in assembly_stability certificates (issue 31, sourced by forged_certificates.sh): the
# dead prefixes' letters are in "contact_order" (body by body); the checker places them itself, so an order that is
# not a permutation of the contacts is malformed (exit 2 naming the field) and another permutation, or none, leaves
# the Motzkin vectors proving nothing (INVALID).

fw=$work/forged_wall31
mkdir -p "$fw"
"$cc" assembly "$s/assembly_two_boxes_pushed.json" --certificate "$fw/strong.json" > /dev/null
check 0 'evidence verifies exactly: strongly_stable' check "$fw/strong.json" --problem "$s/assembly_two_boxes_pushed.json"
cases=$((cases + 1))
grep -q '"contact_order": \[' "$fw/strong.json" || { failures=$((failures + 1)); echo "FAIL: no contact_order in $fw/strong.json"; }
edit() { python3 -c "import json, sys; c = json.load(open(sys.argv[1])); $3; json.dump(c, open(sys.argv[2], 'w'))" "$1" "$2"; }
edit "$fw/strong.json" "$fw/no_order.json" 'del c["contact_order"]'
check 2 'certificate is INVALID' check "$fw/no_order.json"
edit "$fw/strong.json" "$fw/swapped.json" 'o = c["contact_order"]; o[0], o[-1] = o[-1], o[0]'
check 2 'certificate is INVALID' check "$fw/swapped.json"
edit "$fw/strong.json" "$fw/twice.json" 'o = c["contact_order"]; o[1] = o[0]'
check 2 'contact_order: each of the' check "$fw/twice.json"
edit "$fw/strong.json" "$fw/short.json" 'c["contact_order"].pop()'
check 2 'contact_order: each of the' check "$fw/short.json"
edit "$fw/strong.json" "$fw/out_of_range.json" 'c["contact_order"][0] = 99'
check 2 'contact_order[0]' check "$fw/out_of_range.json"
edit "$fw/strong.json" "$fw/not_integer.json" 'c["contact_order"][0] = "first"'
check 2 'contact_order[0]' check "$fw/not_integer.json"
