#!/usr/bin/env bash
# Every citation of the project's docs resolves in a clone (docs/design.md §Style): for each
# "docs/<page>.md §<section>" in src/, tests/, scripts/, README.md, results/ and docs/, the page
# exists and has a heading for that section ("## 3. ..." for a number, "## Layout" for a name).
# Also: no citation of a file outside the repository (REFERENCE.md, DESIGN.md).
set -euo pipefail
cd "${1:-$(dirname "$0")/../..}"
roots=(src tests scripts README.md results docs)
status=0
stray=$(grep -rnIE '(^|[^/a-z])(REFERENCE|DESIGN)\.md' "${roots[@]}" | grep -v '^tests/cli/check_citations.sh' || true)
if [ -n "$stray" ]; then echo "cites a file that is not in the repository:"; echo "$stray"; status=1; fi
checked=0
while IFS= read -r hit; do
  where=${hit%%:docs/*}
  cite=${hit#"$where":}
  page=${cite%% §*}
  section=${cite#* §}
  section=${section%.}
  checked=$((checked + 1))
  if [ ! -f "$page" ]; then echo "$where: $page does not exist"; status=1; continue; fi
  if [[ $section =~ ^[0-9]+$ ]]; then pattern="^#+ $section\\. "; else pattern="^#+ $section"; fi
  grep -qE "$pattern" "$page" || { echo "$where: $page has no section §$section"; status=1; }
done < <(grep -rnoIE 'docs/[a-z0-9_-]+\.md §[0-9A-Za-z]+' "${roots[@]}" | grep -v '^tests/cli/check_citations.sh')
for page in $(grep -rhoIE 'docs/[a-z0-9_/-]+\.md' "${roots[@]}" | sort -u); do
  [ -f "$page" ] || { echo "cited page $page does not exist"; status=1; }
done
echo "$checked section citations checked"
exit $status
