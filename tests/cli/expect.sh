#!/usr/bin/env bash
# expect.sh fail|pass REGEX OUTDIR -- COMMAND...  (REGEX is matched against the output joined into one line)
# Runs COMMAND; checks its exit code (non-zero for fail), that stdout+stderr match REGEX, and for
# fail that OUTDIR was not created (bad input leaves no partial output).
set -u
mode=$1 regex=$2 outdir=$3
shift 4
rm -rf "$outdir"
output=$("$@" 2>&1)
code=$?
echo "$output"
if [ "$mode" = fail ]; then
  [ $code -ne 0 ] || { echo "expect.sh: expected a non-zero exit, got 0"; exit 1; }
  [ ! -e "$outdir" ] || { echo "expect.sh: $outdir was written despite the error"; exit 1; }
  # no staging directory left behind either
  ls -a "$(dirname "$outdir")" | grep -q "^\.$(basename "$outdir")\.staging" && { echo "expect.sh: staging left behind"; exit 1; }
else
  [ $code -eq 0 ] || { echo "expect.sh: expected exit 0, got $code"; exit 1; }
fi
echo "$output" | tr "\n" " " | grep -Eq -- "$regex" || { echo "expect.sh: output does not match /$regex/"; exit 1; }
exit 0
