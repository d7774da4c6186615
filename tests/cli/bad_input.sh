#!/usr/bin/env bash
# bad_input.sh MOMENTBENCH CORPUS NAME WORKDIR: runs case NAME of the bad-input corpus through
# expect.sh: a non-zero exit, a message matching the case's pattern (which names the file, line or
# key and what was expected), and nothing left behind (neither $OUT nor a staging directory).
set -u
MB=$1 corpus=$2 name=$3 work=$4
BAD=$(cd "$(dirname "$corpus")/../data/bad" && pwd)
line=$(awk -F'\t' -v n="$name" '$1 == n' "$corpus")
[ -n "$line" ] || { echo "bad_input.sh: no case '$name' in $corpus"; exit 1; }
regex=$(printf '%s' "$line" | cut -f2)
command=$(printf '%s' "$line" | cut -f3)
rm -rf "$work" && mkdir -p "$work"
OUT=$work/out TMP=$work/tmp
mkdir -p "$TMP"
export MB BAD OUT TMP
exec "$(dirname "$0")/expect.sh" fail "$regex" "$OUT" -- bash -c "$command"
