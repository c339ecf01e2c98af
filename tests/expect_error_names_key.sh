#!/bin/sh
# A bad option must exit 2 with one error line that names its dotted key:
#   expect_error_names_key.sh PROGRAM OUT_DIR KEY ARGS...
prog=$1; out=$2; key=$3; shift 3
rm -rf "$out"
err=$("$prog" --out "$out" "$@" 2>&1 >/dev/null); status=$?
if [ "$status" -ne 2 ]; then echo "exited $status, expected 2: $err"; exit 1; fi
case "$err" in
  *"'$key'"*) echo "ok: $err" ;;
  *) echo "does not name '$key': $err"; exit 1 ;;
esac
if [ -e "$out" ]; then echo "wrote $out"; exit 1; fi
