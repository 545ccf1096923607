# `stability`, `ucp` and `modes` on an assembly file (issue 31), sourced by hostile_inputs.sh: the same answer as
# `assembly FILE [--ucp]` (the query layer reads the file's kind), the modes of N bodies, and the options that do
# not apply to an assembly refused (exit 2 naming the option).

ad=$work/assembly_dispatch
mkdir -p "$ad"
# the same bytes as `assembly` (JSON and text), for each verdict and for the quasistatic problem
for f in assembly_two_boxes assembly_overhang assembly_pushed_box_weak; do
  "$cc" assembly "$s/$f.json" --json > "$ad/$f.assembly.json"
  check 0 "$(head -c 60 "$ad/$f.assembly.json")" stability "$s/$f.json" --json
  "$cc" stability "$s/$f.json" --json > "$ad/$f.stability.json"
  cases=$((cases + 1))
  cmp -s "$ad/$f.assembly.json" "$ad/$f.stability.json" || { failures=$((failures + 1)); echo "FAIL: stability $f --json differs from assembly"; }
done
check 0 'verdict: strongly_stable' stability "$s/assembly_two_boxes.json"
check 0 '"status":"jammed"' ucp "$s/assembly_pushed_boxes_wall.json" --json
check 0 'com velocity (1, 0)' ucp "$s/assembly_pushed_boxes.json"
"$cc" assembly --ucp "$s/assembly_pushed_boxes.json" --json > "$ad/ucp.assembly.json"
"$cc" ucp "$s/assembly_pushed_boxes.json" --json > "$ad/ucp.ucp.json"
cases=$((cases + 1))
cmp -s "$ad/ucp.assembly.json" "$ad/ucp.ucp.json" || { failures=$((failures + 1)); echo "FAIL: ucp ASSEMBLY --json differs from assembly --ucp"; }
# certificates through the other commands, checked
check 0 '"verdict":"unstable"' stability "$s/assembly_overhang.json" --json --certificate "$ad/overhang.cert"
check 0 'assembly_stability certificate is VALID' check "$ad/overhang.cert" --problem "$s/assembly_overhang.json"
check 0 '"status":"solvable"' ucp "$s/assembly_pushed_boxes.json" --json --certificate "$ad/ucp.cert"
check 0 'ucp_solvable certificate is VALID' check "$ad/ucp.cert"
# the modes of N bodies, with their certificate
check 0 '100 feasible modes of 4 contacts between 2 bodies' modes "$s/assembly_two_boxes.json"
check 0 '"dead_prefixes":66' modes "$s/assembly_two_boxes.json" --json --certificate "$ad/modes.cert"
check 0 'assembly_modes certificate is VALID' check "$ad/modes.cert" --problem "$s/assembly_two_boxes.json"
check 0 '"modes":100' check "$ad/modes.cert" --json
check 3 'node budget of 5 prefixes' modes "$s/assembly_two_boxes.json" --max-nodes 5
check 3 'output budget of 3 modes' modes "$s/assembly_two_boxes.json" --max-modes 3
check 2 '--arith: modes are enumerated exactly' modes "$s/assembly_two_boxes.json" --arith float
# options that do not apply to an assembly
for opt in "--wrench 0,-1,0" "--wrenches $ad/none.json" "--region" "--finger"; do
  check 2 "${opt%% *}: an assembly's loads are in its file" stability "$s/assembly_two_boxes.json" $opt
done
check 2 '--wrench: an assembly' stability "$s/assembly_two_boxes.json" --wrench 0,-1,0 --margin
check 2 '--snap: an assembly (a file with bodies) is read exactly' stability "$s/assembly_two_boxes.json" --snap 1e-9
check 2 '--snap: an assembly' modes "$s/assembly_two_boxes.json" --snap 1e-9
check 2 '--unions: an assembly' modes "$s/assembly_two_boxes.json" --unions
check 2 '--table2: an assembly' modes "$s/assembly_two_boxes.json" --table2 printed
check 2 '--method: an assembly' ucp "$s/assembly_pushed_boxes.json" --method paper
check 2 '--seed: the complete search on an assembly' ucp "$s/assembly_pushed_boxes.json" --seed 2
check 2 '--arith: an assembly' stability "$s/assembly_two_boxes.json" --arith float
# a bad assembly is still named by its field through every command
printf '{"kind": "planar", "bodies": [], "contacts": []}' > "$ad/empty.json"
check 2 'empty.json: $.bodies' stability "$ad/empty.json"
check 2 'empty.json: $.bodies' modes "$ad/empty.json"
