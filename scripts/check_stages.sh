#!/usr/bin/env bash
# Stages never reach back (docs/design.md §Layout): a file under src/<stage>/ includes only headers
# of its own stage or of earlier ones in the pipeline order below. Prints each offending include
# and exits 1 if there is one.
set -euo pipefail
cd "$(dirname "$0")/.."
order=(util scene raster basis moments lp continuous shadow techniques solve eval camera oit scatter screen sweep verify report cmd)
# One pass over every include line (grep's "file:line"), so the check costs one process, not
# several per include.
grep -rHE '^#include "[a-z_]+/' src | awk -v order="${order[*]}" '
  BEGIN { n = split(order, names, " "); for (i = 1; i <= n; ++i) rank[names[i]] = i }
  {
    line = $0
    file = substr(line, 1, index(line, ":") - 1)
    split(file, parts, "/"); stage = parts[2]
    target = line; sub(/^[^:]*:#include "/, "", target); sub(/\/.*/, "", target)
    if (target == "generated") next
    if (!(stage in rank) || !(target in rank)) { print "unknown stage: " line; status = 1; next }
    if (rank[target] > rank[stage]) { print "reaches back: " line; status = 1 }
  }
  END { exit status }'
