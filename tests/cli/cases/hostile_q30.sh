# Issue 30, sourced by hostile_inputs.sh: a run that stops on a limit reports that limit alone (exit 3, stderr
# "budget exceeded: WHAT (covered: ...)", nothing on stdout, text or --json), in ucp, assembly and assembly --ucp;
# the bilinear method's own `unknown` (it cannot prove jamming) is an answer, not a limit.

# limit_only TEXT ARGS...: exit 3, TEXT in the message, and no answer on stdout
limit_only() {
  local text=$1
  shift
  check 3 "$text" "$@"
  [ ! -s "$work/out" ] || { failures=$((failures + 1)); echo "FAIL: an answer printed beside the limit: $*"; }
}
q30_ds4=$s/pang1994_dataset4.json
limit_only 'budget exceeded: node budget of 2 exhausted (covered: 2 nodes,' ucp "$q30_ds4" --max-nodes 2
limit_only 'budget exceeded: node budget of 2 exhausted (covered: 2 nodes,' ucp "$q30_ds4" --max-nodes 2 --json
limit_only 'budget exceeded: node budget of 1 exhausted' ucp "$q30_ds4" --max-nodes 1 --arith exact --json
limit_only 'budget exceeded: time limit of 1e-09 s reached' ucp "$q30_ds4" --time-limit 1e-9 --method paper
limit_only 'budget exceeded: node_limit (covered: 1 prefixes visited' assembly "$s/assembly_pushed_box_weak.json" --max-nodes 1
limit_only 'budget exceeded: node_limit (covered: 1 prefixes visited' assembly "$s/assembly_pushed_box_weak.json" --max-nodes 1 --json
limit_only 'budget exceeded: time_limit (covered: ' stability "$s/assembly_pushed_box_weak.json" --time-limit 1e-9 --json
limit_only 'budget exceeded: time limit of 1e-09 s reached' assembly "$s/assembly_pushed_boxes_wall.json" --ucp --time-limit 1e-9 --json
limit_only 'budget exceeded: time limit of 1e-09 s reached' ucp "$s/assembly_pushed_boxes_wall.json" --time-limit 1e-9
# the paper method's stationary pair: an answer with status unknown (exit 3), on stdout
check 3 '"status":"unknown","reason":"stationary pair' ucp "$q30_ds4" --method paper --json
# insert honours --time-limit through the query's deadline (not only the watchdog): a tiny limit on a long sweep
# stops at once, exit 3, naming what it computed; no picture written
q30_mus=$(python3 -c "print(','.join(f'{i}/100' for i in range(1, 201)))")
limit_only 'insert '"$s"'/bt2002_fig10_pentagon_insert.json: time limit of 1e-09 s reached (covered: nothing' \
  insert "$s/bt2002_fig10_pentagon_insert.json" --sweep-mu "$q30_mus" --time-limit 1e-9 --svg "$work/q30_insert.svg"
[ ! -e "$work/q30_insert.svg" ] || { failures=$((failures + 1)); echo "FAIL: insert wrote its picture past the limit"; }
limit_only 'time limit of 1e-09 s reached' insert "$s/bt2002_section7_disk.json" --time-limit 1e-9 --json
