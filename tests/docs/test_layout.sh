#!/bin/sh
# test_layout.sh [BUILD_DIR] - README.md's "## Layout" section matches the
# tree.  In that section (up to the next "## " heading, its "###"
# subsections included) every code span that is a path under src/,
# include/, ports/, tests/ or bench/ must exist: `dir/x.c` a file, `dir/` a
# folder, `dir/*` a folder whose files it covers.  And every file under
# src/, include/ and ports/ (but the READMEs) must be named by such a span
# or covered by a `dir/*` one.  Spans holding `<` (placeholders such as
# `ports/<isa>/`) are not paths.  Each failure names the file: the fix is a
# line in the Layout section, or the file.  Run from the source tree's top.
readme=README.md
pass=0 fail=0
[ -f "$readme" ] || { echo "FAIL layout: $readme not found (run from the source tree's top)"; echo "layout: 0 passed, 1 failed, 0 skipped"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# the section's code spans, one per line
awk '/^## / { on = ($0 == "## Layout") } on' "$readme" |
    grep -o '`[^`]*`' | tr -d '`' | sort -u > "$tmp/spans"
grep -E '^(src|include|ports|tests|bench)/' "$tmp/spans" | grep -v '[<> ]' > "$tmp/paths"
[ -s "$tmp/paths" ] || { echo "FAIL layout: $readme has no \"## Layout\" section naming paths"; fail=$((fail + 1)); }

# every named path exists
while IFS= read -r p; do
    case $p in
    */\*) d=${p%/\*}; if [ -d "$d" ]; then pass=$((pass + 1)); else echo "FAIL layout: $readme's Layout section covers $p, but there is no folder $d"; fail=$((fail + 1)); fi ;;
    */) if [ -d "$p" ]; then pass=$((pass + 1)); else echo "FAIL layout: $readme's Layout section names the folder $p, which does not exist"; fail=$((fail + 1)); fi ;;
    *) if [ -f "$p" ]; then pass=$((pass + 1)); else echo "FAIL layout: $readme's Layout section names $p, which does not exist"; fail=$((fail + 1)); fi ;;
    esac
done < "$tmp/paths"

# every source file is named or covered
grep '/\*$' "$tmp/paths" | sed 's|\*$||' > "$tmp/covers"
find src include ports -type f ! -name README.md ! -name '.*' | sort > "$tmp/files"
while IFS= read -r f; do
    if grep -qxF "$f" "$tmp/paths"; then
        pass=$((pass + 1))
    elif awk -v f="$f" 'index(f, $0) == 1 { hit = 1 } END { exit !hit }' "$tmp/covers"; then
        pass=$((pass + 1))
    else
        echo "FAIL layout: $f is not named in $readme's Layout section (name it there as \`$f\`, or cover its folder as \`$(dirname "$f")/*\`)"
        fail=$((fail + 1))
    fi
done < "$tmp/files"

echo "layout: $pass passed, $fail failed, 0 skipped"
[ $fail -eq 0 ]
