# contactcert design (issue 29): hostile checkpoints, integer options, budgets before allocation. Sourced by
# hostile_inputs.sh (check, run, $cc, $s, $work). Every corrupted checkpoint ends with exit 2 naming the file and
# the field, also under mpirun -np 2 (every rank ends; none waits), and never changes the result.
dz=$work/design
rm -rf "$dz" && mkdir -p "$dz"
pent=$s/bt2002_fig10_pentagon_insert.json
dargs=(design "$pent" --candidates 8 --stable-under 0,-1,0 --chunk-size 8 --top 3 --out "$dz/out")
# A genuine checkpoint: 32 of the 56 placements (chunks 0-3 of 7) done.
check 3 'placement budget --max-placements reached (covered: 32 of 56' "${dargs[@]}" --checkpoint "$dz/ck.json" \
  --max-placements 32
# ck_edit NAME STATEMENT [redigest]: ck.json with the Python statement applied to c (the parsed file) as NAME.json;
# "redigest" recomputes content_digest (the canonical SHA-256 of $.content, as a forger who knows the format would).
ck_edit() {
  python3 - "$dz/ck.json" "$dz/$1.json" "$2" "${3:-}" << 'PY'
import fractions, hashlib, json, re, sys
c = json.load(open(sys.argv[1]))
exec(sys.argv[3])
NUM = re.compile(r"-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?(/[0-9]*[1-9][0-9]*)?")
def exact(x):
  return str(fractions.Fraction(x))
def canon(v):
  if isinstance(v, dict):
    return "{" + ",".join(json.dumps(k) + ":" + canon(v[k]) for k in sorted(v) if v[k] is not None and k not in ("source", "note", "name", "description")) + "}"
  if isinstance(v, list):
    return "[" + ",".join(canon(x) for x in v) + "]"
  if isinstance(v, bool):
    return "true" if v else "false"
  if isinstance(v, (int, float)):
    return json.dumps(exact(repr(v) if isinstance(v, float) else v))
  if isinstance(v, str) and NUM.fullmatch(v):
    return json.dumps(exact(v))
  return json.dumps(v)
if sys.argv[4] == "redigest":
  c["content_digest"] = hashlib.sha256(canon(c["content"]).encode()).hexdigest()
json.dump(c, open(sys.argv[2], "w"))
PY
}
# resume_refused NAME TEXT: resuming from NAME.json ends with exit 2 and a message naming the file and TEXT.
resume_refused() { check 2 "$dz/$1.json: $2" "${dargs[@]}" --checkpoint "$dz/$1.json"; }

# ---- the genuine checkpoint resumes to the uninterrupted result ----
"$cc" "${dargs[@]}" --json > "$dz/full.json"
cp "$dz/ck.json" "$dz/genuine.json"
run 0 '' /dev/null "$dz/resumed.json" "${dargs[@]}" --json --checkpoint "$dz/genuine.json"
cases=$((cases + 1))
cmp -s "$dz/full.json" "$dz/resumed.json" || {
  failures=$((failures + 1))
  echo "FAIL: design resumed from a checkpoint differs from the uninterrupted run"
}

# ---- edits without a new digest: refused as edited ----
top0='c["content"]["result"]["top"][0]'
ck_edit plain_index "$top0[\"placement\"][2] = 99999"
ck_edit plain_negative "$top0[\"placement\"][0] = -1"
ck_edit plain_int_max "$top0[\"placement\"][2] = 2**31 - 1"
ck_edit plain_figure "$top0[\"figure\"] = \"1000\""
ck_edit plain_lps 'c["content"]["result"]["lps"] += 1'
ck_edit plain_done 'c["content"]["done"] = [[0, 6]]'
for f in plain_index plain_negative plain_int_max plain_figure plain_lps plain_done; do
  resume_refused $f '$.content_digest: the SHA-256 of $.content (the checkpoint was edited or damaged'
done
ck_edit digest_zero 'c["content_digest"] = "0" * 64'
resume_refused digest_zero '$.content_digest: the SHA-256'
ck_edit digest_gone 'del c["content_digest"]'
resume_refused digest_gone '$.content_digest: required field is missing'

# ---- edits with a recomputed digest: refused by the field they break ----
ck_edit index_range "$top0[\"placement\"][2] = 99999" redigest
resume_refused index_range '$.content.result.top[0].placement[2]: expected an integer from 0 to 7, found 99999'
ck_edit index_negative "$top0[\"placement\"][0] = -1" redigest
resume_refused index_negative '$.content.result.top[0].placement[0]: expected an integer from 0 to 7, found -1'
ck_edit index_int_max "$top0[\"placement\"][2] = 2**31 - 1" redigest
resume_refused index_int_max '$.content.result.top[0].placement[2]: expected an integer from 0 to 7, found 2147483647'
ck_edit index_int64 "$top0[\"placement\"][2] = 2**63" redigest
resume_refused index_int64 '$.content.result.top[0].placement[2]: expected an integer from 0 to 7'
ck_edit index_repeated "$top0[\"placement\"][1] = $top0[\"placement\"][0]" redigest
resume_refused index_repeated '$.content.result.top[0].placement[1]: candidate indices in increasing order (distinct, sorted)'
ck_edit index_unsorted "$top0[\"placement\"].reverse()" redigest
resume_refused index_unsorted '$.content.result.top[0].placement[1]: candidate indices in increasing order'
ck_edit index_fraction "$top0[\"placement\"][1] = 1.5" redigest
resume_refused index_fraction '$.content.result.top[0].placement[1]: expected an integer from 0 to 7, found 3/2'
ck_edit index_extra "$top0[\"placement\"].append(7)" redigest
resume_refused index_extra '$.content.result.top[0].placement: 3 candidate indices (--fixels)'
ck_edit index_string "$top0[\"placement\"] = \"0,1,2\"" redigest
resume_refused index_string '$.content.result.top[0].placement: 3 candidate indices'
ck_edit figure_forged "$top0[\"figure\"] = \"1000\"" redigest
resume_refused figure_forged "\$.content.result.top[0].figure: the placement's own figure (re-decided, it differs)"
ck_edit figure_text "$top0[\"figure\"] = \"a lot\"" redigest
resume_refused figure_text '$.content.result.top[0].figure: an exact figure in lowest terms'
ck_edit figure_terms "$top0[\"figure\"] = \"2/4\"" redigest
resume_refused figure_terms '$.content.result.top[0].figure: an exact figure in lowest terms'
ck_edit not_done "$top0[\"placement\"] = [4, 5, 7]" redigest
resume_refused not_done '$.content.result.top[0].placement: a placement of a done chunk (this one is in chunk 6, not done)'
ck_edit top_dropped 'del c["content"]["result"]["top"][0]' redigest
resume_refused top_dropped '$.content.result.top: the best 3 placements'
ck_edit top_twice 'c["content"]["result"]["top"][1] = c["content"]["result"]["top"][0]' redigest
resume_refused top_twice '$.content.result.top[1]: placements best first, each once'
ck_edit top_order 'c["content"]["result"]["top"].reverse()' redigest
resume_refused top_order '$.content.result.top[1]: placements best first, each once'
ck_edit counts_sum 'c["content"]["result"]["by_status"][2] += 1' redigest
resume_refused counts_sum '$.content.result.by_status: counts adding up to the 32 placements of the done chunks'
ck_edit counts_negative 'c["content"]["result"]["by_status"][3] = -4' redigest
resume_refused counts_negative '$.content.result.by_status[3]: expected an integer from 0 to 32'
ck_edit counts_short 'c["content"]["result"]["by_status"].pop()' redigest
resume_refused counts_short '$.content.result.by_status: 8 counts, one per placement status'
ck_edit lps_negative 'c["content"]["result"]["lps"] = -1' redigest
resume_refused lps_negative '$.content.result.lps: expected an integer from 0'
ck_edit done_range 'c["content"]["done"] = [[0, 99]]' redigest
resume_refused done_range '$.content.done[0][1]: expected an integer from 0 to 6, found 99'
ck_edit done_overlap 'c["content"]["done"] = [[0, 3], [2, 3]]' redigest
resume_refused done_overlap '$.content.done[1]: chunk ranges in increasing order, disjoint and not adjacent'
ck_edit done_all 'c["content"]["done"] = [[0, 6]]' redigest
resume_refused done_all '$.content.result.by_status: counts adding up to the 56 placements'
ck_edit chunk_size 'c["content"]["chunk_size"] = 4' redigest
resume_refused chunk_size "\$.content.chunk_size: this run's --chunk-size 8"
ck_edit chunks 'c["content"]["chunks"] = 2**62' redigest
resume_refused chunks "\$.content.chunks: this design's 7 chunks"
ck_edit extra_key 'c["content"]["trust_me"] = True' redigest
resume_refused extra_key '$.content.trust_me: unknown field'
ck_edit kind 'c["kind"] = "ucp_jammed"' redigest
resume_refused kind '$.kind: "design_checkpoint"'
ck_edit other_key 'c["problem"] = "0" * 64' redigest
resume_refused other_key '$.problem: a checkpoint of this design'
# another problem's checkpoint (9 candidates): refused by its problem digest
cp "$dz/ck.json" "$dz/other.json"
check 2 "$dz/other.json: \$.problem: a checkpoint of this design" design "$pent" --candidates 9 --stable-under 0,-1,0 \
  --chunk-size 8 --top 3 --out "$dz/out" --checkpoint "$dz/other.json"

# ---- files that are no checkpoint ----
head -c 120 "$dz/ck.json" > "$dz/truncated.json"
resume_refused truncated '$: malformed JSON at byte 121'
: > "$dz/empty.json"
resume_refused empty ''
echo '[1, 2]' > "$dz/array.json"
resume_refused array '$: a design checkpoint (a JSON object)'
awk 'BEGIN { for (i = 0; i < 200000; i++) printf "["; for (i = 0; i < 200000; i++) printf "]" }' > "$dz/deep.json"
check 2 'deep.json: $[0][0][0]' "${dargs[@]}" --checkpoint "$dz/deep.json"
check 2 'nesting deeper than 64 levels' "${dargs[@]}" --checkpoint "$dz/deep.json"
truncate -s 33M "$dz/huge.json"
resume_refused huge 'larger than the input limit of 32 MiB'
check 2 '/dev/zero: a regular file as the checkpoint' "${dargs[@]}" --checkpoint /dev/zero
mkdir -p "$dz/dir.json"
resume_refused dir 'a regular file as the checkpoint'

# ---- the same refusals under mpirun -np 2: every rank ends with exit 2, none is left waiting ----
if [ -e "$(dirname "$cc")/libcontactcert_mpi.so" ] && command -v mpirun > /dev/null; then
  mpi_refused() {
    local cc_serial=$cc
    cc=mpirun mem=8G
    check 2 "$dz/$1.json: $2" --allow-run-as-root --oversubscribe -np 2 "$cc_serial" "${dargs[@]}" --checkpoint "$dz/$1.json"
    cc=$cc_serial mem=${HOSTILE_MEMORY:-2G}
  }
  mpi_refused index_range '$.content.result.top[0].placement[2]: expected an integer from 0 to 7, found 99999'
  mpi_refused index_int_max '$.content.result.top[0].placement[2]: expected an integer from 0 to 7, found 2147483647'
  mpi_refused figure_forged "\$.content.result.top[0].figure: the placement's own figure"
  mpi_refused plain_index '$.content_digest: the SHA-256 of $.content'
  mpi_refused deep '$[0][0][0]'
  # a budget met by the last chunk: the run is complete, every rank ends with exit 0
  cc_serial=$cc cc=mpirun mem=8G
  check 0 'evaluated 56' --allow-run-as-root --oversubscribe -np 2 "$cc_serial" "${dargs[@]}" --max-placements 56
  cc=$cc_serial mem=${HOSTILE_MEMORY:-2G}
else
  echo "skipped: design checkpoints under mpirun (no MPI build or no mpirun)"
fi

# ---- integer options: decimal only, in range, exit 2 ----
for bad in 0x2 +3 0 -1 1001 ' 5' 5x 1e2 9223372036854775808; do
  check 2 '--top' design "$pent" --candidates 8 --stable-under 0,-1,0 --top "$bad"
done
for bad in 0x3 4 1 +3 3.0; do
  check 2 '--fixels' design "$pent" --candidates 8 --stable-under 0,-1,0 --fixels "$bad"
done
for bad in 0x10 0 -16 9223372036854775807 1000000001 1e3; do
  check 2 '--chunk-size' design "$pent" --candidates 8 --stable-under 0,-1,0 --chunk-size "$bad"
done
for bad in 9223372036854775808 0 -5 0x10 1.5 '+7'; do
  check 2 '--max-placements' design "$pent" --candidates 8 --stable-under 0,-1,0 --max-placements "$bad"
done
for bad in 0 0x10 100001 -3; do
  check 2 '--push-points' design "$pent" --candidates 8 --insertable --push-points "$bad"
done
check 0 'evaluated 56' "${dargs[@]}" --max-placements 56
# the largest chunk is one chunk of all 56 placements (ceil(total / size) without overflow)
check 0 'evaluated 56' design "$pent" --candidates 8 --stable-under 0,-1,0 --chunk-size 1000000000 --out "$dz/big_chunk"
check 0 'evaluated 56' design "$pent" --candidates 8 --stable-under 0,-1,0 --max-placements 9223372036854775807 \
  --out "$dz/max_budget"

# ---- budgets before allocation ----
# C(5000, 3) = 20 820 835 000 placements: chunks are handed out as they are needed, no list of them is built
check 3 'covered: 16 of 20820835000 placements' design "$pent" --candidates 5000 --stable-under 0,-1,0 \
  --max-placements 16 --out "$dz/many"
check 3 'covered: 16 of' design "$pent" --lattice 1/1000 --stable-under 0,-1,0 --max-placements 16 --out "$dz/lattice"
printf '{"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[1000,0],[1000,1000],[0,1000]]}},"fixels":[{"position":[1,0]}],"mu_s":"1/5"}' > "$dz/square.json"
check 2 '--lattice: a coarser pitch: 1/30 makes 119996 candidates, more than the limit of 100000' design \
  "$dz/square.json" --lattice 1/30 --stable-under 0,-1,0
check 3 'scans more than 1000000 lattice lines' design "$dz/square.json" --lattice 1/1000 --stable-under 0,-1,0
awk 'BEGIN { printf "{\"candidates\": ["; for (i = 0; i < 100001; i++) printf "%s[0, 0]", i ? "," : ""; print "]}" }' \
  > "$dz/cands.json"
check 2 "$dz/cands.json: \$.candidates: at most 100000 candidates (found 100001)" design "$pent" --candidates \
  "$dz/cands.json" --stable-under 0,-1,0
check 2 '--candidates: at most 100000 candidates' design "$pent" --candidates 100001 --stable-under 0,-1,0

# ---- figures past the input parser's 4096 digits (a pentagon scaled by 10^2100 + 7: margins of ~8400 digits) ----
# internal figures (chunk results, checkpoints, MPI messages) are never read back through the input parser
python3 -c "
import json
s = 10**2100 + 7
V = [[0, 0], [2 * s, 0], [2 * s, s], [s, 2 * s], [0, 2 * s]]
print(json.dumps({'kind': 'planar', 'workpiece': {'shape': {'type': 'polygon', 'vertices': [[str(x), str(y)] for x, y in V]}},
                  'fixels': [{'position': [str(s), '0']}], 'mu_s': '1/5'}))" > "$dz/huge_pentagon.json"
bargs=(design "$dz/huge_pentagon.json" --candidates 6 --stable-under 0,-1,0 --top 1 --chunk-size 4 --out "$dz/huge_out")
check 0 'best 1:' "${bargs[@]}"
check 3 'covered: 16 of 20 placements' "${bargs[@]}" --max-placements 16 --checkpoint "$dz/huge_ck.json"
cases=$((cases + 1))
grep -qE '"figure":"[0-9]{4097}' "$dz/huge_ck.json" || {
  failures=$((failures + 1))
  echo "FAIL: the checkpoint of the scaled pentagon holds no figure past 4096 digits"
}
check 0 'best 1:' "${bargs[@]}" --checkpoint "$dz/huge_ck.json"
if [ -e "$(dirname "$cc")/libcontactcert_mpi.so" ] && command -v mpirun > /dev/null; then
  cc_serial=$cc cc=mpirun mem=8G
  check 0 'best 1:' --allow-run-as-root --oversubscribe -np 2 "$cc_serial" "${bargs[@]}"
  cc=$cc_serial mem=${HOSTILE_MEMORY:-2G}
fi
