#!/bin/sh
# report_browser.sh REPORT_DIR - loads REPORT_DIR/index.html in headless
# Chromium and fails on an image that does not show (an <img> that failed
# to load or has no width, an SVG <image> whose data does not decode), on a
# script error (an uncaught exception or rejection), and on a page with no
# image at all; keeps a screenshot of the page's top 1280 x 4000 px at
# REPORT_DIR/../report-screenshot.png (under build/).  It proves it can
# fail: the same check on copies with one image's data removed (an <img>,
# an SVG <image>) and on a copy with a failing script must fail.  Called by
# tests/suites/60-bench.sh on its quick report; skipped, with the reason,
# when chromium is not installed.
#
# How: a copy of the page gets, first in <head>, a script that records
# every error event (capture phase: also an image that fails to load) and,
# on load, checks every image and writes one verdict line into the page;
# `chromium --dump-dom` (10 s of virtual time) prints the page after that,
# and the verdict is read from it.
rep=${1:-build/report}
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL report-browser: $*"; }
browser=
for b in chromium chromium-browser google-chrome; do
    command -v $b > /dev/null 2>&1 && { browser=$b; break; }
done
if [ -z "$browser" ]; then
    echo "SKIP report-browser: chromium not installed (apt-get install chromium)"
    echo "report-browser: 0 passed, 0 failed, 1 skipped"
    exit 0
fi
if [ ! -s "$rep/index.html" ]; then
    echo "FAIL report-browser: no $rep/index.html"
    echo "report-browser: 0 passed, 1 failed, 0 skipped"
    exit 1
fi
top=$(cd "$rep/.." && pwd)
work=$top/report-browser
rm -rf "$work"
mkdir -p "$work"
abs_rep=$(cd "$rep" && pwd)
# headless Chromium as root needs --no-sandbox; a private profile, so that
# parallel runs do not share one
run() { # run OUT ARGS...: chromium with the common flags, bounded in time
    o=$1
    shift
    timeout 120 "$browser" --headless=new --no-sandbox --disable-gpu --hide-scrollbars \
        --no-first-run --user-data-dir="$work/profile" --virtual-time-budget=10000 "$@" > "$o" 2> "$o.err"
}
probe='<script>(function () {
  var errs = [];
  window.addEventListener("error", function (e) {
    var t = e.target;
    if (t && t !== window && t.tagName)
      errs.push("not loaded: <" + t.tagName.toLowerCase() + "> " + String(t.getAttribute("src") || t.getAttribute("href") || "").slice(0, 60));
    else
      errs.push("script error: " + e.message + " (" + e.filename + ":" + e.lineno + ")");
  }, true);
  window.addEventListener("unhandledrejection", function (e) { errs.push("unhandled rejection: " + e.reason); });
  window.addEventListener("load", function () {
    /* <img>: loaded with a width; SVG <image>: its href decodes as an image */
    var im = document.images, sv = document.getElementsByTagName("image"), n = im.length + sv.length;
    var shown = 0, waits = [], i;
    for (i = 0; i < im.length; i++) {
      if (im[i].complete && im[i].naturalWidth > 0) shown++;
      else errs.push("image not shown: <img> " + (im[i].alt || String(im[i].src).slice(0, 60)));
    }
    for (i = 0; i < sv.length; i++) (function (href) {
      var t = new Image();
      t.src = href;
      waits.push(t.decode().then(function () { if (t.naturalWidth > 0) shown++; else errs.push("image not shown: <image> (empty) " + href.slice(0, 60)); },
                                 function () { errs.push("image not shown: <image> " + href.slice(0, 60)); }));
    })(sv[i].getAttribute("href") || sv[i].getAttribute("xlink:href") || "");
    Promise.all(waits).then(function () {
      var p = document.createElement("pre");
      p.id = "facet-browser-verdict";
      p.textContent = "images " + n + " shown " + shown + " errors " + errs.length + (errs.length ? ": " + errs.join("; ") : "");
      document.body.appendChild(p);
    });
  });
})();</script>'
# check PAGE: prints the verdict line, returns 0 when the page is clean
check() {
    page=$1
    name=$(basename "$page" .html)
    PROBE=$probe awk '!done && (i = index($0, "<head>")) {
        $0 = substr($0, 1, i + 5) ENVIRON["PROBE"] substr($0, i + 6); done = 1 } { print }' "$page" > "$work/$name.probe.html"
    run "$work/$name.dom" --dump-dom "file://$work/$name.probe.html"
    v=$(sed -n 's|.*<pre id="facet-browser-verdict">\([^<]*\)</pre>.*|\1|p' "$work/$name.dom")
    if [ -z "$v" ]; then
        echo "no verdict from the page (did it load? $(tail -n 3 "$work/$name.dom.err" | tr '\n' ' '))"
        return 1
    fi
    echo "$v"
    case $v in "images 0 "*) return 1 ;; *" errors 0") return 0 ;; *) return 1 ;; esac
}
cp "$rep/index.html" "$work/report.html"
# relative links (none today: PNGs are data URIs) resolve as in the report
for f in "$abs_rep"/*.png; do [ -e "$f" ] && ln -sf "$f" "$work/"; done
if v=$(check "$work/report.html"); then ok; else bad "$rep/index.html in $browser: $v"; fi
echo "report-browser: $rep/index.html: $v"
# copies with one image's data removed (an <img>, an SVG <image>) and one
# with a failing script: the check must fail on each (a kind of image the
# report does not have is not tested)
for a in src href; do
    awk -v a=$a '!done && sub(" " a "=\"data:image/png;base64,[A-Za-z0-9+/=]*\"", " " a "=\"removed.png\"") { done = 1 } { print }' \
        "$rep/index.html" > "$work/$a-image-removed.html"
    if cmp -s "$rep/index.html" "$work/$a-image-removed.html"; then echo "report-browser: no $a= data-URI image to remove"
    elif v=$(check "$work/$a-image-removed.html"); then bad "a missing image ($a=) passes: $v"; else ok; fi
done
sed 's|</body>|<script>facet_no_such_function();</script></body>|' "$rep/index.html" > "$work/script-error.html"
if v=$(check "$work/script-error.html"); then bad "a script error passes: $v"; else ok; fi
# the screenshot, of the report itself: the top 1280 x 4000 px
shot=$top/report-screenshot.png
rm -f "$shot"
run "$work/shot.log" --window-size=1280,4000 --screenshot="$shot" "file://$work/report.html"
if [ -s "$shot" ] && [ "$(od -An -tx1 -N8 "$shot" | tr -d ' ')" = 89504e470d0a1a0a ]; then ok
else bad "no screenshot ($(tail -n 3 "$work/shot.log.err" | tr '\n' ' '))"; fi
echo "report-browser: screenshot $shot"
rm -rf "$work/profile"
echo "report-browser: $pass passed, $fail failed, 0 skipped"
[ $fail -eq 0 ]
