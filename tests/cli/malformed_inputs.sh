#!/usr/bin/env bash
# Table of malformed inputs (issue 7, point 3): every case must end with the expected exit code (2 for bad
# input, 3 for an exhausted budget) and a one-line message naming the file, the JSON path or the option.
# A crash (signal), exit 1 or a message without the expected text fails the case.
# Usage: malformed_inputs.sh CONTACTCERT REPO_DIR WORK_DIR
set -u
cc=$1
repo=$2
work=$3
m=$repo/tests/cli/malformed
s=$repo/scenes
mkdir -p "$work"
# Generated inputs: binary garbage, an empty file, absurd nesting, a directory, a missing file.
printf '\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR\xff\xfe\x01\x02garbage\x00' > "$work/garbage.bin"
: > "$work/empty.json"
head -c 100000 /dev/zero | tr '\0' '[' > "$work/deep_array.json"
{ for _ in $(seq 2000); do printf '{"a":'; done; } > "$work/deep_object.json"
mkdir -p "$work/a_directory.json"
missing=$work/does_not_exist.json
rm -f "$missing"

failures=0
cases=0
# check EXIT EXPECTED_TEXT ARGS... : runs contactcert ARGS and checks the exit code and that the message
# (stderr; for exit 3 stdout or stderr) contains EXPECTED_TEXT literally.
check() {
  local want=$1 text=$2
  shift 2
  cases=$((cases + 1))
  "$cc" "$@" > "$work/out" 2> "$work/err" < /dev/null
  local rc=$?
  local msg
  msg=$(cat "$work/err")
  [ "$want" -eq 3 ] && msg="$(cat "$work/out") $msg"
  local why=""
  if [ "$rc" -ge 128 ]; then
    why="killed by signal $((rc - 128))"
  elif [ "$rc" -ne "$want" ]; then
    why="exit $rc, expected $want"
  elif ! grep -qF -- "$text" <<< "$msg"; then
    why="message does not contain: $text"
  elif [ "$want" -eq 2 ] && [ "$(wc -l < "$work/err")" -ne 1 ]; then
    why="expected a one-line message on stderr"
  fi
  if [ -n "$why" ]; then
    failures=$((failures + 1))
    echo "FAIL: contactcert $*: $why"
    echo "  stderr: $(head -c 400 "$work/err")"
  fi
}

# ---- quasistatic problems (SPEC section 2): contactcert ucp ----
check 0 "" ucp "$m/ucp_valid.json"
check 2 'ucp_truncated.json: $: malformed JSON' ucp "$m/ucp_truncated.json"
check 2 'garbage.bin: $: malformed JSON at byte 1' ucp "$work/garbage.bin"
check 2 'empty.json: $: malformed JSON' ucp "$work/empty.json"
check 2 'deep_array.json: $[0][0]' ucp "$work/deep_array.json"
check 2 'nesting deeper than 64 levels' ucp "$work/deep_array.json"
check 2 'deep_object.json: $.a.a' ucp "$work/deep_object.json"
check 2 'a_directory.json: is a directory' ucp "$work/a_directory.json"
check 2 'does_not_exist.json: cannot open the file' ucp "$missing"
check 2 'ucp_missing_mu.json: $.mu: required field is missing' ucp "$m/ucp_missing_mu.json"
check 2 'ucp_extra_field.json: $.mu_S: unknown field' ucp "$m/ucp_extra_field.json"
check 2 'ucp_duplicate_key.json: $.mu: duplicate key' ucp "$m/ucp_duplicate_key.json"
check 2 'ucp_top_array.json: $: expected an object, found an array' ucp "$m/ucp_top_array.json"
check 2 'ucp_ragged_P.json: $.P[1]: expected a row of 1 numbers, found 2' ucp "$m/ucp_ragged_P.json"
check 2 'ucp_P_rows.json: $.P: expected 2 rows, found 3' ucp "$m/ucp_P_rows.json"
check 2 'ucp_mu_length.json: $.mu: expected an array of 1 numbers, found 2' ucp "$m/ucp_mu_length.json"
check 2 'ucp_not_number.json: $.mu[0]: "half" is not an exact number' ucp "$m/ucp_not_number.json"
check 2 'ucp_mu_object.json: $.mu[0]: expected a number or a numeric string, found an object' ucp "$m/ucp_mu_object.json"
check 2 'ucp_nc_fraction.json: $.nc: expected an integer from 1' ucp "$m/ucp_nc_fraction.json"
check 2 'ucp_zero_den.json: $.mu[0]: "1/0" is not an exact number (zero denominator' ucp "$m/ucp_zero_den.json"
check 2 'ucp_nan_string.json: $.mu[0]: "NaN" is not an exact number' ucp "$m/ucp_nan_string.json"
check 2 'ucp_inf_string.json: $.mu[0]: "inf" is not an exact number' ucp "$m/ucp_inf_string.json"
check 2 'ucp_minus_infinity_string.json: $.mu[0]: "-Infinity"' ucp "$m/ucp_minus_infinity_string.json"
check 2 'ucp_bare_nan.json: $.mu[0]: malformed JSON' ucp "$m/ucp_bare_nan.json"
check 2 'ucp_bare_infinity.json: $.mu[0]: malformed JSON' ucp "$m/ucp_bare_infinity.json"
check 2 'ucp_negative_mu.json: $.mu[0]: expected a friction coefficient >= 0' ucp "$m/ucp_negative_mu.json"
check 2 'ucp_huge_exponent_string.json: $.mu[0]: "1e99999" is not an exact number (exponent out of range' ucp "$m/ucp_huge_exponent_string.json"
check 2 'ucp_huge_exponent_bare.json: $.mu[0]: "1e99999" is not an exact number (exponent out of range' ucp "$m/ucp_huge_exponent_bare.json"
check 2 'ucp_huge_negative_exponent.json: $.mu[0]: "1e-99999" is not an exact number (exponent out of range' ucp "$m/ucp_huge_negative_exponent.json"
check 2 'ucp_wrong_kind.json: $.kind: expected "quasistatic", "quasistatic_scene" or "ucp", found "quasi"' ucp "$m/ucp_wrong_kind.json"
check 2 'ucp_d_block.json: $.d[0]: expected 0' ucp "$m/ucp_d_block.json"
check 2 'ucp_alpha_range.json: $.alpha[0]: expected an integer from 0 to 0, found 3' ucp "$m/ucp_alpha_range.json"
check 2 'ucp_form_X_ragged.json: $.X.A[1]: expected a row of 2 numbers' ucp "$m/ucp_form_X_ragged.json"
check 2 'ucp_form_b_length.json: $.X.b: expected an array of 1 numbers, found 2' ucp "$m/ucp_form_b_length.json"
check 2 'bt2002_section7_disk.json: $.kind: expected "quasistatic", "quasistatic_scene" or "ucp", found "planar"' ucp "$s/bt2002_section7_disk.json"
check 2 'qs_scene_bad_finger.json: $.contacts[0].finger: exactly one of "velocity"' ucp "$m/qs_scene_bad_finger.json"
# ---- command-line options of ucp; the node budget ends in exit 3 with what it covered ----
check 3 'budget exceeded: node budget of 1 exhausted (covered: 1 nodes, 9 pairs, 18 lps)' ucp "$s/pang1994_dataset4.json" --method complete --max-nodes 1
check 3 'budget exceeded: node budget of 1 exhausted (covered: 1 nodes, 9 pairs, 18 lps)' ucp "$s/pang1994_dataset4.json" --method complete --max-nodes 1 --json
check 2 '--max-nodes' ucp "$s/pang1994_dataset4.json" --max-nodes 0
check 2 '--max-nodes' ucp "$s/pang1994_dataset4.json" --max-nodes lots
check 2 '--method' ucp "$s/pang1994_dataset4.json" --method bogus
check 2 '--arith' ucp "$s/pang1994_dataset4.json" --arith approximate
check 2 'FILE: expected a problem file' ucp
check 2 '-: $: malformed JSON' ucp -
check 2 'g.json: cannot open the file for writing' ucp --generate random --out "$work/a_directory.json/sub/g.json"
check 2 'c.json: cannot open the file for writing' ucp "$m/ucp_valid.json" --certificate "$work/garbage.bin/c.json"
check 2 'garbage.bin/out: --out: a folder that can be created' demo --out "$work/garbage.bin/out"
check 2 '--mu-max: "1/0" is not an exact number (zero denominator' ucp --generate random --mu-max 1/0 --out "$work/gen.json"
check 2 '--nc: expected a decimal integer from 1 to 1000' ucp --generate random --nc 0 --out "$work/gen.json"

# ---- planar scenes (SPEC section 3): contactcert cone / stability / insert ----
check 0 "" cone "$m/scene_valid.json" --mode nn
check 2 'scene_fixel_inside.json: $.fixels[0].position: fixel at (0, 1/2) lies inside' cone "$m/scene_fixel_inside.json" --mode n
check 2 'scene_fixel_inside.json: $.fixels[0].position' stability "$m/scene_fixel_inside.json" --wrench 0,-1,0
check 2 'scene_negative_mu.json: $.mu_s: a number >= 0' cone "$m/scene_negative_mu.json" --mode n
check 2 'scene_negative_fixel_mu.json: $.fixels[0].mu_k: a number >= 0' stability "$m/scene_negative_fixel_mu.json" --wrench 0,-1,0
check 2 'scene_missing_workpiece.json: $.workpiece: required field is missing' cone "$m/scene_missing_workpiece.json" --mode n
check 2 'scene_missing_mu.json: $.fixels[0]: a friction coefficient' cone "$m/scene_missing_mu.json" --mode n
check 2 'scene_extra_fixel_field.json: $.fixels[0].colour: unknown field' cone "$m/scene_extra_fixel_field.json" --mode n
check 2 'scene_point_dims.json: $.fixels[0].position: expected an array of 2 numbers, found 3' cone "$m/scene_point_dims.json" --mode n
check 2 'scene_zero_radius.json: $.workpiece.shape.radius: a positive number' cone "$m/scene_zero_radius.json" --mode n
check 2 'scene_bad_polygon.json: $.workpiece.shape.vertices: a simple polygon' cone "$m/scene_bad_polygon.json" --mode n
check 2 'scene_no_fixels.json: $.fixels: at least one fixel' cone "$m/scene_no_fixels.json" --mode n
check 2 'scene_zero_normal.json: $.fixels[0]: a non-zero normal' cone "$m/scene_zero_normal.json" --mode n
check 2 'scene_nan_position.json: $.fixels[0].position[0]: "nan" is not an exact number' cone "$m/scene_nan_position.json" --mode n
check 2 'scene_zero_den_radius.json: $.workpiece.shape.radius: "3/0" is not an exact number (zero denominator' cone "$m/scene_zero_den_radius.json" --mode n
check 2 'pang1994_dataset1.json: $.kind: "planar"' cone "$s/pang1994_dataset1.json" --mode nnn
check 2 'garbage.bin: $: malformed JSON' stability "$work/garbage.bin" --wrench 0,-1,0
check 2 'a_directory.json: is a directory' insert "$work/a_directory.json"
check 2 'does_not_exist.json: cannot open the file' cone "$missing" --mode n
# impossible modes: wrong length, unknown letter, a touching fixel given a gap letter and the converse
check 2 '--mode: one letter per fixel (2 letters' cone "$m/scene_valid.json" --mode n
check 2 '--mode: one letter per fixel (2 letters' cone "$m/scene_valid.json" --mode nnn
check 2 "--mode: fixel 1's letter 'x' is not one of s a u l r n m" cone "$m/scene_valid.json" --mode nx
check 2 "--mode: fixel 0's letter 'a': fixel 0 touches" cone "$m/scene_valid.json" --mode an
check 2 "--mode: fixel 0's letter 'n': fixel 0 does not touch" cone "$m/scene_gap.json" --mode nn
check 2 '--route' cone "$m/scene_valid.json" --mode nn --route bogus
# bad --wrench and other options of stability / insert
check 2 '--wrench: "nan" is not an exact number' stability "$m/scene_valid.json" --wrench 1,nan,0
check 2 '--wrench: "inf" is not an exact number' stability "$m/scene_valid.json" --wrench inf,0,0
check 2 '--wrench: expected 3 comma-separated numbers' stability "$m/scene_valid.json" --wrench 1,2
check 2 '--wrench: expected 3 comma-separated numbers' stability "$m/scene_valid.json" --wrench 1,2,3,4
check 2 '--wrench: expected 3 comma-separated numbers' stability "$m/scene_valid.json" --wrench 1,2,3,
check 2 '--wrench: "1/0" is not an exact number (zero denominator' stability "$m/scene_valid.json" --wrench 1,1/0,0
check 2 '--wrench: "1e99999" is not an exact number (exponent out of range' stability "$m/scene_valid.json" --wrench 1e99999,0,0
check 2 '--wrench: "" is not an exact number (empty' stability "$m/scene_valid.json" --wrench ,,
check 2 '--wrench: "0x10" is not an exact number' stability "$m/scene_valid.json" --wrench 0x10,0,0
check 2 '--wrench' stability "$m/scene_valid.json" --wrench 0,-1,0 --finger
check 2 '--wrench' stability "$m/scene_valid.json" --wrench
check 2 '--sweep-mu: "x" is not an exact number' insert "$s/bt2002_fig10_pentagon_insert.json" --sweep-mu 0.1,x
check 2 '--sweep-mu: friction coefficients must be >= 0' insert "$s/bt2002_fig10_pentagon_insert.json" --sweep-mu -1

# ---- cone files (SPEC section 4): contactcert convert ----
check 2 'cone_ragged.json: $.rays[1]: expected a row of 3 numbers, found 2' convert "$m/cone_ragged.json"
check 2 'cone_wrong_width.json: $.inequalities[0]: expected a row of 3 numbers, found 2' convert "$m/cone_wrong_width.json"
check 2 'cone_zero_dim.json: $.dim: expected an integer from 1' convert "$m/cone_zero_dim.json"
check 2 'cone_huge_dim.json: $.dim: expected an integer from 1' convert "$m/cone_huge_dim.json"
check 2 'cone_both_forms.json: $: expected either the span form' convert "$m/cone_both_forms.json"
check 2 'cone_not_number.json: $.rays[0][1]: "x" is not an exact number' convert "$m/cone_not_number.json"
check 2 'cone_zero_den.json: $.rays[0][1]: "2/0" is not an exact number (zero denominator' convert "$m/cone_zero_den.json"
check 2 'cone_extra_field.json: $.cones: unknown field' convert "$m/cone_extra_field.json"
check 2 'deep_object.json: $.a.a' convert "$work/deep_object.json"
check 2 'empty.json: $: malformed JSON' convert "$work/empty.json"

# ---- certificates: contactcert check ----
check 2 'cert_unknown_kind.json: $.kind: expected a certificate kind' check "$m/cert_unknown_kind.json"
check 2 'cert_stability_empty.json: $.scene: required field is missing' check "$m/cert_stability_empty.json"
check 2 'cert_ucp_jammed_empty.json: $.problem: required field is missing' check "$m/cert_ucp_jammed_empty.json"
check 2 'cert_ucp_solvable_empty.json: $.problem: required field is missing' check "$m/cert_ucp_solvable_empty.json"
check 2 'ucp_valid.json: $.kind: expected a certificate kind' check "$m/ucp_valid.json"
check 2 'garbage.bin: $: malformed JSON' check "$work/garbage.bin"
check 2 'a_directory.json: is a directory' check "$work/a_directory.json"

echo "malformed_inputs: $((cases - failures)) of $cases cases passed"
[ "$failures" -eq 0 ]
