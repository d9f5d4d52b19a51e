// chooser_check.js - a test module for browser.js (--script): drives the
// interactive chooser at the top of index.html and checks its answers
// against the report's own data, computed here, independently of the
// page's script, from OUTDIR/choose.tsv (bench/report/sec_choose.c writes
// it from the same candidates as the page's JSON; the page's copy is not
// read).  The rule is the one bench/report/chooser.js states; this file
// implements it again with its own loops.
//
// Cases: for every target, term, variant ("any" where the term has an exact
// form, else each kernel) and need (8, 10, 12 bits, float), the expected
// answer; the page is asked for the case (with the most candidates) whose
// answer is fixed point, the one whose answer is f32_fast, f32 precise,
// binary16 (f16), the one where nothing meets the need, one with a maximum
// total error typed in, and a term without an exact reference (a variant
// chosen).  Missing a fixed-point, an f32_fast or an f16 case fails (the
// data must have each).  For each: the recommended kernel, format and
// cost, the next cheaper and the next more accurate, the code line (the
// function it calls is declared in include/; an f16 answer's line includes
// facet/f16.h, says its arrays are uint16_t bit patterns and names the
// conversion helpers, declared there too), and the plot (one point per
// candidate, each named on hover, the recommendation marked).  Returns the
// list of failures.
'use strict';
const fs = require('fs');
const path = require('path');
const url = require('url');

const NEED = { '8': Math.pow(2, -8), '10': Math.pow(2, -10), '12': Math.pow(2, -12), float: Math.pow(2, -20) };

function read_tsv(file) {
    const d = { targets: [], terms: [], cands: [] };
    for (const line of fs.readFileSync(file, 'utf8').split('\n')) {
        if (!line || line[0] === '#') continue;
        const f = line.split('\t');
        if (f[0] === 'target') d.targets[Number(f[1])] = { name: f[2], unit: f[3], path: f[4] };
        else if (f[0] === 'term') d.terms[Number(f[1])] = { ref: f[2] === '1', title: f[3], kernels: [] };
        else if (f[0] === 'cand')
            d.cands.push({ t: Number(f[1]), g: Number(f[2]), kernel: f[3], format: f[4], cost: Number(f[5]),
                           impl: Number(f[6]), model: Number(f[7]), i: d.cands.length });
    }
    for (const c of d.cands) {
        c.err = c.impl + (c.model > 0 ? c.model : 0);
        const ks = d.terms[c.g].kernels;
        if (ks.indexOf(c.kernel) < 0) ks.push(c.kernel);
    }
    return d;
}

// the expected answer, by plain loops
function expect(d, t, g, variant, need) {
    const list = [];
    for (const c of d.cands)
        if (c.t === t && c.g === g && (variant ? c.kernel === variant : d.terms[g].ref && c.model >= 0)) list.push(c);
    let rec = null, none = false;
    for (const c of list)
        if (c.err <= need && (!rec || c.cost < rec.cost || (c.cost === rec.cost && c.err < rec.err))) rec = c;
    if (!rec) {
        none = true;
        for (const c of list)
            if (!rec || c.err < rec.err || (c.err === rec.err && c.cost < rec.cost)) rec = c;
    }
    let cheaper = null, better = null;
    if (rec)
        for (const c of list) {
            if (c.cost < rec.cost && (!cheaper || c.err < cheaper.err || (c.err === cheaper.err && c.cost < cheaper.cost)))
                cheaper = c;
            if (c.err < rec.err && (!better || c.cost < better.cost || (c.cost === better.cost && c.err < better.err)))
                better = c;
        }
    return { n: list.length, rec, none, cheaper, better };
}

function same(a, b) { return Math.abs(a - b) <= 1e-12 * Math.max(Math.abs(a), Math.abs(b)); }

async function ask(page, t, g, variant, need, maxerr) {
    await page.select('#ch-target', String(t));
    await page.select('#ch-term', String(g));
    await page.select('#ch-variant', variant);
    await page.select('#ch-need', need);
    if (need === 'max')
        await page.$eval('#ch-maxerr', (e, v) => { e.value = v; e.dispatchEvent(new Event('input')); }, String(maxerr));
    return page.evaluate(() => {
        const q = (id) => document.getElementById(id);
        const one = (id) => {
            const e = q(id);
            return e ? { kernel: e.getAttribute('data-kernel'), format: e.getAttribute('data-format'),
                         cost: e.getAttribute('data-cost'), none: e.getAttribute('data-none') } : null;
        };
        const pts = Array.from(document.querySelectorAll('#ch-plot circle.pt'));
        return {
            rec: one('ch-rec'), cheaper: one('ch-cheaper'), better: one('ch-better'),
            code: q('ch-code') ? q('ch-code').textContent : '',
            points: pts.length,
            named: pts.filter((p) => p.querySelector('title') && p.querySelector('title').textContent.length > 3).length,
            marks: document.querySelectorAll('#ch-plot circle.rec').length,
        };
    });
}

function declared(fn) {
    for (const h of ['include/facet.h', 'include/facet/fx.h', 'include/facet/f16.h'])
        if (fs.existsSync(h) && new RegExp('\\b' + fn + '\\(').test(fs.readFileSync(h, 'utf8'))) return true;
    return false;
}

exports.run = async function (page, log) {
    const fails = [];
    const dir = path.dirname(url.fileURLToPath(page.url()));
    const tsv = path.join(dir, 'choose.tsv');
    if (!fs.existsSync(tsv)) return ['chooser: no ' + tsv];
    const d = read_tsv(tsv);
    const shown = await page.evaluate(() => {
        const r = document.getElementById('facet-chooser');
        return r ? !r.hidden && r.getBoundingClientRect().height > 200 : false;
    });
    if (!shown) return ['chooser: #facet-chooser is not shown'];
    // the cases
    const pick = {};
    d.targets.forEach((tg, t) => d.terms.forEach((tm, g) => {
        const variants = tm.ref ? [''] : tm.kernels;
        for (const v of variants)
            for (const need of Object.keys(NEED)) {
                const e = expect(d, t, g, v, NEED[need]);
                if (!e.rec || e.n < 3) continue;
                const c = { t, g, v, need, e };
                const kind = e.none ? 'nothing meets the need' : e.rec.format.slice(0, 2) === 'fx' ? 'fixed point'
                    : e.rec.format === 'f32_fast' ? 'f32_fast' : e.rec.format === 'f16' ? 'f16' : 'f32';
                // per kind the case with the most candidates (the first of those)
                if (!pick[kind] || e.n > pick[kind].e.n) pick[kind] = c;
                if (!tm.ref && (!pick['a term without a reference'] || e.n > pick['a term without a reference'].e.n))
                    pick['a term without a reference'] = c;
            }
    }));
    for (const k of ['fixed point', 'f32_fast', 'f16'])
        if (!pick[k]) fails.push('chooser: the data has no case whose answer is ' + k);
    // a maximum error typed in: just above the error of the f32_fast case's
    // next cheaper (so the answer moves to a cheaper one)
    if (pick['f32_fast']) {
        const p = pick['f32_fast'], e = expect(d, p.t, p.g, p.v, NEED[p.need]);
        const m = e.cheaper ? e.cheaper.err * 1.01 : e.rec.err * 2;
        pick['a maximum total error'] = { t: p.t, g: p.g, v: p.v, need: 'max', max: Number(m.toPrecision(3)) };
    }
    for (const kind of Object.keys(pick)) {
        const c = pick[kind];
        const need = c.need === 'max' ? c.max : NEED[c.need];
        const e = expect(d, c.t, c.g, c.v, need);
        const what = kind + ': ' + d.targets[c.t].name + ' / ' + d.terms[c.g].title + (c.v ? ' / ' + c.v : '') +
            ' / need ' + c.need + (c.need === 'max' ? ' ' + c.max : '');
        let got;
        try {
            got = await ask(page, c.t, c.g, c.v, c.need, c.max);
        } catch (x) {
            fails.push('chooser: ' + what + ': ' + String(x.message || x).split('\n')[0]);
            continue;
        }
        log('chooser: ' + what + ': page ' + (got.rec ? got.rec.kernel + ' ' + got.rec.format + ' ' + got.rec.cost : '-') +
            ', data ' + e.rec.kernel + ' ' + e.rec.format + ' ' + e.rec.cost);
        const bad = (s) => fails.push('chooser: ' + what + ': ' + s);
        if (!got.rec) { bad('no answer on the page'); continue; }
        if (got.rec.kernel !== e.rec.kernel || got.rec.format !== e.rec.format || !same(Number(got.rec.cost), e.rec.cost))
            bad('recommends ' + got.rec.kernel + ' ' + got.rec.format + ' at ' + got.rec.cost + ', the data says ' +
                e.rec.kernel + ' ' + e.rec.format + ' at ' + e.rec.cost);
        if ((got.rec.none === '1') !== e.none) bad('says nothing meets the need: ' + got.rec.none + ', the data: ' + e.none);
        for (const [name, want] of [['cheaper', e.cheaper], ['better', e.better]]) {
            const g = got[name];
            const gk = g ? g.kernel + ' ' + g.format : '(missing)', wk = want ? want.kernel + ' ' + want.format : ' ';
            if (gk !== wk) bad('next ' + name + ': ' + gk + ', the data says ' + wk);
        }
        const fn = 'facet_' + e.rec.kernel + '_' + e.rec.format + (d.targets[c.t].path === 'batch' ? '_batch' : '');
        if (got.code.indexOf(fn + '(') < 0) bad('the code line does not call ' + fn + ': ' + got.code);
        else if (!declared(fn)) bad(fn + ' is not declared in include/facet.h, include/facet/fx.h or include/facet/f16.h');
        if (e.rec.format === 'f16') {
            if (got.code.indexOf('#include <facet/f16.h>') < 0 || got.code.indexOf('uint16_t') < 0)
                bad('the f16 code line does not include facet/f16.h or does not say the arrays are uint16_t: ' + got.code);
            for (const h of ['facet_f16_from_f32_batch', 'facet_f32_from_f16_batch'])
                if (got.code.indexOf(h + '(') < 0 || !declared(h)) bad('the f16 code line does not name ' + h + ' (declared)');
        }
        if (got.points !== e.n) bad('the plot has ' + got.points + ' points, the data ' + e.n + ' candidates');
        if (got.named !== got.points) bad((got.points - got.named) + ' points are not named on hover');
        if (got.marks !== 1) bad('the plot marks ' + got.marks + ' recommendations');
    }
    if (process.env.FACET_CHOOSER_SHOT && pick['fixed point']) {
        const c = pick['fixed point'];
        await ask(page, c.t, c.g, c.v, c.need);
        const box = await page.$('#facet-chooser');
        await box.screenshot({ path: process.env.FACET_CHOOSER_SHOT });
    }
    return fails;
};
