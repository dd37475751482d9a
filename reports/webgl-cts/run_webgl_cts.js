#!/usr/bin/env node
// Run Khronos WebGL conformance test pages in headless Chromium, one browser launch per
// configuration, and save every result the pages report.
//
// usage: node run_webgl_cts.js --tests SDK_TESTS_DIR --out OUT_DIR --config NAME
//          --pages PAGES_FILE [--flag=--some-chromium-flag ...] [--chromium PATH]
//          [--page-timeout SECONDS] [--idle-timeout SECONDS] [--playwright DIR]
//   SDK_TESTS_DIR  the sdk/tests folder of a KhronosGroup/WebGL checkout (served as is)
//   PAGES_FILE     one page a line, relative to SDK_TESTS_DIR, with its query string
//                  (e.g. conformance2/samplers/samplers.html?webglVersion=2); '#' comments
//   --playwright   a folder whose node_modules holds playwright-core (default: this folder)
// Writes OUT_DIR/<config>/results.json (probe + one entry per page), console.log (the pages'
// console messages) and browser.log (the browser's stderr, each line tagged with the page open).
//
// How results are collected: the pages' js-test-pre.js reports every PASS/FAIL/SKIP to
// `window.parent.webglTestHarness.reportResults(url, success, msg, skipped)` and calls
// `webglTestHarness.notifyFinished(url)` at the end (after printing TEST COMPLETE); the
// official runner (webgl-conformance-tests.html) provides that object from its parent frame.
// Here the page is loaded top-level (so window.parent === window) and an init script defines
// window.webglTestHarness before the page's scripts run: the same calls the official runner
// counts are counted here. dEQP skip-list warnings (not reported to the harness) and the
// "TEST COMPLETE: n PASS, m FAIL" line are read from the DOM at the end.
// Also recorded per page: webglcontextlost events, and browser stderr lines about the GPU process.
// A page ends when it calls notifyFinished, when no result arrives for --idle-timeout seconds
// (the official runner uses 20 s), when it runs --page-timeout seconds, or when it crashes.
'use strict';
// Browser stderr (GPU process exits etc.) is only reachable through playwright's debug log
// 'pw:browser': enable it here and divert those lines from our stderr to OUT_DIR/<config>/browser.log.
process.env.DEBUG = (process.env.DEBUG ? process.env.DEBUG + ',' : '') + 'pw:browser';
const browserLines = { sink: null, page: '(startup)', events: [] };
{
  const origWrite = process.stderr.write.bind(process.stderr);
  process.stderr.write = (chunk, ...rest) => {
    const s = String(chunk);
    if (!s.includes('pw:browser')) return origWrite(chunk, ...rest);
    if (browserLines.sink) browserLines.sink.write(`[${browserLines.page}] ${s.replace(/\n$/, '')}\n`);
    if (/GPU process|GPU state invalid|context lost|lost context|VK_ERROR|DEVICE_LOST|Received signal|segmentation/i.test(s)) {
      browserLines.events.push(s.replace(/^.*?\[err\] /, '').trim().slice(0, 300));
    }
    return true;
  };
}
const fs = require('fs');
const http = require('http');
const path = require('path');

function parseArgs(argv) {
  const a = { flags: [], chromium: 'chromium', pageTimeout: 300, idleTimeout: 120,
              playwright: __dirname };
  for (let i = 0; i < argv.length; i++) {
    const k = argv[i];
    const eq = k.indexOf('=');
    const key = eq > 0 ? k.slice(0, eq) : k;
    const val = () => (eq > 0 ? k.slice(eq + 1) : argv[++i]);
    switch (key) {
      case '--tests': a.tests = path.resolve(val()); break;
      case '--out': a.out = path.resolve(val()); break;
      case '--config': a.config = val(); break;
      case '--pages': a.pages = path.resolve(val()); break;
      case '--flag': a.flags.push(val()); break;
      case '--chromium': a.chromium = val(); break;
      case '--page-timeout': a.pageTimeout = Number(val()); break;
      case '--idle-timeout': a.idleTimeout = Number(val()); break;
      case '--playwright': a.playwright = path.resolve(val()); break;
      default: throw new Error('unknown argument ' + k);
    }
  }
  if (!a.tests || !a.out || !a.config || !a.pages) {
    throw new Error('need --tests, --out, --config and --pages');
  }
  return a;
}

const kTypes = {
  '.html': 'text/html', '.htm': 'text/html', '.js': 'text/javascript', '.css': 'text/css',
  '.json': 'application/json', '.svg': 'image/svg+xml', '.png': 'image/png', '.jpg': 'image/jpeg',
  '.gif': 'image/gif', '.webp': 'image/webp', '.mp4': 'video/mp4', '.webm': 'video/webm',
  '.txt': 'text/plain', '.vert': 'text/plain', '.frag': 'text/plain', '.wasm': 'application/wasm',
};

// The probe page: WebGL 1/2 availability, renderer strings, depth-related extensions.
const kProbeHtml = `<!DOCTYPE html><html><body><script>
function info(version) {
  const c = document.createElement('canvas');
  const gl = c.getContext(version === 2 ? 'webgl2' : 'webgl');
  if (!gl) return { available: false };
  const r = { available: true, version: gl.getParameter(gl.VERSION),
    shadingLanguageVersion: gl.getParameter(gl.SHADING_LANGUAGE_VERSION),
    vendor: gl.getParameter(gl.VENDOR), renderer: gl.getParameter(gl.RENDERER),
    extensions: gl.getSupportedExtensions() };
  const dbg = gl.getExtension('WEBGL_debug_renderer_info');
  if (dbg) {
    r.unmaskedVendor = gl.getParameter(dbg.UNMASKED_VENDOR_WEBGL);
    r.unmaskedRenderer = gl.getParameter(dbg.UNMASKED_RENDERER_WEBGL);
  }
  return r;
}
window.__probe = { webgl1: info(1), webgl2: info(2), userAgent: navigator.userAgent };
</script></body></html>`;

// Static file server for SDK_TESTS_DIR on 127.0.0.1, ephemeral port.
function serve(root) {
  const server = http.createServer((req, res) => {
    const p = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    if (p === '/__probe.html') {
      res.writeHead(200, { 'Content-Type': 'text/html' }); res.end(kProbeHtml); return;
    }
    let f = path.join(root, path.normalize(p));
    if (!f.startsWith(root)) { res.writeHead(403); res.end(); return; }
    fs.stat(f, (err, st) => {
      if (!err && st.isDirectory()) f = path.join(f, 'index.html');
      fs.readFile(f, (err2, data) => {
        if (err2) { res.writeHead(404); res.end(); return; }
        res.writeHead(200, { 'Content-Type': kTypes[path.extname(f)] || 'application/octet-stream',
                             'Cache-Control': 'no-store' });
        res.end(data);
      });
    });
  });
  return new Promise(resolve => server.listen(0, '127.0.0.1', () => resolve(server)));
}

function which(prog) {
  if (prog.includes('/')) return prog;
  for (const d of (process.env.PATH || '').split(':')) {
    const f = path.join(d, prog);
    try { fs.accessSync(f, fs.constants.X_OK); return f; } catch (e) { /* next */ }
  }
  throw new Error(prog + ' not found on PATH');
}

const sleep = ms => new Promise(r => setTimeout(r, ms));

// page.evaluate has no timeout of its own; a page stuck in a long script would block it.
function evalT(page, fn, ms) {
  let timer;
  return Promise.race([page.evaluate(fn).finally(() => clearTimeout(timer)),
    new Promise((_, rej) => { timer = setTimeout(() => rej(new Error(`evaluate timed out after ${ms} ms`)), ms); })]);
}

// Defined before the page's own scripts; js-test-pre.js picks it up as window.parent.webglTestHarness.
const kInitScript = `
  window.__wgl = { pass: 0, fail: 0, skip: 0, fails: [], skips: [], last: Date.now(),
                   finished: 0, finishCalls: 0, contextLost: 0 };
  window.addEventListener('webglcontextlost', () => { window.__wgl.contextLost++; }, true);
  window.webglTestHarness = {
    reportResults(url, success, msg, skipped) {
      const w = window.__wgl; w.last = Date.now();
      if (skipped) { w.skip++; w.skips.push(String(msg)); }
      else if (success) { w.pass++; }
      else { w.fail++; w.fails.push(String(msg)); }
    },
    notifyFinished(url) { const w = window.__wgl; w.finishCalls++; if (!w.finished) w.finished = Date.now(); },
  };
`;

async function main() {
  const args = parseArgs(process.argv.slice(2));
  const { chromium } = require(require.resolve('playwright-core', { paths: [args.playwright] }));
  const pages = fs.readFileSync(args.pages, 'utf8').split('\n').map(l => l.replace(/#.*/, '').trim())
    .filter(l => l);
  const outDir = path.join(args.out, args.config);
  fs.mkdirSync(outDir, { recursive: true });
  const consoleLog = fs.createWriteStream(path.join(outDir, 'console.log'));
  browserLines.sink = fs.createWriteStream(path.join(outDir, 'browser.log'));
  const server = await serve(args.tests);
  const origin = `http://127.0.0.1:${server.address().port}`;
  const flags = [...new Set([
    '--no-sandbox', '--disable-quic', '--no-first-run', '--disable-background-networking',
    '--disable-component-update', '--disable-sync', '--disable-extensions',
    '--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1', ...args.flags,
  ])];
  const t0 = Date.now();
  const browser = await chromium.launch({ executablePath: which(args.chromium), headless: true,
                                          args: flags, timeout: 120000 });
  const result = { config: args.config, chromiumFlags: flags, browserVersion: browser.version(),
                   env: {}, started: new Date(t0).toISOString(), pageTimeoutS: args.pageTimeout,
                   idleTimeoutS: args.idleTimeout, pages: [] };
  for (const k of ['LIBGL_ALWAYS_SOFTWARE', 'GALLIUM_DRIVER', 'EGL_PLATFORM', 'VK_ICD_FILENAMES']) {
    if (process.env[k] !== undefined) result.env[k] = process.env[k];
  }
  const save = () => fs.writeFileSync(path.join(outDir, 'results.json'), JSON.stringify(result, null, 1));
  const context = await browser.newContext();
  // Only the local server is reachable.
  await context.route(u => !u.href.startsWith(origin), r => r.abort());
  await context.addInitScript(kInitScript);

  {
    const page = await context.newPage();
    page.on('console', m => consoleLog.write(`[probe] ${m.type()}: ${m.text()}\n`));
    try {
      await page.goto(`${origin}/__probe.html`, { timeout: 120000 });
      result.probe = await evalT(page, () => window.__probe, 60000);
    } catch (e) { result.probe = { error: String(e) }; }
    await page.close().catch(() => {});
  }
  const p2 = result.probe.webgl2 || {};
  console.log(`[${args.config}] ${result.browserVersion}; webgl2 ${p2.available ? 'yes' : 'NO'}; ` +
              `renderer ${p2.unmaskedRenderer || (result.probe.webgl1 || {}).unmaskedRenderer || result.probe.error}`);
  save();

  result.startupBrowserEvents = browserLines.events.splice(0);
  for (const rel of pages) {
    browserLines.page = rel;
    const page = await context.newPage();
    const run = { page: rel, pass: 0, fail: 0, skip: 0, fails: [], skips: [],
                  pageErrors: [], finished: false, timedOut: null, crashed: false };
    page.on('console', m => consoleLog.write(`[${rel}] ${m.type()}: ${m.text()}\n`));
    page.on('pageerror', e => { run.pageErrors.push(String(e).slice(0, 500));
                                consoleLog.write(`[${rel}] pageerror: ${e}\n`); });
    let crashed = false;
    page.on('crash', () => { crashed = true; });
    const start = Date.now();
    try {
      await page.goto(`${origin}/${rel}`, { timeout: 120000, waitUntil: 'domcontentloaded' });
      let lastPrint = Date.now();
      for (;;) {
        if (crashed) break;
        const st = await evalT(page, () => ({ finished: window.__wgl.finished, last: window.__wgl.last,
          pass: window.__wgl.pass, fail: window.__wgl.fail, now: Date.now() }), 60000);
        if (st.finished) { run.finished = true; break; }
        if (Date.now() - start > args.pageTimeout * 1000) { run.timedOut = 'page'; break; }
        if (st.now - st.last > args.idleTimeout * 1000) { run.timedOut = 'idle'; break; }
        if (Date.now() - lastPrint > 60000) {
          console.log(`  ${rel}: ${((Date.now() - start) / 1000).toFixed(0)} s, ${st.pass} pass, ${st.fail} fail`);
          lastPrint = Date.now();
        }
        await sleep(150);
      }
      if (!crashed) {
        const r = await evalT(page, () => {
          const w = window.__wgl;
          // The visible result lines (#console), as the page prints them.
          const lines = [...document.querySelectorAll('#console > span')].map(s => s.textContent);
          const dom = { pass: [], fail: [], warn: [], skip: [] };
          const cases = [];
          // Per FAIL: the last section heading ("Testing ...", "checking ...") and the last other
          // non-result (debug output) line before it.
          const failContext = [];
          let recent = [], heading = '';
          for (const l of lines) {
            const m = l.match(/^(PASS|FAIL|WARNING|SKIP) ([\s\S]*)$/);
            if (m) {
              dom[{ PASS: 'pass', FAIL: 'fail', WARNING: 'warn', SKIP: 'skip' }[m[1]]].push(m[2]);
              if (m[1] === 'FAIL') {
                const last = recent[recent.length - 1];
                failContext.push(heading && heading !== last ? [heading].concat(last ? [last] : []) : recent.slice(-1));
              }
            } else if (l.trim()) {
              recent.push(l.trim().slice(0, 300)); if (recent.length > 3) recent.shift();
              if (/^(testing|checking|test:|Start testcase)/i.test(l.trim())) heading = l.trim().slice(0, 300);
            }
            const c = l.match(/^Start testcase: (.*)$/);
            if (c) cases.push(c[1].trim());
          }
          dom.failContext = failContext;
          const desc = document.getElementById('description');
          const m = desc && desc.textContent.match(/TEST COMPLETE: \d+ PASS, \d+ FAIL/);
          // The whole visible output of pages with a FAIL line (capped), to read failures in order.
          const consoleText = dom.fail.length ? lines.slice(0, 3000).map(l => l.slice(0, 400)) : undefined;
          return { pass: w.pass, fail: w.fail, skip: w.skip, fails: w.fails, skips: w.skips,
                   finishCalls: w.finishCalls, contextLost: w.contextLost, dom, deqpCases: cases, consoleText,
                   domSummary: m ? m[0] : null, title: document.title };
        }, 60000);
        Object.assign(run, r);
      }
    } catch (e) {
      run.error = String(e).slice(0, 1000);
    }
    run.crashed = crashed;
    run.seconds = (Date.now() - start) / 1000;
    await sleep(100); // let the browser's stderr for this page arrive
    run.browserEvents = browserLines.events.splice(0);
    result.pages.push(run);
    const d = run.dom || { pass: [], fail: [], warn: [] };
    console.log(`[${args.config}] ${rel}: shown ${d.pass.length} PASS, ${d.fail.length} FAIL, ${d.warn.length} WARNING; ` +
      `harness ${run.pass} pass, ${run.fail} fail, ${run.skip} skip, ` +
      `${run.seconds.toFixed(1)} s${run.finished ? '' : ' NOT FINISHED'}${run.timedOut ? ' TIMEOUT(' + run.timedOut + ')' : ''}` +
      `${crashed ? ' CRASHED' : ''}${run.contextLost ? ' CONTEXT LOST x' + run.contextLost : ''}` +
      `${run.browserEvents.length ? ' BROWSER: ' + run.browserEvents.join(' | ') : ''}${run.error ? ' ERROR ' + run.error : ''}`);
    save();
    await page.close({ runBeforeUnload: false }).catch(() => {});
  }
  result.totalSeconds = (Date.now() - t0) / 1000;
  save();
  await browser.close().catch(() => {});
  server.close();
  consoleLog.end();
  browserLines.sink.end();
}

// Hard stop: nothing here may outlive its budget.
const kHardLimitMs = Number(process.env.WEBGL_CTS_HARD_LIMIT_S || 3600) * 1000;
setTimeout(() => { console.error('hard time limit reached'); process.exit(3); }, kHardLimitMs).unref();
main().then(() => process.exit(0), e => { console.error(e); process.exit(1); });
