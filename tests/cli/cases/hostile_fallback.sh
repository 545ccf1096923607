# Huge magnitudes (issue 29, item 6): Data Set 4 with entries of d near 1e306. A float rung's LP basis can be
# singular or infeasible in its own tableau there; the float search goes on without that vertex's edges and its
# verdict is checked exactly, so every arithmetic answers (jammed, exit 0), never "internal error" (exit 1).
for f in "$h"/ds4_d_1e306.json "$h"/ds4_d_1e306_singular.json; do
  for arith in exact verified adaptive; do
    check 0 'jammed' ucp "$f" --arith "$arith"
    # the bilinear methods alone cannot prove jamming: exit 3 "unknown", never 1
    check 3 'unknown' ucp "$f" --arith "$arith" --method paper
    check 3 'unknown' ucp "$f" --arith "$arith" --method modified
  done
  check '0|3' 'ucp' ucp "$f" --arith float
  # the same verdict on the exact and the adaptive path
  "$cc" ucp "$f" --arith exact --json > "$work/fallback_exact.json" 2> /dev/null
  check 0 "$(sed 's/.*"status":"\([a-z]*\)".*/"status":"\1"/' "$work/fallback_exact.json")" ucp "$f" --arith adaptive --json
done
