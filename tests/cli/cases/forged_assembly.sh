# Forged assembly_stability certificates (issue 31), sourced by forged_certificates.sh: the checker
# (checker/assembly_check.h) rebuilds every system from the embedded assembly, so a dropped branch of the
# walk, a wrong vector, a relabelled body, a changed verdict or scene are INVALID (exit 2) and the genuine ones VALID.

fa=$work/forged_assembly
mkdir -p "$fa"
"$cc" assembly "$s/assembly_two_boxes_pushed.json" --certificate "$fa/strong.json" > /dev/null
"$cc" assembly "$s/assembly_overhang.json" --certificate "$fa/unstable.json" > /dev/null
"$cc" assembly "$s/assembly_pushed_box_weak.json" --certificate "$fa/weak.json" > /dev/null
check 0 'assembly_stability certificate is VALID for' check "$fa/strong.json" --problem "$s/assembly_two_boxes_pushed.json"
check 0 'evidence verifies exactly: unstable' check "$fa/unstable.json"
check 0 'evidence verifies exactly: weakly_stable' check "$fa/weak.json"
check 0 '"dead_prefixes":22' check "$fa/strong.json" --json
# edit IN OUT PYTHON: OUT is the certificate IN with the Python statement applied to its dict `c`.
edit() { python3 -c "import json, sys; c = json.load(open(sys.argv[1])); $3; json.dump(c, open(sys.argv[2], 'w'))" "$1" "$2"; }
# a dropped branch: one dead prefix left out, so some modes are not covered
edit "$fa/strong.json" "$fa/dropped.json" 'del c["dead"][3]'
check 2 'no dead prefix covers the modes that start' check "$fa/dropped.json"
# a branch listed twice
edit "$fa/strong.json" "$fa/twice.json" 'c["dead"].append(c["dead"][0])'
check 2 'is listed twice' check "$fa/twice.json"
# a wrong vector: one weight of a dead prefix's Motzkin vector changed (still primitive)
edit "$fa/strong.json" "$fa/wrong_vector.json" 'm = c["dead"][0]["motzkin"]; m[0][1] = str(int(m[0][1]) + 1) if int(m[0][1]) + 1 else "1"'
check 2 'its certificate does not prove the prefix' check "$fa/wrong_vector.json"
edit "$fa/unstable.json" "$fa/wrong_farkas.json" 'm = c["resting"]["motzkin"]; m[-1][1] = str(-int(m[-1][1]))'
check 2 'the resting certificate does not prove' check "$fa/wrong_farkas.json"
# a relabelled body: the moving witness's accelerations given to the other body
edit "$fa/unstable.json" "$fa/relabelled.json" 'a = c["moving"]["acceleration"]; c["moving"]["acceleration"] = a[3:] + a[:3]'
check 2 'moving: ' check "$fa/relabelled.json"
# the bodies relabelled in the embedded scene (the same boxes and contacts, digest redone): the evidence's
# Newton-Euler rows and accelerations are body by body, so the vectors no longer prove their prefixes dead
edit "$fa/strong.json" "$fa/scene_relabelled.json" 's = json.loads(c["scene"]); s["bodies"].reverse()
for x in s["contacts"]:
  for side in ("from", "to"):
    if "body" in x[side]: x[side]["body"] = 1 - x[side]["body"]
c["scene"] = json.dumps(s)'
sed -i "s/\"problem_sha256\": *\"[0-9a-f]*\"/\"problem_sha256\": \"$(digest "$fa/scene_relabelled.json")\"/" "$fa/scene_relabelled.json"
check 2 'certificate is INVALID' check "$fa/scene_relabelled.json"
# the scene changed without a new digest; the verdict changed; an unknown key; a prefix with a foreign letter
edit "$fa/strong.json" "$fa/scene_changed.json" 'c["scene"] = c["scene"].replace("1/2", "1/3")'
check 2 'problem_sha256 is not the digest' check "$fa/scene_changed.json"
edit "$fa/strong.json" "$fa/verdict.json" 'c["verdict"] = "weakly_stable"'
check 2 'weakly stable without a moving solution' check "$fa/verdict.json"
edit "$fa/weak.json" "$fa/weak_as_strong.json" 'c["verdict"] = "strongly_stable"'
check 2 'strongly stable with a moving solution' check "$fa/weak_as_strong.json"
edit "$fa/strong.json" "$fa/extra_key.json" 'c["note"] = "x"'
check 2 'unknown field' check "$fa/extra_key.json"
edit "$fa/strong.json" "$fa/letter.json" 'c["dead"][0]["prefix"] = "a"'
check 2 '$.dead[0].prefix: a prefix' check "$fa/letter.json"
# about another problem
check 2 'is about another problem than' check "$fa/strong.json" --problem "$s/assembly_two_boxes.json"
