// browser.js - loads a report page in Debian's headless chromium through
// puppeteer-core and prints one verdict line:
//   images N shown M errors K[: what]
// Every <img> must have loaded with a width, every SVG <image>'s data must
// decode, and no script error or unhandled rejection may occur (recorded
// from before the page's first script runs).  Nothing here waits for a
// time: the page's load event and the image decodes are awaited as
// events, so a loaded machine makes the check slower, never different.
// Only a hang stops it (FACET_BROWSER_HANG seconds, default 900, then exit
// 3 with "hang").
//   node tests/report/browser.js PAGE.html [--screenshot OUT.png]
//        [--script MODULE.js]   (a test module: exports async run(page, log)
//                                returning a list of failure strings)
// Exit 0: clean; 1: the page is not clean; 2: usage; 3: hang or no browser.
'use strict';
const path = require('path');
const fs = require('fs');

function usage() {
    console.error('usage: node browser.js PAGE.html [--screenshot OUT.png] [--script MODULE.js]');
    process.exit(2);
}

const args = process.argv.slice(2);
let page_file = null, shot = null, script = null;
for (let i = 0; i < args.length; i++) {
    if (args[i] === '--screenshot') shot = args[++i];
    else if (args[i] === '--script') script = args[++i];
    else if (!page_file) page_file = args[i];
    else usage();
}
if (!page_file || !fs.existsSync(page_file)) usage();

const hang_s = Number(process.env.FACET_BROWSER_HANG || 900);
const watchdog = setTimeout(() => {
    console.log('hang: no verdict after ' + hang_s + ' s');
    process.exit(3);
}, hang_s * 1000);

let puppeteer;
try {
    puppeteer = require('puppeteer-core');
} catch (e) {
    console.log('no puppeteer-core: ' + e.message);
    process.exit(3);
}

const browser_path = process.env.FACET_CHROMIUM || '/usr/bin/chromium';

(async () => {
    const profile = fs.mkdtempSync(path.join(require('os').tmpdir(), 'facet-chromium-'));
    const browser = await puppeteer.launch({
        executablePath: browser_path,
        headless: true,
        userDataDir: profile,
        protocolTimeout: 0, // no time limit on a protocol call: the watchdog is the only one
        timeout: 0, // nor on the browser's start (puppeteer's default is 30 s: a loaded machine exceeds it)
        args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
               '--disable-background-networking', '--disable-component-update', '--disable-sync',
               '--disable-default-apps', '--hide-scrollbars', '--window-size=1280,4000'],
    });
    const errs = [];
    let verdict_ok = false;
    try {
        const page = await browser.newPage();
        page.setDefaultTimeout(0);
        page.setDefaultNavigationTimeout(0);
        await page.setViewport({ width: 1280, height: 4000 });
        page.on('pageerror', (e) => errs.push('script error: ' + String(e.message || e).split('\n')[0]));
        page.on('requestfailed', (r) => errs.push('not loaded: ' + r.url().slice(0, 60)));
        await page.evaluateOnNewDocument(() => {
            window.addEventListener('unhandledrejection', (e) => {
                (window.__facet_errs = window.__facet_errs || []).push('unhandled rejection: ' + e.reason);
            });
            window.addEventListener('error', (e) => {
                const t = e.target;
                if (t && t !== window && t.tagName)
                    (window.__facet_errs = window.__facet_errs || []).push('not loaded: <' + t.tagName.toLowerCase() + '> ' +
                        String(t.getAttribute('src') || t.getAttribute('href') || '').slice(0, 60));
            }, true);
        });
        await page.goto('file://' + path.resolve(page_file), { waitUntil: 'load', timeout: 0 });
        const r = await page.evaluate(async () => {
            const out = { n: 0, shown: 0, errs: (window.__facet_errs || []).slice() };
            const im = Array.from(document.images);
            const sv = Array.from(document.getElementsByTagName('image'));
            out.n = im.length + sv.length;
            for (const i of im) {
                try { await i.decode(); } catch (e) { /* judged below */ }
                if (i.complete && i.naturalWidth > 0) out.shown++;
                else out.errs.push('image not shown: <img> ' + (i.alt || String(i.src).slice(0, 60)));
            }
            for (const s of sv) {
                const href = s.getAttribute('href') || s.getAttribute('xlink:href') || '';
                const t = new Image();
                t.src = href;
                try {
                    await t.decode();
                    if (t.naturalWidth > 0) out.shown++;
                    else out.errs.push('image not shown: <image> (empty) ' + href.slice(0, 60));
                } catch (e) {
                    out.errs.push('image not shown: <image> ' + href.slice(0, 60));
                }
            }
            return out;
        });
        const all = errs.concat(r.errs);
        if (script) {
            const mod = require(path.resolve(script));
            const f = await mod.run(page, (s) => console.log(s));
            for (const x of f) all.push(x);
        }
        console.log('images ' + r.n + ' shown ' + r.shown + ' errors ' + all.length + (all.length ? ': ' + all.join('; ') : ''));
        verdict_ok = r.n > 0 && all.length === 0;
        if (shot) await page.screenshot({ path: shot, clip: { x: 0, y: 0, width: 1280, height: 4000 } });
    } finally {
        await browser.close();
        fs.rmSync(profile, { recursive: true, force: true });
        clearTimeout(watchdog);
    }
    process.exit(verdict_ok ? 0 : 1);
})().catch((e) => {
    console.log('browser failed: ' + String(e && e.message || e).split('\n')[0]);
    process.exit(3);
});
