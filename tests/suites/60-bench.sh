# The bench machinery (bench/, its own binary build/facet-bench):
# `facet-bench bench` runs and prints well-formed JSON with the expected
# fields and rejects bad selections; `facet-bench batch-symbols` locates
# every port's batch functions (what bench/report/report.sh sizes); and the
# library's `facet` command carries none of it (no bench or peer object,
# so no -march=native code).  The PNG encoder and rasterizer tests are
# build/tests/test_bench, run by the compiler suites.  Timing figures are
# not judged.  A quick report (below) replaces the bench part a full one
# left, and loads in Chromium without a missing image or a script error
# (tests/report/report_browser.sh; screenshot build/report-screenshot.png).
. tests/lib/suite_lib.sh
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL bench: $*"; }
if ! $MAKE -s -j"$JOBS" BUILD=build tests build/facet-bench >build/bench-suite.build.log 2>&1; then
    cat build/bench-suite.build.log
    echo "ERROR bench: build failed (log: build/bench-suite.build.log)"
    exit 0
fi
# build/facet links src/cli/*.o and libfacet.a only: no global symbol any
# bench object defines (harness, peers, report, raster; main aside) is in it
find build/bench -name '*.o' -exec nm -g --defined-only {} + 2>/dev/null |
    awk 'NF == 3 && $3 != "main" { print $3 }' | sort -u > build/bench-suite.bench.syms
nm --defined-only build/facet | awk '{ print $NF }' | sort -u > build/bench-suite.facet.syms
[ -s build/bench-suite.bench.syms ] && ok || bad "no bench objects under build/bench"
shared=$(comm -12 build/bench-suite.bench.syms build/bench-suite.facet.syms | tr '\n' ' ')
[ -z "$shared" ] && ok || bad "build/facet carries bench symbols: $shared"
n=$(nm build/facet | grep -ciE 'peer|bench'); [ "$n" -eq 0 ] && ok || bad "nm build/facet: $n peer/bench symbols"
build/facet bench >/dev/null 2>&1; [ $? -eq 2 ] && ok || bad "facet still has a bench verb"
build/facet --help | grep -q bench && bad "facet --help mentions bench" || ok
# batch-symbols: one line per f32 tier, compiled-in port and kernel, each at a function
nports=$(build/facet eval --help | sed -n 's/^ports compiled in://p' | sed 's/ (not on this CPU)//g' | wc -w)
nk=$(build/facet list | grep -vc -- '->') # the kernels (samplers: "inputs -> outputs")
build/facet-bench batch-symbols > build/bench-suite.batch-symbols; rc=$?
[ $rc -eq 0 ] && [ "$(wc -l < build/bench-suite.batch-symbols)" -eq $((2 * nports * nk)) ] && ok ||
    bad "batch-symbols: exit $rc, $(wc -l < build/bench-suite.batch-symbols) lines, want 2 tiers x $nports ports x $nk kernels"
syms=$(nm -S --defined-only build/facet-bench)
anchor=$(printf '%s\n' "$syms" | awk '$NF == "facet_port_supported" { print $1; exit }')
missing=0
while read -r fmt port k off; do
    addr=$(printf "%0${#anchor}x" $((0x$anchor + off)))
    printf '%s\n' "$syms" | awk -v a="$addr" '$1 == a && NF == 4 && $3 ~ /^[tT]$/ { f = 1 } END { exit !f }' ||
        missing=$((missing + 1))
done < build/bench-suite.batch-symbols
[ -n "$anchor" ] && [ $missing -eq 0 ] && ok || bad "batch-symbols: $missing offsets are not functions"
out=$(build/facet-bench bench ggx_d --json --quick 2>/dev/null); rc=$?
[ $rc -eq 0 ] && ok || bad "facet-bench bench ggx_d --json exited $rc"
j=$(printf '%s' "$out" | tr -d '\n')
for key in '"clock": {"source": "' '"unit": "' '"measured_core_cycles": ' '"results": \[' \
           '"kernel": "ggx_d", "format": "f32", "port": "scalar", "path": "batch"' \
           '"path": "inline"' '"path": "call"' '"max_err": [0-9]' '"argmax": \[' \
           '"throughput": {"min": [0-9]' '"latency": {"min": [0-9]' '"spread": ' '"within_bound": true' ; do
    printf '%s' "$j" | grep -qE "$key" && ok || bad "JSON lacks /$key/"
done
# balanced braces and brackets, and a closing ']}'
opens=$(printf '%s' "$j" | tr -cd '{' | wc -c); closes=$(printf '%s' "$j" | tr -cd '}' | wc -c)
[ "$opens" -eq "$closes" ] && ok || bad "JSON braces unbalanced ($opens vs $closes)"
printf '%s' "$j" | grep -qE '\]\}$' && ok || bad "JSON does not end with ]}"
if command -v python3 >/dev/null 2>&1; then
    printf '%s' "$out" | python3 -c 'import json,sys; d=json.load(sys.stdin); assert d["results"]' \
        && ok || bad "python3 json.load rejects the output"
fi
# every ggx_d row within its facet bound (error is a property, not a timing)
n_bad=$(printf '%s' "$out" | grep -c '"within_bound": false')
[ "$n_bad" -eq 0 ] && ok || bad "$n_bad ggx_d rows outside the bound"
# the samplers: a batch row per f32 tier and port this CPU runs, each within
# its facet.h bound, the inline loops, and the textbook peer row (bench.c
# run_samplers)
nsup=$(build/facet eval --help | sed -n 's/^ports compiled in://p' | sed 's/[a-z0-9]* (not on this CPU)//g' | wc -w)
sout=$(build/facet-bench bench ggx_sample_vndf --json --quick 2>/dev/null); rc=$?
sj=$(printf '%s' "$sout" | tr -d '\n')
nb=$(printf '%s' "$sj" | grep -o '"kernel": "ggx_sample_vndf", "format": "f32[_a-z]*", "port": "[a-z0-9]*", "path": "batch"' | wc -l)
[ $rc -eq 0 ] && [ "$nb" -eq $((2 * nsup)) ] && ok || bad "bench ggx_sample_vndf: exit $rc, $nb batch rows, want 2 tiers x $nsup ports this CPU runs"
printf '%s' "$sj" | grep -q '"port": "textbook", "path": "peer"' && ok || bad "bench ggx_sample_vndf: no textbook peer row"
printf '%s' "$sj" | grep -q '"kernel": "ggx_sample_vndf", "format": "f32", "port": "scalar", "path": "inline"' && ok ||
    bad "bench ggx_sample_vndf: no scalar inline row"
n_bad=$(printf '%s' "$sout" | grep -c '"within_bound": false')
[ "$n_bad" -eq 0 ] && ok || bad "$n_bad ggx_sample_vndf rows outside the bound"
# the peers' check (bench/harness/peers.c): every peer term of this CPU is
# its kernel's formula (arithmetic error only on the well-conditioned set),
# and its control, a peer of another model, fails
pc=$(build/facet-bench bench --peer-check 2>&1); rc=$?
[ $rc -eq 0 ] && printf '%s\n' "$pc" | grep -q '^peer check: every term within 2^-10' && ok ||
    { printf '%s\n' "$pc" | grep -v '^[a-z_0-9]* *[a-z_0-9]* *[0-9.e-]*$' | head -5; bad "facet-bench bench --peer-check (exit $rc)"; }
npc=$(printf '%s\n' "$pc" | awk '$1 ~ /^shader/ { n++ } END { print n + 0 }')
[ "$npc" -ge $(( $(build/facet list | grep -vc -- '->') )) ] && ok || bad "--peer-check: $npc shader peer terms, want at least one per kernel"
# text form and bad input
build/facet-bench bench lambert --quick --no-peers | grep -qE '^lambert +f32 +scalar +batch' && ok || bad "text table"
build/facet-bench bench nosuch >/dev/null 2>&1; [ $? -eq 2 ] && ok || bad "unknown kernel: want exit 2"
build/facet-bench bench ggx_d --port nosuch --quick >/dev/null 2>&1; [ $? -eq 2 ] && ok || bad "unknown port: want exit 2"
build/facet-bench bench ggx_d --format q15 >/dev/null 2>&1; [ $? -eq 2 ] && ok || bad "unknown format: want exit 2"
build/facet-bench bench --help | grep -q 'usage: facet-bench bench' && ok || bad "--help"
# est_cycles_median is the median over ticks_per_cycle (it printed the
# minimum: four shared number buffers for five numbers in one printf)
if command -v python3 >/dev/null 2>&1; then
    printf '%s' "$out" | python3 -c '
import json, sys
d = json.load(sys.stdin); t = d["clock"]["ticks_per_cycle"]
stats = [r[k] for r in d["results"] for k in ("throughput", "latency") if k in r]
bad = [s for s in stats if abs(s["est_cycles_median"] - s["median"] / t) > 2e-4 * s["median"] / t]
sys.exit(1 if bad or not stats else 0)' && ok || bad "JSON est_cycles_median is not median / ticks_per_cycle"
fi
# exit codes: 1 when stdout cannot be written; 2 for a value past its cap
build/facet-bench bench lambert --quick --no-peers >/dev/full 2>/dev/null; [ $? -eq 1 ] && ok || bad "stdout /dev/full: want exit 1"
build/facet-bench bench lambert --epochs 1002 >/dev/null 2>&1; [ $? -eq 2 ] && ok || bad "--epochs 1002: want exit 2"
build/facet-bench bench lambert --samples 65544 >/dev/null 2>&1; [ $? -eq 2 ] && ok || bad "--samples 65544: want exit 2"
build/facet-bench bench lambert --samples " 8" >/dev/null 2>&1; [ $? -eq 2 ] && ok || bad "--samples ' 8': want exit 2"
# the Cortex-M harness of make report (bench/cortexm/cortexm_main.c, one call
# per kernel of the list) compiles in every format: a kernel input it has no
# point for broke every Cortex-M figure of the report without a failing check
if command -v arm-none-eabi-gcc > /dev/null 2>&1; then
    for f in "-DBENCH_FX" "-DBENCH_FX -DBENCH_FX_FAST" "-mfloat-abi=soft"; do
        # shellcheck disable=SC2086
        arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -O2 -std=c99 -Wall -Wextra -Werror -Iinclude $f -fsyntax-only \
            bench/cortexm/cortexm_main.c 2> build/bench-suite.cortexm.log && ok ||
            { head -5 build/bench-suite.cortexm.log; bad "bench/cortexm/cortexm_main.c does not compile ($f)"; }
    done
fi
# the Arm vector targets' counting program (bench/report/armcount_main.c, one
# call per kernel and tier of the list) compiles for both ports: a kernel
# the list gains must not silently drop the chooser's NEON and Helium rows
# (and with the binary16 tables, as arm_targets.sh and qcount.sh m55-f16
# build it; RVV below)
if command -v aarch64-linux-gnu-gcc > /dev/null 2>&1; then
    for f in ""; do
        aarch64-linux-gnu-gcc -O2 -std=c99 -Wall -Wextra -Werror -Iinclude -DARMCOUNT_PORT=neon $f -fsyntax-only \
            bench/report/armcount_main.c 2> build/bench-suite.armcount.log && ok ||
            { head -5 build/bench-suite.armcount.log; bad "bench/report/armcount_main.c does not compile for NEON ($f)"; }
    done
fi
if command -v arm-none-eabi-gcc > /dev/null 2>&1; then
    for f in "" "-DARMCOUNT_F16_ONLY"; do
        arm-none-eabi-gcc -mcpu=cortex-m55 -mfloat-abi=hard -mthumb -O2 -std=c99 -Wall -Wextra -Werror -Iinclude \
            -DARMCOUNT_PORT=helium $f -fsyntax-only bench/report/armcount_main.c 2> build/bench-suite.armcount.log && ok ||
            { head -5 build/bench-suite.armcount.log; bad "bench/report/armcount_main.c does not compile for Helium ($f)"; }
    done
fi
# and for RVV as arm_targets.sh and qcount.sh rv64-f16 build it (the port
# flags the library's build gives src/core/platform.h: the rvv line with its
# binary16 table rvvfp16)
if command -v riscv64-linux-gnu-gcc > /dev/null 2>&1; then
    for f in "" "-DARMCOUNT_F16_ONLY"; do
        riscv64-linux-gnu-gcc -O2 -std=c99 -Wall -Wextra -Werror -Iinclude -DFACET_PORT_RVV=1 -DFACET_PORT_RVVFP16=1 \
            -DARMCOUNT_PORT=rvv $f -fsyntax-only bench/report/armcount_main.c 2> build/bench-suite.armcount.log && ok ||
            { head -5 build/bench-suite.armcount.log; bad "bench/report/armcount_main.c does not compile for RVV ($f)"; }
    done
fi
# the report's own part on its own (no mca, no Cortex-M traces): a quick run
# writes a self-contained index.html that is valid UTF-8, whose labelled
# figures put every label inside their SVG (an uninitialised picture once
# drew its titles from stack garbage), and whose image-space table has the
# f32, fixed-point and model rows
# It runs over the directory a full `make report` leaves: accuracy.md (the
# part tests/report/report.sh writes; a fixture here) and report.md = accuracy.md +
# that run's bench part.  A quick run used to append a second Benchmarks
# section to index.html and to leave report.md as it was, unlabelled as
# quick: now both are accuracy.md + this run's bench part, labelled.
r=build/bench-suite-report
rm -rf $r && mkdir -p $r
printf '# facet report\n\n## f32 accuracy (a 60-bench fixture for the part make report writes)\n\nnone measured\n' > $r/accuracy.md
{ cat $r/accuracy.md; printf '\n# Benchmarks (bench/)\n\nthe stale bench part of a full run\n'; } > $r/report.md
cp $r/report.md $r/report.md.full
# the Arm vector targets' costs (what bench/report/arm_targets.sh leaves): a
# fixture with NEON costed and Helium skipped, so both chooser paths show
{ echo "# format port kernel measure value"
  echo "f32 neon brdf_hammon mca-cortex-a57 44.50"; echo "f32_fast neon brdf_hammon mca-cortex-a57 43.25"
  echo "fx_fast neon brdf_hammon mca-cortex-a57 99.75"; echo "f32 neon brdf_hammon qemu-insn 44.9"
  # smith_vis: f32_fast the cheapest, so the chooser check has an f32_fast
  # answer whatever this machine's timings are
  echo "f32 neon smith_vis mca-cortex-a57 9.50"; echo "f32_fast neon smith_vis mca-cortex-a57 7.25"
  echo "fx_fast neon smith_vis mca-cortex-a57 21.00"
  # binary16: neonfp16's smith_vis the cheapest, so the chooser check has an
  # f16 answer (at 8 bits) whatever this machine's timings are
  echo "f16 neon smith_vis mca-cortex-a57 3.00"; echo "f16 neon smith_vis qemu-insn 6.0"
  # binary16 on the A55 model (the f16 table of the speed section)
  echo "f32 neon brdf_hammon mca-cortex-a55 53.02"; echo "f32_fast neon brdf_hammon mca-cortex-a55 47.06"
  echo "f16 neon brdf_hammon mca-cortex-a55 35.11"
  # and on RVV (rvvfp16: qemu instructions at VLEN 128, the RVV column)
  echo "f32 rvv brdf_hammon qemu-insn 53.9"; echo "f32_fast rvv brdf_hammon qemu-insn 49.9"
  echo "f16 rvv brdf_hammon qemu-insn 38.0"; } > $r/arm_vec.tsv
printf 'neon ok llvm-mca fixture\nhelium skipped: a 60-bench fixture reason\n' > $r/arm_vec.status
printf 'neon-f16 ok the neonfp16 table, llvm-mca fixture\nhelium-f16 skipped: no f16 port yet (a 60-bench fixture)\n' >> $r/arm_vec.status
# the RTL port's cost (what make rtl leaves in ports/rtl/cost.tsv): a
# fixture with one module placed on an UP5K and one that fits no iCE40, so
# the chooser's hardware row shows both forms of its clock
{ printf 'module\tlatency\tcells\tgate_equivalents\tdepth\tluts\tdsps\tfmax_mhz\tdevice\tlcs\tebr\tffs\tluts_no_dsp\n'
  printf 'fresnel_schlick\t12\t11790\t21174\t38\t792\t8\t25.59\tup5k\t1687\t0\t896\t-\n'
  printf 'brdf_hammon\t49\t90001\t170002\t40\t9001\t40\t-\tnone\t-\t9\t5001\t-\n'; } > $r/rtl_cost.tsv
# Cortex-M figures (what bench/cortexm/cortexm.sh leaves in arm.tsv; these
# from a full run) for the visibility kernels, so that the interactive
# chooser has targets whose answer is fixed point (tests/report/chooser_check.js)
awk '{ split("fx-m0cyc fxfast-m0cyc f32soft-m0cyc fx-mca fxfast-mca f32soft-mca f32fpu-mca", w, " ")
       for (i = 1; i <= 7; i++) print w[i], $1, (i <= 3 ? "cortex-m0" : "cortex-m4"), $(i + 1), "fixture" }' > $r/arm.tsv <<'EOF'
smith_vis 2141.8 461.0 9115.5 367.3 126.0 2851.5 144.0
smith_vis_fit 1845.8 384.5 4249.8 546.5 133.1 1521.0 98.0
EOF
if build/facet-bench report $r --quick > $r.log 2>&1; then ok; else bad "facet-bench report --quick failed (log $r.log)"; fi
n=$(grep -c '^<h1>Benchmarks (bench/)' $r/index.html)
[ "$n" -eq 1 ] && ok || bad "index.html has $n Benchmarks sections, want 1"
[ "$(grep -c '^<h1>facet report' $r/index.html)" -eq 1 ] && ok || bad "index.html lacks the accuracy part"
cmp -s $r/report.md $r/report.md.full && bad "report.md not rewritten by the quick run" || ok
# the accuracy part's head (title, machine) opens the report, its tables close it
{ awk '/^## /{exit} {print}' $r/accuracy.md; cat $r/bench.md; printf '\n# Accuracy (tests/report/report.sh)\n\n'
  awk 'f || /^## /{f = 1; print}' $r/accuracy.md; } | cmp -s - $r/report.md && ok ||
    bad "report.md is not accuracy.md's head + this run's bench.md + accuracy.md's tables"
# the page opens with the chooser: it comes before every other section
first=$(grep -m1 -n '^<h2>' $r/index.html | cut -d: -f2-)
[ "$first" = "<h2>Which one to use</h2>" ] && ok || bad "index.html's first section is '$first', not the chooser"
grep -q '^# Benchmarks (bench/), QUICK RUN$' $r/report.md && ok || bad "report.md not labelled as a quick run"
grep -q '<title>facet report (quick run)</title>' $r/index.html && grep -q '^<h1>Benchmarks (bench/), QUICK RUN</h1>$' $r/index.html &&
    ok || bad "index.html not labelled as a quick run"
rm -f $r/report.md.full
if command -v python3 >/dev/null 2>&1; then
    python3 - "$r/index.html" <<'PY' && ok || bad "report index.html: labels outside their figure, an inf or nan coordinate, or not UTF-8"
import re, sys
s = open(sys.argv[1], encoding="utf-8").read()  # raises on invalid UTF-8
figs = re.findall(r'<svg xmlns="http://www.w3.org/2000/svg" width="(\d+)" height="(\d+)"(.*?)</svg>', s, re.S)
assert len(figs) >= 8, len(figs)
assert not re.search(r' (?:x|y|cx|cy|x1|x2|y1|y2|points)="[^"]*(?:inf|nan)', s, re.I), "an inf or nan coordinate"
for w, h, body in figs:
    for x, y in re.findall(r'<text x="(-?[0-9.]+)" y="(-?[0-9.]+)"', body):
        assert -1 <= float(x) <= int(w) + 1 and -1 <= float(y) <= int(h) + 1, (x, y, w, h)
PY
fi
for row in '| f32 scalar | oracle |' '| fx (Q15 dots) | oracle |' '| fx_fast (Q15 dots) | oracle |' \
           '| f16 scalar (binary16 dots, alpha >= 2^-7) | oracle |' '| fx_fast (Q15 dots, alpha >= 2^-7) | oracle |' \
           '| model: exact-Vis BRDF | brdf_hammon oracle |'; do
    grep -qF "$row" $r/bench.md && ok || bad "image-space table lacks the row '$row'"
done
# the speed section's binary16 table on the Arm ports and RVV: the
# fixture's A55 cycles and RVV instructions, f16 against both tiers,
# brdf_hammon's target judged
grep -qF '| brdf_hammon | 53.0 / 47.1 / 35.1 = 1.51x / 1.34x | - | - | 53.9 / 49.9 / 38.0 = 1.42x / 1.31x | **missed** |' $r/bench.md && ok ||
    bad "speed: no binary16 row for brdf_hammon on the A55 model with its 1.7x target"
# the chooser's Arm vector targets: NEON costed in its one unit (modelled
# cycles; the qemu-insn line must not leak in), Helium (its counts and its
# modelled cycles) with the reason it was not costed; and without
# arm_vec.status the report says why
awk '/^### whole BRDF/ { f = 1 } f && /^\| NEON \(aarch64, Cortex-A57 model\) \| 3 \|/ { print; exit }' $r/bench.md |
    grep -q '<= 43.2 cyc (llvm-mca A57 model): <b>brdf_hammon f32_fast</b>' && ok ||
    bad "chooser: no NEON row for brdf_hammon with its llvm-mca cost (whole BRDF table)"
awk '/^### whole BRDF/ { f = 1 } f && /^\| Helium \(Cortex-M55\) \| 0 \| not costed: skipped: a 60-bench fixture reason \|/ { g = 1 } END { exit !g }' $r/bench.md &&
    ok || bad "chooser: no Helium row stating why it was not costed"
awk '/^### whole BRDF/ { f = 1 } f && /^\| Helium \(Cortex-M55, llvm-mca-16 model\) \| 0 \| not costed: skipped: a 60-bench fixture reason \|/ { g = 1 } END { exit !g }' $r/bench.md &&
    ok || bad "chooser: no row for Helium's modelled cycles stating why it was not costed"
grep -q 'Helium: skipped: a 60-bench fixture reason' $r/bench.md && ok || bad "chooser: the Helium status is not stated"
# binary16 in the chooser: NEON lists its f16 table's candidates (the
# fixture's), AVX2 says it has no binary16 arithmetic, Helium why it has no
# f16 rows; and the f16 candidate is in the Visibility table's NEON row
grep -qF '| NEON (aarch64, Cortex-A57 model) | listed: the neonfp16 table |' $r/bench.md && ok ||
    bad "chooser: the NEON target does not list its f16 table"
grep -qF '| AVX2 (this machine) | not listed: no binary16 arithmetic (' $r/bench.md && ok ||
    bad "chooser: the AVX2 target does not say it has no binary16 arithmetic"
grep -qF '| Helium (Cortex-M55) | not listed: no f16 port yet (a 60-bench fixture) |' $r/bench.md && ok ||
    bad "chooser: the Helium target does not say why it has no f16 rows"
awk '/^### visibility/ { f = 1 } f && /^\| NEON \(aarch64, Cortex-A57 model\) \|/ { print; exit }' $r/bench.md |
    grep -q '<= 3 cyc (llvm-mca A57 model): <b>smith_vis f16</b>' && ok ||
    bad "chooser: no f16 candidate in the visibility table's NEON row"
# the chooser's hardware target: gate equivalents and the clock (or that it
# fits no iCE40), from the RTL cost file; and the hardware section's table
hw='| Hardware (ports/rtl, one sample per clock) | 1 |'
awk -v hw="$hw" '/^### / { t = $0 } t == "### whole BRDF" && index($0, hw) == 1 { print; exit }' $r/bench.md |
    grep -qF '<= 170002 gate eq.: <b>brdf_hammon fx_fast</b> (fits no iCE40)' && ok ||
    bad "chooser: no hardware row for brdf_hammon in gate equivalents (whole BRDF table)"
awk -v hw="$hw" '/^### / { t = $0 } t == "### Fresnel" && index($0, hw) == 1 { print; exit }' $r/bench.md |
    grep -qF '<= 21174 gate eq.: <b>fresnel_schlick fx_fast</b> at 25.6 MHz (iCE40 UP5K)' && ok ||
    bad "chooser: no hardware row for fresnel_schlick with its clock (Fresnel table)"
grep -qF "| brdf_hammon | 49 | 90001 | 170002 | 40 | none | 9001 | 40 | 9 | - | - | - |" $r/bench.md &&
    grep -qF "| anchor: log-domain Phong shading engine (Lai, Yu, Chen, ISCAS 2002) |" $r/bench.md && ok ||
    bad "hardware section: no row for the fixture's brdf_hammon, or no anchor"
# the menu's variants in image space: one row per variant (the variants the
# report's per-kernel table names, bench/report/kernel_facts.c), numbers in
# every measured cell, no inf or nan, a model error wherever the variant
# approximates a reference, and the labelled figure of the model rows
sed -n '/^### The menu.s variants in image space/,/^#/p' $r/bench.md > $r/variants.md
build/facet-bench report --facts | awk -F '\t' '$1 == "variant" { print $3 }' > $r/variants.want
[ "$(wc -l < $r/variants.want)" -ge 30 ] && ok || bad "facet-bench report --facts lists $(wc -l < $r/variants.want) image-space variants"
while IFS= read -r v; do
    grep -qF "| $v | " $r/variants.md && ok || bad "image-space variants: no row for '$v'"
done < $r/variants.want
cell='[0-9]+ / [0-9]+ / [0-9]+\.[0-9][0-9][0-9] \([0-9]+\.[0-9][0-9]\)' # (no {n}: mawk has none)
# columns: variant, term, f32, f32_fast, fx, fx_fast, model against, model error
CELL="^$cell\$" awk 'BEGIN { c = ENVIRON["CELL"] } /^\| / && !/^\| variant / && !/^\|---/ {
        sub(/^\| /, ""); sub(/ \|$/, ""); n = split($0, f, / \| /)
        if (n != 8) { print "columns: " $0; bad = 1 }
        for (i = 3; i <= 6; i++) if (f[i] != "-" && f[i] !~ c) { print "cell: " $0; bad = 1 }
        if (f[7] != "-") { refs++; if (f[8] ~ c || f[8] == "0 (the reference)") mods++; else { print "model: " $0; bad = 1 } }
        else if (f[8] != "-") { print "model without reference: " $0; bad = 1 } }
    END { if (refs < 20) { print refs " rows with a reference, want >= 20"; bad = 1 } exit bad }' $r/variants.md > $r/variants.bad &&
    ok || { head -3 $r/variants.bad; bad "image-space variants: a malformed row (above)"; }
grep -qiE '(^|[^a-z])(inf|nan)([^a-z]|$)' $r/variants.md && bad "image-space variants: inf or nan in the table" || ok
grep -qE '^\| smith_vis_hammon \| Vis \| '"$cell"' \| '"$cell"' \| '"$cell"' \| '"$cell"' \|' $r/variants.md && ok ||
    bad "image-space variants: smith_vis_hammon lacks its f32, f32_fast, fx and fx_fast cells"
grep -q '<b>Model error in image space: each variant against its exact reference.</b>' $r/index.html && ok ||
    bad "no labelled figure of the variants' model error"
[ -s $r/image_variants_model.png ] && ok || bad "no image_variants_model.png"
# white furnace: Lambert's directional albedo is 1 (to the quadrature's 2e-4)
grep -qE '^\| lambert \| any \| 1\.000[0-9] \| 1\.000[0-9] \| 1\.000[0-9] \|' $r/bench.md && ok ||
    bad "white furnace: Lambert's albedo is not 1"
grep -qE '^\| diffuse_hammon \| 0\.3 \| ' $r/bench.md && ok || bad "white furnace: no diffuse_hammon row"
# the report's per-kernel table (bench/report/kernel_facts.c: each kernel's
# term, exact form or model, image-space variants) has one entry per kernel
# of the list: the check passes on the library's list and fails on a list
# with a kernel it has no entry for, or without one it has
kernels=$(build/facet list | grep -v -- '->' | awk '{ print $1 }')
build/facet-bench report --facts > /dev/null 2>&1 && ok || bad "facet-bench report --facts: the table does not match the kernel list"
# shellcheck disable=SC2086
build/facet-bench report --facts $kernels > /dev/null 2>&1 && ok || bad "facet-bench report --facts KERNELS... fails on the list itself"
# shellcheck disable=SC2086
build/facet-bench report --facts $kernels no_such_kernel > /dev/null 2> $r.facts.err; rc=$?
[ $rc -eq 1 ] && grep -q 'no entry for kernel no_such_kernel' $r.facts.err && ok ||
    bad "a kernel without an entry in kernel_facts.c passes the check (exit $rc)"
# shellcheck disable=SC2086
build/facet-bench report --facts $(printf '%s\n' $kernels | sed 1d) > /dev/null 2> $r.facts.err; rc=$?
[ $rc -eq 1 ] && grep -q 'which the kernel list lacks' $r.facts.err && ok ||
    bad "an entry for a kernel the list lacks passes the check (exit $rc)"
# the speed table (bench/report/sec_speed.c, from the report run's own
# interleaved speed run): a brdf_hammon row per x86 width this CPU runs with
# its targets beside the ratios, and the vector ports' table from the
# fixture's NEON costs (Helium skipped, no RVV: "-")
grep -q '^## Speed: both f32 tiers against the same-formula peers (interleaved rounds)$' $r/bench.md && ok ||
    bad "no speed section in bench.md"
for w in avx2 avx512; do
    build/facet eval --help | sed -n 's/^ports compiled in://p' | sed 's/[a-z0-9]* (not on this CPU)//g' | grep -qw $w || continue
    grep -qE "^\| brdf_hammon \| [0-9]+ / [0-9]+ \| $w \| [0-9.]+ \([0-9.]+\) \| [0-9.]+ \([0-9.]+\) \| [0-9.]+ \([0-9.]+\) \| [0-9.]+ \([0-9.]+\) \| [0-9.]+x \(>= 1\.30x: (met|\*\*missed\*\*)\) \|" $r/bench.md &&
        ok || bad "speed table: no brdf_hammon $w row with the 1.3x target"
done
# binary16 in the same rounds, where this CPU runs an f16 table of its own
# (the bench rows of the same run say whether it does)
if grep -q '^| brdf_hammon | f16 | avx512fp16 | batch |' $r/bench.md; then
    # f16, f32, f32_fast, the binary16 transcription (shader_f16_fm), then
    # the ratios with issue 22's targets, the errors (the transcription's inf)
    grep -qE '^\| brdf_hammon \| avx512fp16 \(avx512\) \| [0-9.]+ \([0-9.]+\) \| [0-9.]+ \([0-9.]+\) \| [0-9.]+ \([0-9.]+\) \| [0-9.]+ \([0-9.]+\) \| [0-9.]+x \(>= 2\.50x: (met|\*\*missed\*\*)\) \| [0-9.]+x \| [0-9.]+x \(>= 0\.60x: (met|\*\*missed\*\*)\) \| [0-9.e-]+ \(0\.0037\) / (inf|[0-9.e-]+) \|$' $r/bench.md &&
        ok || bad "speed table: no brdf_hammon f16 row for avx512fp16 with the binary16 transcription and the targets"
fi
grep -qE '^\| brdf_hammon \| [0-9]+ / [0-9]+ \| 44\.5 / 43\.2 = 1\.03x \| - \| 53\.9 / 49\.9 = 1\.08x \| met \|$' $r/bench.md && ok ||
    bad "speed table: no vector-port row for brdf_hammon from the NEON and RVV fixtures"
# the measured set: a report rendered from the set the quick run recorded
# (--replay OUTDIR/measured.tsv) is the quick run's report, byte for byte
# (a measurement the set does not record would differ: timings vary)
r2=build/bench-suite-replay
rm -rf $r2 && mkdir -p $r2
cp $r/accuracy.md $r/arm_vec.tsv $r/arm_vec.status $r/rtl_cost.tsv $r/arm.tsv $r2/
if build/facet-bench report $r2 --replay $r/measured.tsv > $r2.log 2>&1; then ok; else bad "facet-bench report --replay failed (log $r2.log)"; fi
for f in bench.md report.md index.html choose.tsv sampling.svg image_variants_model.png raster_oracle.png; do
    cmp -s $r/$f $r2/$f && ok || bad "the replayed report's $f differs from the recorded run's"
done
# the report in a browser: no missing image, no script error; screenshot
run_one report-browser sh tests/report/report_browser.sh $r
echo "bench: $pass passed, $fail failed, 0 skipped"
