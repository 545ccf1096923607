# `contactcert assembly` (issue 31), sourced by hostile_inputs.sh: the bundled assemblies' verdicts, refusals of
# bad files and options (exit 2 naming the file and field or the option), budgets (exit 3 with what was covered).

asm=$work/assembly
mkdir -p "$asm"
# The bundled assemblies and their hand-derived verdicts (docs/formats.md section 3a, scenes/assembly_*.json).
check 0 '"verdict":"strongly_stable"' assembly "$s/assembly_two_boxes.json" --json
check 0 '"verdict":"strongly_stable"' assembly "$s/assembly_two_boxes_pushed.json" --json
check 0 '"verdict":"unstable"' assembly "$s/assembly_overhang.json" --json
check 0 '"verdict":"strongly_stable"' assembly "$s/assembly_corbel.json" --json
check 0 '"verdict":"strongly_stable"' assembly "$s/assembly_corbel_arch.json" --json
check 0 '"verdict":"weakly_stable"' assembly "$s/assembly_pushed_box_weak.json" --json
check 0 'moves in mode' assembly "$s/assembly_pushed_box_weak.json"
check 0 '"status":"solvable"' assembly --ucp "$s/assembly_pushed_boxes.json" --json
check 0 'com velocity (1, 0)' assembly --ucp "$s/assembly_pushed_boxes.json"
check 0 '"status":"jammed"' assembly --ucp "$s/assembly_pushed_boxes_wall.json" --json
# adaptive runs as verified (scene_arith), exact gives the same verdict
check 0 '"arith":"verified"' assembly "$s/assembly_two_boxes.json" --json --arith adaptive
check 0 '"verdict":"unstable"' assembly "$s/assembly_overhang.json" --json --arith exact
# not an assembly, a float run, options the question would ignore, budgets out of range
check 2 'bt2002_section7_disk.json: $.bodies: an assembly' assembly "$s/bt2002_section7_disk.json"
check 2 '--arith: an assembly' assembly "$s/assembly_two_boxes.json" --arith float
check 2 '--arith: an assembly' assembly --ucp "$s/assembly_pushed_boxes.json" --arith float
check 2 '--max-bases: only --ucp has a Step 3' assembly "$s/assembly_two_boxes.json" --max-bases 10
check 2 '--max-nodes' assembly "$s/assembly_two_boxes.json" --max-nodes 0
check 2 '--max-nodes' assembly "$s/assembly_two_boxes.json" --max-nodes 0x10
# a budget: exit 3 with what was covered, and no certificate
check 3 'budget exceeded: node_limit (covered: 2 prefixes visited' assembly "$s/assembly_two_boxes_pushed.json" --max-nodes 2 --certificate "$asm/none.json"
[ ! -e "$asm/none.json" ] || { failures=$((failures + 1)); echo "FAIL: a certificate was written on a budget"; }
check 3 'budget exceeded: node_limit (covered: 2 prefixes visited' assembly "$s/assembly_two_boxes_pushed.json" --max-nodes 2 --json
# bad assemblies: exit 2 naming the field
printf '{"kind":"planar","bodies":[{"shape":{"type":"polygon","vertices":[[0,0],[2,0],[2,1],[0,1]]}},{"shape":{"type":"polygon","vertices":[[1,0],[3,0],[3,1],[1,1]]}}],"contacts":[{"from":{"body":0},"to":{"body":1},"point":[2,0],"normal":[1,0]}],"mu_s":1}' > "$asm/overlap.json"
check 2 'overlap.json: $.bodies[1]' assembly "$asm/overlap.json"
printf '{"kind":"planar","bodies":[{"shape":{"type":"polygon","vertices":[[0,0],[2,0],[2,1],[0,1]]}}],"obstacles":[{"shape":{"type":"polygon","vertices":[[-5,-1],[5,-1],[5,0],[-5,0]]}}],"contacts":[{"from":{"obstacle":0},"to":{"body":0},"point":[1,"1/2"],"normal":[0,1]}],"mu_s":1}' > "$asm/off.json"
check 2 'off.json: $.contacts[0]' assembly "$asm/off.json"
printf '{"kind":"planar","bodies":[{"shape":{"type":"polygon","vertices":[[0,0],[2,0],[2,1],[0,1]]}}],"obstacles":[{"shape":{"type":"polygon","vertices":[[-5,-1],[5,-1],[5,0],[-5,0]]}}],"contacts":[{"from":{"obstacle":0},"to":{"body":3},"point":[0,0],"normal":[0,1]}],"mu_s":1}' > "$asm/range.json"
check 2 'range.json: $.contacts[0]' assembly "$asm/range.json"
# a finger in a planar assembly is for a quasistatic_scene; a finger that is not the `from` party
sed 's/"kind": "quasistatic_scene"/"kind": "planar"/' "$s/assembly_pushed_boxes.json" > "$asm/planar_finger.json"
check 2 'planar_finger.json: $.fingers' assembly "$asm/planar_finger.json"
# an unwritable certificate or picture names the file
check 2 "$asm/no/dir/c.json" assembly "$s/assembly_two_boxes.json" --certificate "$asm/no/dir/c.json"
check 2 "$asm/no/dir/p.svg" assembly "$s/assembly_two_boxes.json" --svg "$asm/no/dir/p.svg"
# the picture: well-formed, a normal per contact (20) and the resting forces (18: two contacts carry none)
check 0 'picture:' assembly "$s/assembly_corbel_arch.json" --svg "$asm/arch.svg"
if ! xmllint --noout "$asm/arch.svg" 2> /dev/null || [ "$(grep -c 'url(#assembly-normal)' "$asm/arch.svg")" -ne 20 ] ||
  [ "$(grep -c 'url(#assembly-force)' "$asm/arch.svg")" -ne 18 ]; then
  failures=$((failures + 1))
  echo "FAIL: assembly --svg: not well-formed, or not an arrow per contact and per non-zero force"
fi
