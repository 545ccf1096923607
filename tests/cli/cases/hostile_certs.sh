# Budgets in the mode tree (issue 29, item 4): the walk is iterative, so 20 000 fixels end 0 or 3 (never a
# stack overflow), the enumerations whose output can be exponential (--unions, --table2 printed) stop at an output
# budget (--max-modes, default 100000) with what they covered, and `modes --certificate` writes only what `check`
# reads. Sourced by hostile_inputs.sh: uses check, $cc, $work, $s.

# bar K Y: K fixels at (2i + 1, Y) under the bar [0, 2K] x [0, 1] (Y = 0: touching; Y < 0: a gap).
bar() {
  awk -v k="$1" -v y="$2" 'BEGIN {
    printf "{\"kind\":\"planar\",\"workpiece\":{\"shape\":{\"type\":\"polygon\",\"vertices\":[[0,0],[%d,0],[%d,1],[0,1]]}},", 2 * k, 2 * k;
    printf "\"mu_s\":\"1/2\",\"mu_k\":\"1/2\",\"fixels\":[";
    for (i = 0; i < k; i++) printf "%s{\"position\":[%d,%s]}", i ? "," : "", 2 * i + 1, y;
    printf "]}\n" }'
}
# disk K: K gap fixels around the unit disk at the rational points ((1 - t^2), 2t) / (1 + t^2), t = 2j/K - 1 (and
# the point (-1, 0) for t = infinity is never used), at distance 2 from the centre.
disk() {
  awk -v k="$1" 'BEGIN {
    printf "{\"kind\":\"planar\",\"workpiece\":{\"shape\":{\"type\":\"disk\",\"center\":[0,0],\"radius\":1}},";
    printf "\"mu_s\":\"1/2\",\"mu_k\":\"1/2\",\"fixels\":[";
    for (j = 0; j < k; j++) {
      p = 2 * j - k; q = k;  # t = p / q in [-1, 1)
      printf "%s{\"position\":[\"%d/%d\",\"%d/%d\"]}", j ? "," : "", 2 * (q * q - p * p), q * q + p * p, 4 * p * q, q * q + p * p;
    }
    printf "]}\n" }'
}

# ---- 20 000 fixels: the walk's depth is a vector (the recursive walk overflowed the stack near 17 000) ----
bar 20000 -1 > "$work/bar20000_gap.json"
check '0|3' '' modes "$work/bar20000_gap.json" --kinematic --time-limit 5
check '0|3' '' modes "$work/bar20000_gap.json" --time-limit 5 --certificate "$work/bar20000_modes.json"
check 3 'covered: 20001 prefixes visited, 1 feasible modes found' modes "$work/bar20000_gap.json" --kinematic --max-nodes 20001

# ---- the output budget of the enumerations that can be exponential ----
bar 16 0 > "$work/block16.json"
check 3 'mode enumeration: output budget of 100000 modes exhausted (covered: ' modes "$work/block16.json" --table2 printed --kinematic
check 3 'output budget of 10 modes exhausted' modes "$s/bt2002_section7_disk.json" --unions --max-modes 10
check 3 'output budget of 9 modes exhausted' modes "$s/bt2002_section7_disk.json" --table2 printed --max-modes 9
check 0 '10 feasible modes' modes "$s/bt2002_section7_disk.json" --max-modes 10
check 0 '"modes":[' modes "$s/bt2002_section7_disk.json" --unions --json
check 2 '--max-modes' modes "$s/bt2002_section7_disk.json" --unions --max-modes 0
check 2 '--max-modes' modes "$s/bt2002_section7_disk.json" --unions --max-modes -3
check 2 '--max-modes' modes "$s/bt2002_section7_disk.json" --unions --max-modes many
check 2 'expected a decimal integer from 1' modes "$s/bt2002_section7_disk.json" --max-modes 0x10
check 2 'expected a decimal integer from 1' modes "$s/bt2002_section7_disk.json" --max-modes 9223372036854775808
# a time limit ends a long exponential walk too
bar 2000 -1 > "$work/bar2000_gap.json"
check 3 'time limit' modes "$work/bar2000_gap.json" --unions --kinematic --time-limit 1
# raised past what `check` reads: the certificate is refused, not written
check 3 'more than the 32 MiB that check reads' modes "$work/block16.json" --table2 printed --kinematic \
  --max-modes 200000 --certificate "$work/block16_modes.json"
check 2 'cannot open the file' check "$work/block16_modes.json"

# ---- 64 gap fixels: the certificate (sparse Motzkin vectors) is one that check reads and accepts ----
disk 64 > "$work/disk64_gap.json"
check 0 '' modes "$work/disk64_gap.json" --kinematic --certificate "$work/disk64_modes.json"
check 0 'modes certificate is VALID' check "$work/disk64_modes.json" --problem "$work/disk64_gap.json"
