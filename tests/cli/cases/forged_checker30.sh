# The checker's own model (issue 30): an `assembly --ucp` certificate embeds the assembly, and its checker derives
# P, Jn, Jt, d and mu from the assembly's geometry (checker/assembly_ucp_check.h) instead of trusting the embedded
# matrices; a certificate whose problem is not its assembly's is INVALID, naming the entry. Sourced by
# forged_certificates.sh ($cc, $work, $s, check, forge, digest).
asol=$work/asm_solvable.json
ajam=$work/asm_jammed.json
"$cc" assembly "$s/assembly_pushed_boxes.json" --ucp --certificate "$asol" > /dev/null
"$cc" assembly "$s/assembly_pushed_boxes_wall.json" --ucp --certificate "$ajam" > /dev/null
check 0 'ucp_solvable certificate is VALID' check "$asol"
check 0 'ucp_jammed certificate is VALID' check "$ajam"
check 0 '"valid":true' check "$ajam" --json
# the assembly changed, the problem (and its digest) kept: the matrices disagree with the geometry
forge asm_mu 's/\\"mu\\": \\"3\/10\\"/\\"mu\\": \\"1\/10\\"/' "$asol"
check 2 "is not the quasistatic problem of the embedded assembly: mu[0] is 3/10, the assembly's 1/10" check "$work/asm_mu.json"
forge asm_push 's/\\"velocity\\": \[1, 0\]/\\"velocity\\": [2, 0]/' "$asol"
check 2 "theta_dot[0] is 1, the assembly's 2" check "$work/asm_push.json"
forge asm_gravity 's/\\"gravity\\": \[0, -1\]/\\"gravity\\": [0, -2]/' "$ajam"
check 2 'is not the quasistatic problem of the embedded assembly: d[' check "$work/asm_gravity.json"
# the problem changed and re-digested, the assembly kept: refused before any Farkas vector is read
forge asm_p 's/"P":\[\["0","1"/"P":[["0","2"/' "$ajam"
sed -z "s/\"problem_sha256\":\"[0-9a-f]*\"/\"problem_sha256\":\"$(digest "$work/asm_p.json")\"/" \
  "$work/asm_p.json" > "$work/asm_p_redigested.json"
check 2 "is not the quasistatic problem of the embedded assembly: P[0][1] is 2, the assembly's 1" check "$work/asm_p_redigested.json"
# an embedded assembly that is not one: exit 2 naming it
forge asm_not_json 's/"assembly":"{/"assembly":"{{/' "$ajam"
check 2 '(embedded assembly)' check "$work/asm_not_json.json"
forge asm_no_bodies 's/\\"bodies\\"/\\"bodies_\\"/' "$asol"
check 2 'embedded assembly' check "$work/asm_no_bodies.json"
# a finger's contact moved off the body: its frame is refused before any matrix
forge asm_finger 's/\\"position\\": \[0, \\"1\/2\\"\]/\\"position\\": [\\"1\/2\\", \\"1\/2\\"]/' "$asol"
check 2 'embedded assembly' check "$work/asm_finger.json"
