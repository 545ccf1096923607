# Hostile inputs, round two (issue 29, items 3, 5 and 7): strict integer and duration options on every command but
# design, options a run would ignore, nesting bombs, pipes without a writer and endless files on every reader, and
# messages free of library internals and huge numbers. Sourced by hostile_inputs.sh (check, run, $cc, $work, $s,
# $m, $ds4, $scene).

# check_clean WANT TEXT ARGS...: as check, and the message holds no library text and no line over 600 characters.
check_clean() {
  check "$@"
  if grep -qE 'json\.exception|parse_error\.|type_error\.|what\(\)' "$work/err" "$work/out" ||
    [ "$(awk '{ if (length($0) > n) n = length($0) } END { print n + 0 }' "$work/err")" -gt 600 ]; then
    failures=$((failures + 1))
    echo "FAIL: contactcert ${*:3}: library text or a huge line in the message"
    echo "  output: $(head -c 400 "$work/err")"
  fi
}

# ---- 1. every integer option of every command but design: decimal digits within its range, nothing else ----
# The options are read from each command's --help (CLI11 prints "INT in [lo, hi]"), so a new one is covered too.
int_options=0
for sub in ucp modes stability cone insert convert check demo bench; do
  for opt in $("$cc" "$sub" --help | grep -oE -- '--[a-z-]+ (UINT|INT)' | cut -d' ' -f1 | sort -u); do
    int_options=$((int_options + 1))
    for bad in 0x10 +3 -1 -0 1e3 1.5 '' ' 5' 5x 18446744073709551616; do
      check_clean 2 "$opt: expected a decimal integer from" "$sub" "$scene" "$opt" "$bad"
    done
    if [ "$opt" != --seed ]; then  # 2^63: one past every signed option's range (a seed takes any 64-bit value)
      check_clean 2 "$opt: expected a decimal integer from" "$sub" "$scene" "$opt" 9223372036854775808
    fi
  done
done
[ "$int_options" -ge 8 ] || { failures=$((failures + 1)); echo "FAIL: only $int_options integer options found in --help"; }
check 2 '--max-nodes: expected a decimal integer from 1 to 9223372036854775807, found "9223372036854775808"' \
  modes "$scene" --max-nodes 9223372036854775808
check 2 '--seed: expected a decimal integer from 0 to 18446744073709551615' ucp "$ds4" --seed 18446744073709551616
check 0 "modes of" modes "$scene" --max-nodes 9223372036854775807
check 3 'budget' modes "$scene" --max-nodes 1
# durations: plain decimal seconds from 0 to 1e7
for bad in +3 ' 5' 5x 0x10 . 1e e5 1e400 -0 inf nan 10000001; do
  check_clean 2 '--time-limit: expected a number of seconds from 0 to 1e7' modes "$scene" --time-limit "$bad"
done
check 0 'modes of' modes "$scene" --time-limit 1e3
check 0 'modes of' modes "$scene" --time-limit .5e1
check 2 '--time-limit' check "$scene" --time-limit 1e8

# ---- 2. an option the run would ignore is refused ----
rm -f "$work/refused_cert.json" "$work/refused.svg"
printf '0,-1,0\n1,1,0\n' > "$work/wrenches.txt"
check 2 '--certificate: --wrenches writes no certificate' stability "$scene" --wrenches "$work/wrenches.txt" --certificate "$work/refused_cert.json"
check 2 '--certificate: --region writes no certificate' stability "$scene" --region --certificate "$work/refused_cert.json"
check 2 '--certificate: --finger writes no certificate' stability "$scene" --finger --certificate "$work/refused_cert.json"
check 2 '--svg: a picture is drawn only with --region or --finger' stability "$scene" --wrench 0,-1,0 --svg "$work/refused.svg"
check 2 '--svg: a picture is drawn only with --region or --finger' stability "$scene" --wrenches "$work/wrenches.txt" --svg "$work/refused.svg"
[ -e "$work/refused_cert.json" ] || [ -e "$work/refused.svg" ] && { failures=$((failures + 1)); echo "FAIL: a refused run wrote a file"; }
check 2 '--margin: the margin is computed exactly' stability "$scene" --wrench 0,-1,0 --margin --arith float
check 2 '--svg: a picture needs --arith exact or verified' cone "$scene" --mode nn --arith float --svg "$work/refused.svg"
check 2 '--certificate: --generate writes a problem and solves none' ucp --generate random --certificate "$work/refused_cert.json"
check 2 '--method: --generate writes a problem and solves none' ucp --generate random --method paper
check 2 '--max-nodes: --generate writes a problem and solves none' ucp --generate reduction --max-nodes 5
check 2 'file: --generate writes a problem and solves none' ucp "$ds4" --generate random
check 2 '--nc: an option of --generate' ucp "$ds4" --nc 3
check 2 '--out: an option of --generate' ucp "$ds4" --out "$work/g.json"
check 2 '--planted: an option of --generate' ucp "$ds4" --planted
check 2 '--rows: an option of --generate reduction' ucp --generate random --rows 3
check 2 '--mu-max: an option of --generate random' ucp --generate reduction --mu-max 1/2
check 0 'certificate' stability "$scene" --wrench 0,-1,0 --certificate "$work/st_ok.json" --margin
for method in paper modified enumerate; do
  check 2 "--max-nodes: the node budget of --method complete's search; --method $method has no search tree" \
    ucp "$ds4" --method "$method" --max-nodes 5
done
check 2 '--max-bases: the basis budget of Step 3; --method enumerate has no Step 3' ucp "$ds4" --method enumerate --max-bases 5
check 0 'solvable' ucp "$s/pang1994_dataset1.json" --method modified --max-bases 5
check 2 '--arith: check verifies exactly' check "$work/st_ok.json" --arith float
check 0 'VALID' check "$work/st_ok.json" --arith exact
check 0 '' ucp --generate reduction --rows 2 --cols 3 --planted --seed 4 --out "$work/g.json"

# ---- 3. nesting deeper than 64 levels is refused before any recursion, on every reader ----
nest() {  # nest NAME DEPTH: an array nested DEPTH levels around 1
  awk -v d="$2" 'BEGIN { for (i = 0; i < d; i++) printf "["; printf "1"; for (i = 0; i < d; i++) printf "]" }' > "$work/$1.json"
}
nest deep 200000
nest depth64 64
nest depth65 65
for cmd in "ucp" "convert" "check" "modes" "insert" "cone --mode n" "stability --region"; do
  # shellcheck disable=SC2086
  check_clean 2 'deep.json: $[0][0][0]' $cmd "$work/deep.json"
  # shellcheck disable=SC2086
  check 2 'nesting deeper than 64 levels' $cmd "$work/deep.json"
done
check 2 'depth64.json: $: expected a cone object' convert "$work/depth64.json"
check 2 'depth65.json: $[0][0]' convert "$work/depth65.json"
awk 'BEGIN { printf "{\"kind\":\"planar\",\"note\":"; for (i = 0; i < 100000; i++) printf "{\"a\":"; printf "1";
  for (i = 0; i < 100000; i++) printf "}"; printf "}" }' > "$work/deep_object.json"
check 2 'deep_object.json: $.note.a.a' cone "$work/deep_object.json" --mode n
"$cc" ucp "$s/pang1994_dataset1.json" --certificate "$work/sol1.json" > /dev/null
sed -z "s/\"x\":/\"x_deep\":$(cat "$work/depth65.json"),\"x\":/" "$work/sol1.json" > "$work/cert_deep.json"
check 2 'cert_deep.json: $.x_deep' check "$work/cert_deep.json"
check 2 'deep.json' check "$work/sol1.json" --problem "$work/deep.json"
"$cc" stability "$scene" --wrench 0,-1,0 --certificate "$work/st.json" > /dev/null
deep_scene=$(awk 'BEGIN { for (i = 0; i < 70; i++) printf "["; for (i = 0; i < 70; i++) printf "]" }')
sed -z "s/\"scene\": \"{/\"scene\": \"{\\\\\"note\\\\\":$deep_scene,/" "$work/st.json" > "$work/st_deep_scene.json"
check 2 'st_deep_scene.json (embedded scene): $.note[0]' check "$work/st_deep_scene.json"
check 2 'deep.json: $[0][0]' stability "$scene" --wrenches "$work/deep.json"

# ---- 4. a named pipe without a writer reads as empty (exit 2) and never blocks; endless files stop at 32 MiB ----
rm -f "$work/fifo"
mkfifo "$work/fifo"
for cmd in "ucp" "convert" "check" "modes" "insert" "cone --mode n" "stability --region"; do
  # shellcheck disable=SC2086
  check 2 'fifo: $: malformed JSON: no JSON text (the input is empty' $cmd "$work/fifo"
  # shellcheck disable=SC2086
  check 2 '/dev/zero: larger than the input limit of 32 MiB' $cmd /dev/zero
done
check 2 'fifo: $: malformed JSON: no JSON text' check "$work/sol1.json" --problem "$work/fifo"
check 2 '/dev/zero: larger than the input limit' check "$work/sol1.json" --problem /dev/zero
check 2 'fifo: at least one wrench' stability "$scene" --wrenches "$work/fifo"
check 2 '/dev/zero: larger than the input limit' stability "$scene" --wrenches /dev/zero
check 2 '-: $: malformed JSON: no JSON text' ucp -
check 2 "$work: is a directory" cone "$work" --mode n
# a pipe with a writer is read as it is written (process substitution)
check 0 'solvable' ucp <(cat "$s/pang1994_dataset1.json")
check 0 "mode 'nn'" cone <(cat "$scene") --mode nn --certificate "$work/cone_pipe.json"
check 0 'VALID' check "$work/cone_pipe.json"

# ---- 5. messages: no library internals, no huge numbers ----
printf '{"kind":"ucp", tru}' > "$work/literal.json"
check_clean 2 'literal.json: $: malformed JSON at byte 19: syntax error while parsing object key - invalid literal' ucp "$work/literal.json"
{ printf '{"kind":"ucp","n":'; head -c 30000 /dev/zero | tr '\0' 'x'; printf '}'; } > "$work/long_token.json"
check_clean 2 'long_token.json: $.n: malformed JSON at byte 19' ucp "$work/long_token.json"
{ printf '{"kind":"ucp","n":"'; head -c 30000 /dev/zero | tr '\0' 'x'; printf '\001"}'; } > "$work/long_string.json"
check_clean 2 'long_string.json' ucp "$work/long_string.json"
sed -z "s/\"format\": 2/\"format\": $(head -c 4000 /dev/zero | tr '\0' 9)/" "$work/sol1.json" > "$work/huge_format.json"
check_clean 2 'expected an integer from 2 to 2, found "9999999999999999999999999999999999999999..." (4000 characters)' \
  check "$work/huge_format.json"
sed -z "s/\"kind\": \"ucp_solvable\"/\"kind\": \"$(head -c 5000 /dev/zero | tr '\0' k)\"/" "$work/sol1.json" > "$work/huge_kind.json"
check_clean 2 '(5000 characters)' check "$work/huge_kind.json"
check_clean 2 '--wrench' stability "$scene" --wrench "$(head -c 5000 /dev/zero | tr '\0' 1)"
check_clean 2 '--time-limit' ucp "$ds4" --time-limit "$(head -c 5000 /dev/zero | tr '\0' 1)"
check_clean 2 '--max-nodes' ucp "$ds4" --max-nodes "$(head -c 5000 /dev/zero | tr '\0' 1)"
# a file name that is not UTF-8 cannot go into the --json output: exit 2 saying so, not an internal error
check_clean 2 'command line: a text given on it (a file name?) is not UTF-8' ucp "$s/pang1994_dataset1.json" --json \
  --certificate "$work/"$'\xff'".json"
check_clean 2 'is not UTF-8' modes "$scene" --json --certificate "$work/"$'\xfe'".json"
check 0 'certificate' modes "$scene" --certificate "$work/"$'\xfe'".json"
# huge strings are quoted as excerpts: a duplicate key, a problem kind
{ printf '{"%s":1,"%s":2}' "$(head -c 3000 /dev/zero | tr '\0' d)" "$(head -c 3000 /dev/zero | tr '\0' d)"; } > "$work/dup_key.json"
check_clean 2 'dup_key.json: $.dddddddddddddddddddddddddddddddddddddddd...: duplicate key "dddddddddddddddddddddddddddddddddddddddd..." (3000 characters)' ucp "$work/dup_key.json"
printf '{"kind":"%s"}' "$(head -c 3000 /dev/zero | tr '\0' q)" > "$work/huge_problem_kind.json"
check_clean 2 'huge_problem_kind.json: $.kind: expected "quasistatic", "quasistatic_scene" or "ucp", found "qqqq' ucp "$work/huge_problem_kind.json"
# a scene that does not suit insertion is named, also when the demo reads it from --scenes
mkdir -p "$work/demo_scenes"
cp "$s/bt2002_section7_disk.json" "$work/demo_scenes/"
cp "$repo/tests/cli/hostile/one_fixel.json" "$work/demo_scenes/bt2002_fig10_pentagon_insert.json"
check_clean 2 'demo_scenes/bt2002_fig10_pentagon_insert.json: $.fixels: insertion needs 2 or 3 fixels' \
  demo --scenes "$work/demo_scenes" --out "$work/demo_out"
