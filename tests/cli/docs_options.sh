#!/usr/bin/env bash
# docs/formats.md must name every option of every subcommand (it is the user's reference to the command
# line). Usage: docs_options.sh CONTACTCERT DOCS_FILE
set -u
cc="$1" doc="$2"
subs=$("$cc" --help | awk 'tolower($0) ~ /^subcommands:/ {on=1; next} on && NF {print $1}')
if [ "$(echo "$subs" | wc -w)" -lt 7 ]; then
  echo "docs: could not read the subcommands from $cc --help"
  exit 1
fi
missing=0
checked=0
for sub in $subs; do
  for opt in $("$cc" "$sub" --help | grep -oE '(^|[ ,])--[a-z][a-z-]*' | tr -d ' ,' | sort -u); do
    case "$opt" in --help) continue ;; esac
    checked=$((checked + 1))
    if ! grep -q -- "\`$opt" "$doc"; then
      echo "docs: $sub $opt is not described in $doc"
      missing=1
    fi
  done
done
echo "docs: $checked options of $(echo "$subs" | wc -w) subcommands checked"
# Every numeric option goes through the strict checks of cli/option_checks.h, whose ranges --help shows: an integer
# as "INT:INT in [lo, hi]", a duration as "FLOAT:SECONDS in [0, 1e7]".
for sub in $subs; do
  for opt in $("$cc" "$sub" --help | grep -E -- '--[a-z-]+ (U?INT|FLOAT|NUMBER|POSITIVE)' |
    grep -vE -- '--[a-z-]+ (U?INT:INT in \[|FLOAT:SECONDS in \[)' | awk '{print $1}'); do
    echo "options: $sub $opt takes a number without the strict check (cli/option_checks.h)"
    missing=1
  done
done
exit $missing
