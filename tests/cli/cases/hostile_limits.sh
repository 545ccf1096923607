# A query's limit is a status that every command reports the same way (issue 30 item 4; cli/command.h
# report_limit): exit 3, "budget exceeded: WHAT (covered: ...)" on stderr and nothing on stdout, --json or not.
# Sourced by hostile_inputs.sh: uses check, run, $cc, $work, $s, $repo.

# A time limit of 1e-9 s has passed before the first unit of work: nothing covered, whatever the machine's load.
disk="$s/bt2002_section7_disk.json"
tree='budget exceeded: mode enumeration: time limit of 1e-09 s reached (covered: 0 prefixes visited, 0 feasible'
printf '0,-1,0\n1,-1,0\n' > "$work/limits_wrenches.txt"
check 3 "$tree" stability "$disk" --wrenches "$work/limits_wrenches.txt" --time-limit 1e-9
check 3 "$tree" stability "$disk" --wrench 0,-1,0 --margin --time-limit 1e-9
check 3 "$tree" stability "$disk" --wrench 0,-1,0 --arith float --time-limit 1e-9
check 3 "$tree" stability "$disk" --finger --time-limit 1e-9
check 3 "$tree" modes "$disk" --time-limit 1e-9
check 3 'budget exceeded: double description: time limit of 1e-09 s reached (covered: 0 of 4 rows paired)' \
  convert "$repo/tests/cli/convert/paper_span.json" --time-limit 1e-9
check 3 'budget exceeded: double description: time limit of 1e-09 s reached (covered: 0 of 3 rows paired)' \
  cone "$s/bt2002_fig4a_lla.json" --mode lla --time-limit 1e-9 --arith float
# --json: the limit is on stderr only; stdout stays empty (no half-written object)
for args in "modes $disk --max-nodes 1" "stability $disk --region --time-limit 1e-9"; do
  read -r -a argv <<< "$args"
  run 3 'budget exceeded: mode enumeration: ' /dev/null "$work/limits_stdout" "${argv[@]}" --json
  if [ -s "$work/limits_stdout" ]; then
    failures=$((failures + 1))
    echo "FAIL: contactcert $args --json: stdout not empty on a limit: $(head -c 200 "$work/limits_stdout")"
  fi
done
# a budget met while making the candidates, before design's search: the same report
check 3 'budget exceeded: ' design "$s/design_ratchet_pawl.json" --lattice 1/10000000 --stable-under 0,-1,0 \
  --out "$work/limits_design"
