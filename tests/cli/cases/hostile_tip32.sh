# Session 15's motion items (issue 32), sourced by hostile_inputs.sh: the budget of the uniqueness prefix tree names
# the command the user ran (`assembly FILE --ucp --all` was named `ucp FILE`).
check 3 "budget exceeded: assembly $s/assembly_pushed_boxes.json: the uniqueness prefix tree's LP budget" \
  assembly "$s/assembly_pushed_boxes.json" --ucp --all --max-modes 1
check 3 "budget exceeded: ucp $s/assembly_pushed_boxes.json: the uniqueness prefix tree's LP budget" \
  ucp "$s/assembly_pushed_boxes.json" --all --max-modes 1
# docs/papers.md states Data Set 1's three motions as `ucp --all` prints them: each line must be in the output.
d1_lines=$(grep -cE '^ +motion [123] \(mode [-+rs]{3}\): q_dot \(' "$repo/docs/papers.md")
if [ "$d1_lines" != 3 ]; then
  failures=$((failures + 1))
  echo "FAIL: docs/papers.md states $d1_lines of Data Set 1's three motions"
fi
while IFS= read -r line; do
  check 0 "$(sed -E 's/^ +//' <<< "$line")" ucp "$s/pang1994_dataset1.json" --all
done < <(grep -E '^ +motion [123] \(mode [-+rs]{3}\): q_dot \(' "$repo/docs/papers.md")
check 0 'motion_uniqueness certificate is VALID' check "$(
  "$cc" ucp "$s/pang1994_dataset1.json" --all --uniqueness-certificate "$work/tip32_d1.json" > /dev/null
  echo "$work/tip32_d1.json"
)"
# The unbounded not_unique case (a vertex and vertex + ray): a square on one fixel with no load may leave it at any
# speed; text and --json say so, and its certificate (two witnesses) checks.
free=$repo/tests/cli/uniqueness/free_square.json
check 0 'uniqueness: not unique (4 solution modes, 38 LPs, a q_dot component unbounded)' ucp "$free" --all
check 0 '"uniqueness":{"status":"not_unique","motions":[["0","0","0"]],"modes":["s"],"solution_modes":["s","r","+","-"],"unbounded":true' \
  ucp "$free" --all --json
check 0 'two solutions with different q_dot' check "$(
  "$cc" ucp "$free" --all --uniqueness-certificate "$work/tip32_free.json" > /dev/null
  echo "$work/tip32_free.json"
)"
