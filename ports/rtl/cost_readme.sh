#!/bin/sh
# cost_readme.sh DIR - prints DIR/README.md with the text between its cost
# markers replaced by `cost_md.sh DIR` (the committed cost.tsv and
# cost_cells.tsv); cost.sh writes the result back, and tests/suites/57-rtl.sh
# checks that the README equals it.
set -eu
d=$1
begin='<!-- cost: begin (ports/rtl/cost_md.sh on cost.tsv, cost_cells.tsv; make rtl rewrites it) -->'
end='<!-- cost: end -->'
grep -qxF "$begin" "$d/README.md" && grep -qxF "$end" "$d/README.md" || {
    echo "cost_readme.sh: $d/README.md lacks the cost markers" >&2
    exit 1
}
t=$(mktemp)
sh "$(dirname "$0")/cost_md.sh" "$d" > "$t"
awk -v b="$begin" -v e="$end" -v f="$t" '
    $0 == b { print; while ((getline l < f) > 0) print l; skip = 1; next }
    $0 == e { skip = 0 }
    !skip' "$d/README.md"
rm -f "$t"
