# `ucp --all` (issue 32): the uniqueness of a single instant's motion, decided by simulate's prefix tree, sourced by
# hostile_inputs.sh. Data Set 2 (at its mu and at mu = 1/2 on every contact) is unique with a motion_uniqueness
# certificate `check` verifies; the pushed box tipping at its threshold (the problem simulate's first step solves,
# taken from its uniqueness certificate) has two motions; two bodies in an assembly are unique; the budget exits 3
# with the LPs covered; the options without --all, on the float path or with --generate, and a plain UCP problem,
# exit 2 naming the option.
ua=$work/hostile_all32
rm -rf "$ua" && mkdir -p "$ua"
check 0 'the motion (mode +--): q_dot (-553456349/4026684725, 912621408/575240675' \
  ucp "$s/pang1994_dataset2.json" --all --uniqueness-certificate "$ua/d2.json"
check 0 'motion_uniqueness certificate is VALID' check "$ua/d2.json" --problem "$s/pang1994_dataset2.json"
sed 's/"mu": \["0.1", "0.4", "0.3"\]/"mu": ["1\/2", "1\/2", "1\/2"]/' "$s/pang1994_dataset2.json" > "$ua/d2_half.json"
check 0 '  uniqueness: unique' ucp "$ua/d2_half.json" --all --certificate "$ua/d2_half_ucp.json" \
  --uniqueness-certificate "$ua/d2_half.json.u"
check 0 'every solution has the same q_dot' check "$ua/d2_half.json.u"
check 0 'ucp_solvable certificate is VALID' check "$ua/d2_half_ucp.json"
sed 's/"tip": \[0, "3\/2"\]/"tip": [0, 1]/' "$s/motion_pushed_box.json" > "$ua/h1.json"
"$cc" simulate "$ua/h1.json" --steps 1 --certificates "$ua/h1" > /dev/null
python3 -c "import json, sys; json.dump(json.load(open(sys.argv[1]))['problem'], open(sys.argv[2], 'w'))" \
  "$ua/h1/step-0-uniqueness.json" "$ua/two.json"
check 0 'motion 2 (mode sr+): q_dot (0, 2, -1)' ucp "$ua/two.json" --all --uniqueness-certificate "$ua/two_u.json"
check 0 'two solutions with different q_dot' check "$ua/two_u.json" --problem "$ua/two.json"
check 0 'not_unique' ucp "$ua/two.json" --all --json
check 0 'the motion (mode rrrr): body 0 (0, 0, 0), body 1 (0, 0, 0)' \
  ucp "$s/assembly_two_boxes_pushed.json" --all --uniqueness-certificate "$ua/asm_u.json"
check 0 'motion_uniqueness certificate is VALID' check "$ua/asm_u.json"
check 3 "the uniqueness prefix tree's LP budget (--max-modes 5) ran out (covered: " \
  ucp "$s/assembly_pushed_boxes.json" --all --max-modes 5
check 3 "(--max-modes 5) ran out" ucp "$ua/two.json" --all --max-modes 5 --json
check 2 "--max-modes: the budget of --all's uniqueness question; add --all" ucp "$ua/two.json" --max-modes 5
check 2 '--uniqueness-certificate: the certificate of --all' ucp "$ua/two.json" --uniqueness-certificate "$ua/x.json"
check 2 '--all: the uniqueness question is decided exactly' ucp "$ua/two.json" --all --arith float
check 2 '--generate writes a problem and solves none' ucp --generate random --all
"$cc" ucp --generate reduction --out "$ua/plain.json"
check 2 '--all asks whether the body velocity q_dot is unique' ucp "$ua/plain.json" --all
