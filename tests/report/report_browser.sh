#!/bin/sh
# report_browser.sh REPORT_DIR - loads REPORT_DIR/index.html in headless
# Chromium and fails on an image that does not show (an <img> that failed
# to load or has no width, an SVG <image> whose data does not decode), on a
# script error (an uncaught exception or rejection), and on a page with no
# image at all; keeps a screenshot of the page's top 1280 x 4000 px at
# REPORT_DIR/../report-screenshot.png (under build/).  It proves it can
# fail: the same check on copies with one image's data removed (an <img>,
# an SVG <image>) and on a copy with a failing script must fail.  The
# interactive chooser is driven by tests/report/chooser_check.js (its
# answers against REPORT_DIR/choose.tsv), which must fail on a copy whose
# chooser answers wrongly and on one without the chooser's script.  Called by
# tests/suites/60-bench.sh on its quick report; skipped, with the reason,
# when chromium is not installed.
#
# How: tests/report/browser.js drives Debian's chromium through
# puppeteer-core (installed by .ci/run into build/npm: `npm ci` with
# tests/report/package.json and package-lock.json).  It awaits the page's
# load event and every image decode as events, with no time budget, so a
# loaded machine makes the check slower, never different.  (The earlier
# check ran `chromium --dump-dom` with 10 s of virtual time: under load the
# decodes, real work the virtual clock does not wait for, sometimes had not
# finished when the DOM was dumped: "no verdict from the page".)
rep=${1:-build/report}
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL report-browser: $*"; }
browser=
for b in chromium chromium-browser google-chrome; do
    command -v $b > /dev/null 2>&1 && { browser=$(command -v $b); break; }
done
npm_dir=${FACET_NPM:-build/npm}
skip() {
    echo "SKIP report-browser: $1"
    echo "report-browser: 0 passed, 0 failed, 1 skipped"
    exit 0
}
[ -n "$browser" ] || skip "chromium not installed (apt-get install chromium)"
command -v node > /dev/null 2>&1 || skip "node not installed (apt-get install nodejs)"
[ -d "$npm_dir/node_modules/puppeteer-core" ] ||
    skip "puppeteer-core not installed (cp tests/report/package*.json $npm_dir/ && (cd $npm_dir && npm ci))"
if [ ! -s "$rep/index.html" ]; then
    echo "FAIL report-browser: no $rep/index.html"
    echo "report-browser: 0 passed, 1 failed, 0 skipped"
    exit 1
fi
top=$(cd "$rep/.." && pwd)
work=$(mktemp -d "$top/report-browser.XXXXXX") # private: concurrent runs must not mix
abs_rep=$(cd "$rep" && pwd)
# check PAGE [ARGS...]: prints the verdict line; returns browser.js's status
# (0 clean, 1 not clean, 3 hang or the browser failed)
check() {
    NODE_PATH=$npm_dir/node_modules FACET_CHROMIUM=$browser node tests/report/browser.js "$@" > "$work/verdict" 2>&1
    rc=$?
    tail -n 1 "$work/verdict"
    return $rc
}
# must_fail PAGE LABEL: the check must find the page not clean (status 1:
# a hang or a browser failure is not a detection)
must_fail() {
    v=$(check "$1")
    case $? in
    1) ok ;;
    0) bad "$2 passes: $v" ;;
    *) bad "$2: no verdict ($v)" ;;
    esac
}
cp "$rep/index.html" "$work/report.html"
# a browser that takes 35 s to start (as on a loaded machine) must still
# give a verdict: puppeteer's launch waits 30 s by default, and a check
# that then failed was a timing failure, not the page's (browser.js passes
# timeout 0).  Run beside the other checks, so it costs its sleep once.
printf '#!/bin/sh\nsleep 35\nexec "%s" "$@"\n' "$browser" > "$work/slow-browser"
chmod +x "$work/slow-browser"
(NODE_PATH=$npm_dir/node_modules FACET_CHROMIUM=$work/slow-browser node tests/report/browser.js \
    "$work/report.html" > "$work/slow-verdict" 2>&1; echo $? > "$work/slow-rc") &
slow_pid=$!
# relative links (none today: PNGs are data URIs) resolve as in the report;
# choose.tsv: the chooser's data, which tests/report/chooser_check.js reads
for f in "$abs_rep"/*.png "$abs_rep"/choose.tsv; do [ -e "$f" ] && ln -sf "$f" "$work/"; done
shot=$top/report-screenshot.png
rm -f "$shot"
chooser="--script tests/report/chooser_check.js"
# shellcheck disable=SC2086
if v=$(check "$work/report.html" --screenshot "$shot" $chooser); then ok; else bad "$rep/index.html in $browser: $v"; fi
echo "report-browser: $rep/index.html: $v"
grep '^chooser: ' "$work/verdict" | sed 's/^/report-browser: /'
# the interactive chooser must fail its check on a page whose rule is
# reversed (the most expensive candidate that meets the need), on one that
# takes every binary16 candidate for f32 (so it answers f32 where the data
# says f16) and on one without its script (the static tables alone)
sed 's|a\.cost - b\.cost /\*facet-rule\*/|b.cost - a.cost /*facet-rule*/|' "$rep/index.html" > "$work/chooser-wrong.html"
sed 's|a\[3\] /\*facet-format\*/|(a[3] === "f16" ? "f32" : a[3]) /*facet-format*/|' "$rep/index.html" > "$work/chooser-f16-as-f32.html"
sed '/^(function () {$/,/^})();$/d' "$rep/index.html" > "$work/chooser-no-script.html"
for c in wrong f16-as-f32 no-script; do
    if cmp -s "$rep/index.html" "$work/chooser-$c.html"; then bad "no chooser script to break ($c)"; continue; fi
    # shellcheck disable=SC2086
    v=$(check "$work/chooser-$c.html" $chooser)
    case $? in
    1) ok ;;
    0) bad "the chooser check passes on a page with the chooser $c: $v" ;;
    *) bad "chooser $c: no verdict ($v)" ;;
    esac
done
# the screenshot, of the report itself: the top 1280 x 4000 px
if [ -s "$shot" ] && [ "$(od -An -tx1 -N8 "$shot" | tr -d ' ')" = 89504e470d0a1a0a ]; then ok
else bad "no screenshot"; fi
echo "report-browser: screenshot $shot"
# copies with one image's data removed (an <img>, an SVG <image>) and one
# with a failing script: the check must fail on each (a kind of image the
# report does not have is not tested)
for a in src href; do
    awk -v a=$a '!done && sub(" " a "=\"data:image/png;base64,[A-Za-z0-9+/=]*\"", " " a "=\"removed.png\"") { done = 1 } { print }' \
        "$rep/index.html" > "$work/$a-image-removed.html"
    if cmp -s "$rep/index.html" "$work/$a-image-removed.html"; then echo "report-browser: no $a= data-URI image to remove"
    else must_fail "$work/$a-image-removed.html" "a missing image ($a=)"; fi
done
sed 's|</body>|<script>facet_no_such_function();</script></body>|' "$rep/index.html" > "$work/script-error.html"
must_fail "$work/script-error.html" "a script error"
wait $slow_pid
if [ "$(cat "$work/slow-rc" 2>/dev/null)" = 0 ]; then ok
else bad "a browser that starts in 35 s: no clean verdict ($(tail -n 1 "$work/slow-verdict"))"; fi
rm -rf "$work"
echo "report-browser: $pass passed, $fail failed, 0 skipped"
[ $fail -eq 0 ]
