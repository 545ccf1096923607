#!/usr/bin/env bash
# The docs name the command line as it is. docs/SPEC.md's command table (section 6) has one row per subcommand,
# whose options cell names exactly the options of that subcommand's --help (both ways), and for an option that
# takes a fixed set of values ("TEXT:{a,b}" in --help) exactly those values, written `--opt a\|b`; every row is a
# subcommand. docs/formats.md describes every option. Every numeric option has the strict checks of
# cli/option_checks.h. Usage: docs_options.sh CONTACTCERT SPEC_MD FORMATS_MD
set -u
cc="$1" spec="$2" formats="$3"
subs=$("$cc" --help | awk 'tolower($0) ~ /^subcommands:/ {on=1; next} on && NF {print $1}')
if [ "$(echo "$subs" | wc -w)" -lt 7 ]; then
  echo "docs: could not read the subcommands from $cc --help"
  exit 1
fi
failed=0
fail() {
  echo "$1"
  failed=1
}
# The options cell of the table row of subcommand $1 (`\|` inside a cell kept as a plain |).
table_options() {
  awk -v name="$1" 'index($0, "| `contactcert " name " ") == 1 || index($0, "| `contactcert " name "`") == 1 {
      gsub(/\\\|/, "\001"); split($0, cell, "|"); s = cell[3]; gsub("\001", "|", s); print s }' "$spec"
}
# The options of subcommand $1's --help, one a line as "--name" or "--name a,b,c" (its fixed set of values).
help_options() {
  "$cc" "$1" --help | grep -E '^ +(-[a-z],)?--[a-z]' | sed -E 's/^ +(-[a-z],)?//' |
    sed -E 's/^(--[a-z][a-z-]*)( [A-Z]+:\{([^}]*)\})?.*/\1 \3/; s/ +$//' | grep -v '^--help$'
}
checked=0
for sub in $subs; do
  cell=$(table_options "$sub")
  if [ -z "$cell" ]; then
    fail "docs: $spec has no row for the subcommand $sub"
    continue
  fi
  if [ "$(printf '%s\n' "$cell" | wc -l)" -ne 1 ]; then
    fail "docs: $spec has more than one row for the subcommand $sub"
    continue
  fi
  in_table=$(grep -oE '`--[a-z][a-z-]*' <<< "$cell" | tr -d '`' | sort -u)
  in_help=$(help_options "$sub" | awk '{print $1}' | sort -u)
  for opt in $(comm -23 <(echo "$in_help") <(echo "$in_table")); do
    fail "docs: $sub $opt (in --help) is not in the row of $sub in $spec"
  done
  for opt in $(comm -13 <(echo "$in_help") <(echo "$in_table")); do
    fail "docs: $sub $opt (in $spec) is not an option of $sub (its --help)"
  done
  while read -r opt values; do
    checked=$((checked + 1))
    grep -q -- "\`$opt" "$formats" || fail "docs: $sub $opt is not described in $formats"
    [ -n "$values" ] || continue
    want=$(tr ',' '\n' <<< "$values" | sort)
    got=$(grep -oE -- "\`$opt [^\`]*\`" <<< "$cell" | head -1 | sed -E "s/^\`$opt //; s/\`$//" | tr '|' '\n' | sort)
    [ "$want" = "$got" ] || fail "docs: $sub $opt takes {$values} (--help), the row of $sub in $spec says {$(echo $got | tr ' ' ',')}"
  done < <(help_options "$sub")
done
# Every row of the table is a subcommand.
for row in $(grep -oE '^\| `contactcert [a-z]+' "$spec" | awk '{print $3}' | sort -u); do
  grep -qx -- "$row" <<< "$subs" || fail "docs: $spec has a row for $row, which is not a subcommand of $cc"
done
echo "docs: $checked options of $(echo "$subs" | wc -w) subcommands checked against $spec and $formats"
# Every numeric option goes through the strict checks of cli/option_checks.h, whose ranges --help shows: an integer
# as "INT:INT in [lo, hi]", a duration as "FLOAT:SECONDS in [0, 1e7]".
for sub in $subs; do
  for opt in $("$cc" "$sub" --help | grep -E -- '--[a-z-]+ (U?INT|FLOAT|NUMBER|POSITIVE)' |
    grep -vE -- '--[a-z-]+ (U?INT:INT in \[|FLOAT:SECONDS in \[)' | awk '{print $1}'); do
    fail "options: $sub $opt takes a number without the strict check (cli/option_checks.h)"
  done
done
exit $failed
