#!/bin/sh
# Bad input must be refused before anything is written (README "Running a chapter"):
#   expect_usage_error.sh PROGRAM OUT_DIR "ARGS" ["ARGS"...]
# For each ARGS (one command line, split on blanks), PROGRAM --out OUT_DIR ARGS must
# exit with status 2, print exactly one line on stderr, and leave neither OUT_DIR
# nor anything beside it (a staging folder ".OUT_DIR.staging.*", a lock file).
prog=$1; out=$2; shift 2
beside() { find "$(dirname "$out")" -maxdepth 1 -name ".$(basename "$out").*" "$@"; }
rm -rf "$out"; beside -exec rm -rf {} +
for args in "$@"; do
  # shellcheck disable=SC2086
  err=$("$prog" --out "$out" $args 2>&1 >/dev/null); status=$?
  if [ "$status" -ne 2 ]; then echo "'$args' exited $status, expected 2: $err"; exit 1; fi
  lines=$(printf '%s\n' "$err" | wc -l)
  if [ "$lines" -ne 1 ]; then echo "'$args' printed $lines lines on stderr, expected 1:"; echo "$err"; exit 1; fi
  if [ -e "$out" ] || [ -n "$(beside)" ]; then echo "'$args' wrote $out or" $(beside); exit 1; fi
  echo "ok: '$args' -> $err"
done
