#!/usr/bin/env bash
# Stages never reach back (docs/design.md §Layout): a file under src/<stage>/ includes only headers
# of its own stage or of earlier ones in the pipeline order below. Prints each offending include
# and exits 1 if there is one.
set -euo pipefail
cd "$(dirname "$0")/.."
order=(util scene raster basis moments lp continuous shadow techniques solve eval oit screen sweep verify report cmd)
rank() { local i; for i in "${!order[@]}"; do [ "${order[$i]}" = "$1" ] && echo "$i" && return; done; echo -1; }
status=0
while IFS= read -r line; do
  file=${line%%:*}
  stage=$(echo "$file" | cut -d/ -f2)
  target=$(echo "$line" | sed -E 's/.*#include "([a-z_]+)\/.*/\1/')
  [ "$target" = generated ] && continue
  rs=$(rank "$stage"); rt=$(rank "$target")
  if [ "$rs" -lt 0 ] || [ "$rt" -lt 0 ]; then echo "unknown stage: $line"; status=1; continue; fi
  if [ "$rt" -gt "$rs" ]; then echo "reaches back: $line"; status=1; fi
done < <(grep -rHE '^#include "[a-z_]+/' src)
exit $status
