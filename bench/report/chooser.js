// chooser.js - the interactive chooser at the top of index.html, inlined by
// bench/report/sec_choose.c after the data it reads (the JSON element
// #facet-choose-data: targets (each with the binary16 table its f16
// candidates come from, or why it has none), terms, kernels' inputs, and
// per target and term every candidate [target, term, kernel, format, cost,
// impl, model]; format f32, f32_fast, fx, fx_fast or f16).
// No network, no framework.  Without script the page shows the static
// tables that follow (the same candidates).
//
// The rule (what tests/report/chooser_check.js checks, with its own code,
// against OUTDIR/choose.tsv):
//   total error = implementation error + model error (model error 0 for an
//     exact kernel, left out (< 0) for a model of its own);
//   a need of b output bits is a total error <= 2^-b; float is <= 2^-20;
//     or a maximum total error given;
//   the candidates: the chosen variant's, or with "any" every candidate of
//     the term that approximates its exact form (model >= 0);
//   recommended: the cheapest that meets the need (ties: less error, then
//     the data's order); none meets it: the most accurate is shown as such;
//   next cheaper: of the cheaper ones, the most accurate (ties: cheaper);
//   next more accurate: of the more accurate ones, the cheapest (ties: less
//     error).
(function () {
    'use strict';
    var src = document.getElementById('facet-choose-data');
    var root = document.getElementById('facet-chooser');
    if (!src || !root) return;
    var D = JSON.parse(src.textContent);
    var NEEDS = [
        ['8', '8-bit output (total error <= 2^-8)', Math.pow(2, -8)],
        ['10', '10-bit output (<= 2^-10)', Math.pow(2, -10)],
        ['12', '12-bit output (<= 2^-12)', Math.pow(2, -12)],
        ['float', 'float output (<= 2^-20, a few f32 ulps)', Math.pow(2, -20)],
        ['max', 'a maximum total error:', null]
    ];
    var FORMAT = {
        f32: ['f32', 'precise'], f32_fast: ['f32', 'fast'],
        fx: ['fixed point', 'precise'], fx_fast: ['fixed point', 'fast'],
        f16: ['binary16', 'one']
    };
    var COLOUR = { f32: '#1f6feb', f32_fast: '#8250df', fx: '#bf8700', fx_fast: '#cf222e', f16: '#0a7ea4' };
    var SVGNS = 'http://www.w3.org/2000/svg';

    function el(tag, attrs, text) {
        var e = document.createElement(tag);
        for (var k in attrs) e.setAttribute(k, attrs[k]);
        if (text !== undefined) e.textContent = text;
        return e;
    }
    function sv(tag, attrs, text) {
        var e = document.createElementNS(SVGNS, tag);
        for (var k in attrs) e.setAttribute(k, attrs[k]);
        if (text !== undefined) e.textContent = text;
        return e;
    }
    function g3(x) {
        if (!isFinite(x)) return 'inf';
        return Number(x.toPrecision(3)).toString();
    }
    function total(c) { return (c.model > 0 ? c.model : 0) + c.impl; }

    // the candidates of target t, term g, variant v ('' = any approximation)
    function candidates(t, g, v) {
        var out = [];
        D.cands.forEach(function (a, i) {
            if (a[0] !== t || a[1] !== g) return;
            var c = { i: i, kernel: a[2], format: a[3] /*facet-format*/, cost: a[4], impl: a[5], model: a[6] };
            c.err = total(c);
            if (v ? c.kernel === v : D.terms[g].ref && c.model >= 0) out.push(c);
        });
        return out;
    }
    function by_cost(a, b) { return a.cost - b.cost /*facet-rule*/ || a.err - b.err || a.i - b.i; }
    function by_err(a, b) { return a.err - b.err || a.cost - b.cost || a.i - b.i; }
    function choose(list, need) {
        var ok = list.filter(function (c) { return c.err <= need; }).sort(by_cost);
        var r = { rec: ok.length ? ok[0] : null, none: !ok.length, cheaper: null, better: null };
        if (!r.rec && list.length) r.rec = list.slice().sort(by_err)[0];
        if (!r.rec) return r;
        var rec = r.rec;
        r.cheaper = list.filter(function (c) { return c.cost < rec.cost; }).sort(by_err)[0] || null;
        r.better = list.filter(function (c) { return c.err < rec.err; }).sort(by_cost)[0] || null;
        return r;
    }

    // the code line that calls candidate c on target t
    function code_line(c, t) {
        var ins = D.kernels[c.kernel] || [];
        if (c.format === 'f16')
            return '#include <facet/f16.h>\n' +
                '/* binary16 bit patterns (uint16_t, facet_f16): in from floats with ' +
                'facet_f16_from_f32_batch(h, x, n), out with facet_f32_from_f16_batch(x, h, n) */\n' +
                'facet_' + c.kernel + '_f16_batch(out, ' + ins.join(', ') + ', n);  /* arrays of n uint16_t; ' +
                'the dispatcher picks the ' + (D.targets[t].f16port || 'f16') + ' table on such a CPU */';
        var fx = c.format.slice(0, 2) === 'fx';
        var hdr = fx ? '#include <facet/fx.h>' : '#include <facet.h>';
        if (D.targets[t].path === 'call')
            return hdr + '\n' + 'out = facet_' + c.kernel + '_' + c.format + '(' + ins.join(', ') + ');' +
                (fx ? '  /* fixed-point inputs: formats in facet/fx.h */' : '');
        return hdr + '\n' + 'facet_' + c.kernel + '_' + c.format + '_batch(out, ' +
            ins.join(', ') + ', n);  /* arrays of n' + (fx ? ' fixed-point values' : ' floats') +
            '; the dispatcher picks the ' + D.targets[t].port + ' port on such a CPU */';
    }
    function describe(c, t) {
        var f = FORMAT[c.format] || [c.format, ''];
        var tg = D.targets[t];
        return c.kernel + ', ' + f[0] + ', ' + f[1] + ' tier (' + c.format + '): ' + g3(c.cost) + ' ' + tg.unit +
            (tg.path === 'call' ? ' per call' : ' per sample') + '; implementation error ' + g3(c.impl) +
            ', model error ' + (c.model < 0 ? 'n/a (a model of its own)' : c.model === 0 ? 'exact' : g3(c.model)) +
            ', total ' + g3(c.err);
    }

    // ---- the form -------------------------------------------------------------
    var css = el('style', {}, '#facet-chooser{border:2px solid #1f6feb;border-radius:6px;padding:12px 16px;' +
        'margin:1em 0;background:#f6f8fa}#facet-chooser label{margin-right:14px;font-size:14px}' +
        '#facet-chooser select,#facet-chooser input{font-size:14px;margin-left:4px}' +
        '#ch-answer{font-size:15px;margin:10px 0}#ch-answer dt{font-weight:bold;margin-top:6px}' +
        '#ch-answer dd{margin-left:1.5em}#ch-code{background:#fff;border:1px solid #ccc;padding:6px 8px;' +
        'font-size:13px;white-space:pre-wrap}#ch-plot text{font-family:sans-serif}');
    document.head.appendChild(css);
    root.appendChild(el('h3', {}, 'Interactive chooser'));
    root.appendChild(el('p', {}, 'Pick a target, a term (or the whole BRDF) and the accuracy you need: the ' +
        'page answers from this report\'s measured costs and errors (the static tables below hold the same data). ' +
        'Total error = implementation error + model error, max relative where the value is >= 2^-8.'));
    var form = el('div', { id: 'ch-form' });
    function select(id, label) {
        var l = el('label', {}, label);
        var s = el('select', { id: id });
        l.appendChild(s);
        form.appendChild(l);
        return s;
    }
    var s_target = select('ch-target', 'target');
    var s_term = select('ch-term', 'term');
    var s_variant = select('ch-variant', 'variant');
    var s_need = select('ch-need', 'accuracy');
    var l_max = el('label', {}, 'max total error');
    var i_max = el('input', { id: 'ch-maxerr', type: 'number', step: 'any', min: '0', value: '0.01' });
    l_max.appendChild(i_max);
    form.appendChild(l_max);
    root.appendChild(form);
    var answer = el('dl', { id: 'ch-answer' });
    root.appendChild(answer);
    var plot = el('div', { id: 'ch-plot' });
    root.appendChild(plot);

    D.targets.forEach(function (tg, t) { s_target.appendChild(el('option', { value: String(t) }, tg.name)); });
    D.terms.forEach(function (tm, g) { s_term.appendChild(el('option', { value: String(g) }, tm.title)); });
    NEEDS.forEach(function (n) { s_need.appendChild(el('option', { value: n[0] }, n[1])); });
    function fill_variants() {
        var g = Number(s_term.value), tm = D.terms[g];
        s_variant.textContent = '';
        if (tm.ref) s_variant.appendChild(el('option', { value: '' }, 'any approximation of the exact term'));
        tm.kernels.forEach(function (k) { s_variant.appendChild(el('option', { value: k }, k)); });
    }
    function need_value() {
        var n = NEEDS.filter(function (x) { return x[0] === s_need.value; })[0];
        return n && n[2] !== null ? n[2] : Number(i_max.value);
    }

    // ---- the answer -------------------------------------------------------------
    function entry(id, title, c, t, extra) {
        var dt = el('dt', {}, title), dd = el('dd', { id: id });
        dd.setAttribute('data-kernel', c ? c.kernel : '');
        dd.setAttribute('data-format', c ? c.format : '');
        dd.setAttribute('data-cost', c ? String(c.cost) : '');
        dd.textContent = c ? describe(c, t) + (extra || '') : 'none';
        answer.appendChild(dt);
        answer.appendChild(dd);
        return dd;
    }
    function update() {
        var t = Number(s_target.value), g = Number(s_term.value), v = s_variant.value;
        var need = need_value(), list = candidates(t, g, v), r = choose(list, need);
        l_max.style.display = s_need.value === 'max' ? '' : 'none';
        answer.textContent = '';
        if (!list.length) {
            entry('ch-rec', 'Recommended', null, t);
            answer.appendChild(el('dd', { id: 'ch-note' }, 'No costs for this target and term in this run' +
                (D.targets[t].note ? ': ' + D.targets[t].note : '.')));
            draw([], r, need, t, g);
            return;
        }
        var rec = entry('ch-rec', r.none ? 'Nothing meets a total error <= ' + g3(need) + '; the most accurate'
            : 'Recommended (total error <= ' + g3(need) + ')', r.rec, t);
        rec.setAttribute('data-none', r.none ? '1' : '0');
        var path = D.targets[t].path === 'call' ? 'per-sample call, the portable C (the firmware build) on ' +
            D.targets[t].name : 'batch, ' + D.targets[t].port + ' port';
        answer.appendChild(el('dt', {}, 'Path'));
        answer.appendChild(el('dd', { id: 'ch-path' }, path));
        answer.appendChild(el('dt', {}, 'Code'));
        var dd = el('dd', {});
        dd.appendChild(el('pre', { id: 'ch-code' }, code_line(r.rec, t)));
        answer.appendChild(dd);
        entry('ch-cheaper', 'Next cheaper (less accurate)', r.cheaper, t);
        entry('ch-better', 'Next more accurate (costlier)', r.better, t);
        if (D.targets[t].f16) {
            answer.appendChild(el('dt', {}, 'Binary16 (f16)'));
            answer.appendChild(el('dd', { id: 'ch-f16' }, 'not listed on this target: ' + D.targets[t].f16));
        }
        draw(list, r, need, t, g);
    }

    // ---- the Pareto plot of this term and target ---------------------------------
    var W = 1100, H = 560, L = 90, R = 250, T = 36, B = 64;
    var FLOOR = 1e-8, CEIL = 2.5;
    function clampe(e) { return e < FLOOR ? FLOOR : e > CEIL ? CEIL : e; }
    function draw(list, r, need, t, g) {
        plot.textContent = '';
        var s = sv('svg', { xmlns: SVGNS, width: W, height: H, 'font-size': '13' });
        plot.appendChild(s);
        var pw = W - L - R, ph = H - T - B;
        var lo = Infinity, hi = -Infinity;
        list.forEach(function (c) { lo = Math.min(lo, c.cost); hi = Math.max(hi, c.cost); });
        if (!list.length) { lo = 1; hi = 10; }
        var x0 = Math.floor(Math.log10(lo) - 0.1), x1 = Math.ceil(Math.log10(hi) + 0.1);
        if (x1 <= x0) x1 = x0 + 1;
        var y0 = -8, y1 = 0.5;
        function X(v) { return L + (Math.log10(v) - x0) / (x1 - x0) * pw; }
        function Y(e) { return T + ph - (Math.log10(clampe(e)) - y0) / (y1 - y0) * ph; }
        s.appendChild(sv('text', { x: L, y: 20, 'font-weight': 'bold', 'font-size': '15' },
            'Pareto: ' + D.terms[g].title + ' on ' + D.targets[t].name));
        s.appendChild(sv('rect', { x: L, y: T, width: pw, height: ph, fill: '#fff', stroke: '#888' }));
        var k, px, py;
        // 10^k as a superscript
        function pow_text(attrs, k, before) {
            var e = sv('text', attrs, (before || '') + '10');
            e.appendChild(sv('tspan', { dy: '-6', 'font-size': '10' }, String(k)));
            return e;
        }
        for (k = x0; k <= x1; k++) {
            px = X(Math.pow(10, k));
            s.appendChild(sv('line', { x1: px, x2: px, y1: T, y2: T + ph, stroke: '#ddd' }));
            s.appendChild(sv('line', { x1: px, x2: px, y1: T + ph, y2: T + ph + 6, stroke: '#444' }));
            s.appendChild(pow_text({ x: px, y: T + ph + 22, 'text-anchor': 'middle' }, k));
            // over a few decades, 2 and 5 of each labelled too
            if (k < x1 && x1 - x0 <= 3)
                [2, 5].forEach(function (m) {
                    var v = m * Math.pow(10, k), q = X(v);
                    s.appendChild(sv('line', { x1: q, x2: q, y1: T, y2: T + ph, stroke: '#f0f0f0' }));
                    s.appendChild(sv('line', { x1: q, x2: q, y1: T + ph, y2: T + ph + 4, stroke: '#444' }));
                    s.appendChild(sv('text', { x: q, y: T + ph + 18, 'text-anchor': 'middle', 'font-size': '11' },
                        String(Number(v.toPrecision(1)))));
                });
        }
        for (k = y0; k <= 0; k++) {
            py = Y(Math.pow(10, k));
            s.appendChild(sv('line', { x1: L, x2: L + pw, y1: py, y2: py, stroke: '#ddd' }));
            s.appendChild(sv('line', { x1: L - 6, x2: L, y1: py, y2: py, stroke: '#444' }));
            s.appendChild(pow_text({ x: L - 9, y: py + 4, 'text-anchor': 'end' }, k, k === y0 ? '<= ' : ''));
        }
        s.appendChild(sv('text', { x: L + pw / 2, y: H - 18, 'text-anchor': 'middle', 'font-style': 'italic' },
            'cost, ' + D.targets[t].unit + (D.targets[t].path === 'call' ? ' per call' : ' per sample') + ' (log)'));
        s.appendChild(sv('text', { x: 18, y: T + ph / 2, 'text-anchor': 'middle', 'font-style': 'italic',
            transform: 'rotate(-90 18 ' + (T + ph / 2) + ')' }, 'total error, max relative (log)'));
        // the need
        py = Y(need);
        s.appendChild(sv('line', { x1: L, x2: L + pw, y1: py, y2: py, stroke: '#cf222e', 'stroke-dasharray': '6,4' }));
        s.appendChild(sv('text', { x: L + pw - 4, y: py - 5, 'text-anchor': 'end', fill: '#cf222e' },
            'need: total error <= ' + g3(need)));
        if (!list.length) {
            s.appendChild(sv('text', { x: L + pw / 2, y: T + ph / 2, 'text-anchor': 'middle', fill: '#888' },
                'no costs for this target and term in this run'));
            return;
        }
        // the frontier: by cost, each candidate that lowers the least error so far
        var sorted = list.slice().sort(by_cost), best = Infinity, pts = [], front = [];
        sorted.forEach(function (c) {
            if (c.err < best) {
                if (best < Infinity) pts.push([X(c.cost), Y(best)]);
                best = c.err;
                pts.push([X(c.cost), Y(best)]);
                front.push(c);
            }
        });
        pts.push([L + pw, Y(best)]);
        s.appendChild(sv('polyline', { points: pts.map(function (p) { return p[0].toFixed(1) + ',' + p[1].toFixed(1); }).join(' '),
            fill: 'none', stroke: '#2da44e', 'stroke-width': '2' }));
        list.forEach(function (c) {
            var d = sv('circle', { 'class': 'pt', cx: X(c.cost).toFixed(1), cy: Y(c.err).toFixed(1), r: 6,
                fill: COLOUR[c.format] || '#444', 'fill-opacity': '0.8', stroke: '#fff' });
            d.appendChild(sv('title', {}, c.kernel + ' ' + c.format + ': ' + g3(c.cost) + ' ' + D.targets[t].unit +
                ', total error ' + g3(c.err) + ' (impl. ' + g3(c.impl) + ', model ' +
                (c.model < 0 ? 'n/a' : c.model === 0 ? 'exact' : g3(c.model)) + ')'));
            s.appendChild(d);
        });
        front.forEach(function (c, n) {
            s.appendChild(sv('text', { x: (X(c.cost) + 9).toFixed(1), y: (Y(c.err) - 8 - (n % 2) * 12).toFixed(1),
                'font-size': '11', fill: '#1a7f37' }, c.kernel + ' ' + c.format));
        });
        if (r.rec) {
            var m = sv('circle', { 'class': 'rec', cx: X(r.rec.cost).toFixed(1), cy: Y(r.rec.err).toFixed(1), r: 12,
                fill: 'none', stroke: '#000', 'stroke-width': '3' });
            m.appendChild(sv('title', {}, (r.none ? 'the most accurate: ' : 'recommended: ') + r.rec.kernel + ' ' + r.rec.format));
            s.appendChild(m);
        }
        // the legend, right of the plot
        var ly = T + 10, lx = L + pw + 20;
        Object.keys(COLOUR).forEach(function (f) {
            s.appendChild(sv('circle', { cx: lx, cy: ly, r: 6, fill: COLOUR[f] }));
            s.appendChild(sv('text', { x: lx + 12, y: ly + 4 }, f + ' (' + FORMAT[f].join(', ') + ')'));
            ly += 22;
        });
        s.appendChild(sv('line', { x1: lx - 6, x2: lx + 6, y1: ly, y2: ly, stroke: '#2da44e', 'stroke-width': '2' }));
        s.appendChild(sv('text', { x: lx + 12, y: ly + 4 }, 'frontier (labelled)'));
        ly += 22;
        s.appendChild(sv('circle', { cx: lx, cy: ly, r: 9, fill: 'none', stroke: '#000', 'stroke-width': '3' }));
        s.appendChild(sv('text', { x: lx + 14, y: ly + 4 }, r.none ? 'the most accurate' : 'recommended'));
        ly += 22;
        s.appendChild(sv('line', { x1: lx - 6, x2: lx + 6, y1: ly, y2: ly, stroke: '#cf222e', 'stroke-dasharray': '6,4' }));
        s.appendChild(sv('text', { x: lx + 12, y: ly + 4 }, 'the need'));
        s.appendChild(sv('text', { x: lx - 6, y: ly + 28, 'font-size': '11', fill: '#555' }, 'hover a point: its name'));
    }

    s_target.addEventListener('change', update);
    s_term.addEventListener('change', function () { fill_variants(); update(); });
    s_variant.addEventListener('change', update);
    s_need.addEventListener('change', update);
    i_max.addEventListener('input', update);
    fill_variants();
    update();
    root.hidden = false;
})();
