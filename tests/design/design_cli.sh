#!/usr/bin/env bash
# `contactcert design` end to end: bad input exits 2; every reported placement is re-verified by `stability`,
# its certificates by `check`, its seating pushes by `insert`; the result is the same for np = 1, 2, 3 under
# mpirun (when built with MPI) and after a run killed mid-way is resumed from its checkpoint.
# Usage: design_cli.sh CONTACTCERT REPO_DIR WORK_DIR HAVE_MPI
set -u
cc=$1 repo=$2 work=$3 have_mpi=${4:-OFF}
pentagon=$repo/scenes/bt2002_fig10_pentagon_insert.json
disk=$repo/scenes/bt2002_section7_disk.json
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# Bad input: exit 2 and a message naming the option or the file's field.
expect_2() {
  local text=$1
  shift
  "$cc" design "$@" --out bad > /dev/null 2> err
  local rc=$?
  [ $rc -eq 2 ] || fail "exit $rc (want 2) for: $*"
  grep -qF -- "$text" err || fail "message without '$text' for: $*: $(cat err)"
}
echo '{"candidates": [[1, 0], [2, "1/2"], [1, 1]]}' > off_boundary.json
expect_2 "--candidates: at least 3 candidate points" "$pentagon" --candidates 1 --stable-under 0,-1,0
expect_2 "--candidates: at least 2 candidate points" "$pentagon" --candidates 1 --fixels 2 --stable-under 0,-1,0
expect_2 "--fixels: expected a decimal integer from 2 to 3" "$pentagon" --candidates 8 --fixels 4 --stable-under 0,-1,0
expect_2 "--stable-under: a non-empty wrench set" "$pentagon" --candidates 8 --stable-under ""
expect_2 "--stable-under: a non-empty wrench set" "$pentagon" --candidates 8 --stable-under "cone:"
expect_2 'off_boundary.json: $.candidates[2]: a point on the polygon boundary' "$pentagon" --candidates off_boundary.json --stable-under 0,-1,0

# Re-verification of every reported placement.
args=(design "$pentagon" --candidates 10 --stable-under "0,-1,0" --insertable --rank goal-fraction --top 3 --json --out run)
"$cc" "${args[@]}" > serial.json || fail "serial run exit $?"
count=$(grep -o '"scene_file":"[^"]*"' serial.json | wc -l)
[ "$count" -eq 3 ] || fail "3 placements reported (got $count)"
for k in 1 2 3; do
  "$cc" stability "run/placement_$k.json" --wrench 0,-1,0 | grep -q "verdict: strongly_stable" ||
    fail "placement $k: stability does not confirm strongly_stable"
  "$cc" check "run/placement_${k}_wrench_1.cert.json" | grep -q "is VALID" || fail "placement $k: certificate not VALID"
  "$cc" check "run/placement_${k}_goal.cert.json" --problem "run/placement_$k.json" | grep -q "goal_nonempty certificate is VALID" ||
    fail "placement $k: G_goal certificate not VALID"
  "$cc" insert "run/placement_$k.json" | grep -qE "^ +edge [0-9]+, s in" || fail "placement $k: insert lists no seating push"
done
xmllint --noout run/design.svg 2> /dev/null || [ ! -x "$(command -v xmllint)" ] || fail "design.svg is not valid XML"

# --goal-wrench: G_goal must contain gravity; the placements whose G_goal misses it are counted.
"$cc" design "$pentagon" --candidates 10 --stable-under 0,-1,0 --goal-wrench 0,-1,0 --top 1 --out goal > goal.txt ||
  fail "goal-wrench run exit $?"
grep -qE "goal_misses_wrench [1-9]" goal.txt || fail "no placement rejected for missing the goal wrench"
"$cc" check goal/placement_1_goal_wrench.cert.json | grep -q "is VALID" || fail "goal wrench certificate not VALID"

# --goal-push: some push point's frictionless push must be in G_goal; its certificate names the push point.
"$cc" design "$pentagon" --candidates 10 --goal-push --push-points 12 --top 1 --out push > push.txt ||
  fail "goal-push run exit $?"
grep -qE "no_push_in_goal [1-9]" push.txt || fail "no placement rejected for lacking a seating push"
grep -q '"push"' push/placement_1_goal.cert.json || fail "the G_goal certificate names no push point"
"$cc" check push/placement_1_goal.cert.json | grep -q "holds the frictionless push" || fail "push certificate not VALID"
"$cc" design "$disk" --fixels 2 --candidates 12 --goal-push --top 1 --out disk2 > /dev/null || fail "disk goal-push run exit $?"
"$cc" check disk2/placement_1_goal.cert.json | grep -q "every set of eq. (21)" || fail "2-fixel disk push certificate not VALID"

# A cone of wrenches and two fixels on a disk: each generator's certificate checks.
"$cc" design "$disk" --fixels 2 --candidates 12 --stable-under "cone:0,-1,0;1,-4,0" --top 2 --out cone > cone.txt ||
  fail "cone run exit $?"
grep -q "meets no moving mode's wrench cone" cone.txt || fail "cone run reports no placement"
for c in cone/placement_1_wrench_1.cert.json cone/placement_1_wrench_2.cert.json; do
  "$cc" check "$c" | grep -q "is VALID" || fail "$c not VALID"
done

# The same result for every number of ranks.
if [ "$have_mpi" = "ON" ] && command -v mpirun > /dev/null; then
  for np in 1 2 3; do
    mpirun --oversubscribe --allow-run-as-root -np $np "$cc" "${args[@]}" > "np$np.json" 2> "np$np.err" ||
      fail "mpirun -np $np exit $?: $(tail -3 np$np.err)"
    cmp -s serial.json "np$np.json" || fail "np = $np differs from the serial result"
  done
else
  echo "skipped: MPI runs (built without MPI)"
fi

# Killed mid-way, resumed from the checkpoint: the same output as an uninterrupted run.
ck=(design "$pentagon" --candidates 14 --stable-under "0,-1,0" --insertable --top 3 --json --chunk-size 4 --out ck)
"$cc" "${ck[@]}" > full.json || fail "uninterrupted run exit $?"
"$cc" "${ck[@]}" --checkpoint ck.json > /dev/null &
pid=$!
sleep 1.5
kill -9 $pid 2> /dev/null
wait $pid 2> /dev/null
[ -f ck.json ] || echo "note: killed before the first checkpoint (the resume starts over)"
"$cc" "${ck[@]}" --checkpoint ck.json > resumed.json || fail "resumed run exit $?"
cmp -s full.json resumed.json || fail "the resumed run differs from the uninterrupted one"

[ $failures -eq 0 ] && echo "design_cli: all checks passed"
exit $((failures > 0))
