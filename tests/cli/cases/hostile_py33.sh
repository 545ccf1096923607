# demo and bench as queries (issue 33): their --time-limit stops the run between units with exit 3 and what was
# covered; demo --json is one object; bad options are refused before anything runs.
check 3 'covered: 0 instances' bench --suite paper --quick --out "$work/bench_py33" --time-limit 1e-9
check 3 'demo: time limit of 1e-09 s reached' demo --out "$work/demo_py33" --time-limit 1e-9
check 0 '"command":"demo"' demo --scenes "$work/demo_py33" --out "$work/demo_py33" --json
check 2 '--rungs: a list of known rungs: unknown rung ""' bench --rungs float,,exact --out "$work/bench_py33"
check 2 'the scenes folder does not exist' demo --scenes "$work/no such folder" --json
