#!/usr/bin/env node
// Drive the WebGPU CTS standalone runner (standalone/?runnow=1&q=...) in headless Chromium
// and save the CTS's own results JSON (the "Copy results as JSON" button's output).
//
// usage: node run_cts.js --cts CTS_DIR --out OUT_DIR --config NAME [--compat]
//          [--flag=--some-chromium-flag ...] [--query Q ...] [--query-timeout SECONDS]
//          [--chromium PATH] [--param K=V ...]   (extra runner URL parameters, e.g. debug=1)
// Needs: CTS_DIR built with `npm ci && npm run standalone` (playwright-core comes from
// CTS_DIR/node_modules, it drives the system Chromium; no browser download).
'use strict';
const fs = require('fs');
const http = require('http');
const path = require('path');

function parseArgs(argv) {
  const a = { flags: [], queries: [], params: [], compat: false, queryTimeout: 1800, chromium: 'chromium' };
  for (let i = 0; i < argv.length; i++) {
    const k = argv[i];
    const eq = k.indexOf('=');
    const key = eq > 0 ? k.slice(0, eq) : k;
    const val = () => (eq > 0 ? k.slice(eq + 1) : argv[++i]);
    switch (key) {
      case '--cts': a.cts = path.resolve(val()); break;
      case '--out': a.out = path.resolve(val()); break;
      case '--config': a.config = val(); break;
      case '--compat': a.compat = true; break;
      case '--flag': a.flags.push(val()); break;
      case '--query': a.queries.push(val()); break;
      case '--param': a.params.push(val()); break; // extra runner URL parameter, e.g. debug=1
      case '--query-timeout': a.queryTimeout = Number(val()); break;
      case '--chromium': a.chromium = val(); break;
      default: throw new Error('unknown argument ' + k);
    }
  }
  if (!a.cts || !a.out || !a.config || a.queries.length === 0) {
    throw new Error('need --cts, --out, --config and at least one --query');
  }
  return a;
}

const kTypes = {
  '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.css': 'text/css',
  '.json': 'application/json', '.svg': 'image/svg+xml', '.map': 'application/json',
  '.png': 'image/png', '.bin': 'application/octet-stream', '.txt': 'text/plain',
};

// Minimal static file server for the CTS checkout root, on 127.0.0.1 and an ephemeral port.
function serve(root) {
  const server = http.createServer((req, res) => {
    let p = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    let f = path.join(root, path.normalize(p));
    if (!f.startsWith(root)) { res.writeHead(403); res.end(); return; }
    if (fs.existsSync(f) && fs.statSync(f).isDirectory()) f = path.join(f, 'index.html');
    fs.readFile(f, (err, data) => {
      if (err) { res.writeHead(404); res.end(); return; }
      res.writeHead(200, { 'Content-Type': kTypes[path.extname(f)] || 'application/octet-stream',
                           'Cache-Control': 'no-store' });
      res.end(data);
    });
  });
  return new Promise(resolve => server.listen(0, '127.0.0.1', () => resolve(server)));
}

// Resolve a bare program name on PATH (playwright wants a path).
function which(prog) {
  if (prog.includes('/')) return prog;
  for (const d of (process.env.PATH || '').split(':')) {
    const f = path.join(d, prog);
    try { fs.accessSync(f, fs.constants.X_OK); return f; } catch (e) { /* next */ }
  }
  throw new Error(prog + ' not found on PATH');
}

const sleep = ms => new Promise(r => setTimeout(r, ms));

// Injected before the page's scripts: capture the results JSON the runner would put on the
// clipboard, and timestamp when the #progress box is shown (run started) and hidden (run ended).
const kInitScript = `
  window.__cts = { json: null, shown: 0, hidden: 0 };
  try {
    Object.defineProperty(navigator, 'clipboard', { configurable: true,
      value: { writeText: async t => { window.__cts.json = t; } } });
  } catch (e) { window.__cts.clipErr = String(e); }
  document.addEventListener('DOMContentLoaded', () => {
    const p = document.getElementById('progress');
    if (!p) return;
    new MutationObserver(() => {
      if (p.style.display === 'none') { if (window.__cts.shown) window.__cts.hidden = Date.now(); }
      else if (!window.__cts.shown) window.__cts.shown = Date.now();
    }).observe(p, { attributes: true, attributeFilter: ['style'] });
  });
`;

async function adapterInfo(page, compat) {
  return page.evaluate(async compat => {
    if (!navigator.gpu) return { error: 'navigator.gpu is undefined' };
    const a = await navigator.gpu.requestAdapter(compat ? { featureLevel: 'compatibility' } : {});
    if (!a) return { error: 'requestAdapter returned null' };
    const i = a.info;
    const limits = {};
    for (const k of ['maxTextureDimension2D', 'maxTextureArrayLayers', 'maxSamplersPerShaderStage',
      'maxSampledTexturesPerShaderStage', 'maxStorageBuffersInVertexStage',
      'maxStorageBuffersInFragmentStage', 'maxStorageBuffersPerShaderStage']) {
      limits[k] = a.limits[k];
    }
    return {
      requestedFeatureLevel: compat ? 'compatibility' : 'core',
      vendor: i.vendor, architecture: i.architecture, device: i.device, description: i.description,
      isFallbackAdapter: i.isFallbackAdapter, subgroupMinSize: i.subgroupMinSize,
      subgroupMaxSize: i.subgroupMaxSize,
      features: [...a.features].sort(), limits, userAgent: navigator.userAgent,
    };
  }, compat);
}

async function main() {
  const args = parseArgs(process.argv.slice(2));
  const { chromium } = require(path.join(args.cts, 'node_modules', 'playwright-core'));
  const outDir = path.join(args.out, args.config);
  fs.mkdirSync(outDir, { recursive: true });
  const consoleLog = fs.createWriteStream(path.join(outDir, 'console.log'));
  const server = await serve(args.cts);
  const origin = `http://127.0.0.1:${server.address().port}`;
  const flags = [
    '--no-sandbox', '--enable-unsafe-webgpu', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync',
    '--disable-extensions', '--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1',
    ...args.flags,
  ];
  const t0 = Date.now();
  const browser = await chromium.launch({ executablePath: which(args.chromium), headless: true, args: flags,
                                          timeout: 120000 });
  const meta = { config: args.config, compat: args.compat, chromiumFlags: flags,
                 browserVersion: browser.version(), started: new Date(t0).toISOString(), runs: [] };
  const context = await browser.newContext();
  // Only the local server is reachable (the runner page links a web font; abort that).
  await context.route(u => !u.href.startsWith(origin), r => r.abort());
  await context.addInitScript(kInitScript);

  {
    const page = await context.newPage();
    await page.goto(`${origin}/standalone/index.html?q=webgpu:nothing:*`, { timeout: 120000 });
    meta.adapter = await adapterInfo(page, args.compat);
    await page.close();
  }
  console.log(`[${args.config}] browser ${meta.browserVersion}; adapter ${JSON.stringify(
    { vendor: meta.adapter.vendor, architecture: meta.adapter.architecture,
      isFallbackAdapter: meta.adapter.isFallbackAdapter, error: meta.adapter.error })}`);

  for (const q of args.queries) {
    const page = await context.newPage();
    page.on('console', m => consoleLog.write(`[${q}] ${m.type()}: ${m.text()}\n`));
    page.on('pageerror', e => consoleLog.write(`[${q}] pageerror: ${e}\n`));
    let crashed = false;
    page.on('crash', () => { crashed = true; });
    const url = `${origin}/standalone/?runnow=1${args.compat ? '&compatibility=1' : ''}${
      args.params.map(p => '&' + p).join('')}&q=${
      encodeURIComponent(q)}`;
    const start = Date.now();
    const run = { query: q, url: url.slice(origin.length), timedOut: false, crashed: false };
    try {
      await page.goto(url, { timeout: 120000 });
      let lastName = '', lastPrint = Date.now() - 55000;
      for (;;) {
        if (crashed) break;
        const st = await page.evaluate(() => ({
          shown: window.__cts.shown, hidden: window.__cts.hidden,
          name: document.querySelector('#progress .progress-test-name')?.textContent ?? '',
          info: document.getElementById('info')?.textContent ?? '',
        }));
        if (st.hidden) break;
        if (!st.shown && Date.now() - start > 300000) {
          run.error = 'run did not start within 300 s; #info: ' + st.info; break;
        }
        if (Date.now() - start > args.queryTimeout * 1000) {
          run.timedOut = true; run.runningCaseAtTimeout = st.name;
          await page.click('#progress button', { timeout: 5000 }).catch(() => {});
          break;
        }
        if (Date.now() - lastPrint > 60000) {
          console.log(`  ${((Date.now() - start) / 1000).toFixed(0)}s ${st.name === lastName ? '(same case) ' : ''}${st.name}`);
          lastName = st.name; lastPrint = Date.now();
        }
        await sleep(1000);
      }
      if (!crashed) {
        await page.click('#copyResultsJSON', { timeout: 30000 });
        const json = await page.waitForFunction(() => window.__cts.json, null, { timeout: 60000 });
        fs.writeFileSync(path.join(outDir, q.replace(/[^A-Za-z0-9_,.-]+/g, '_') + '.json'),
                         await json.jsonValue());
      }
    } catch (e) {
      run.error = String(e);
    }
    run.crashed = crashed;
    run.seconds = (Date.now() - start) / 1000;
    meta.runs.push(run);
    console.log(`[${args.config}] ${q}: ${run.seconds.toFixed(0)} s${run.timedOut ? ' TIMED OUT' : ''}${
      run.crashed ? ' CRASHED' : ''}${run.error ? ' ERROR ' + run.error : ''}`);
    await page.close().catch(() => {});
  }
  meta.totalSeconds = (Date.now() - t0) / 1000;
  fs.writeFileSync(path.join(outDir, 'meta.json'), JSON.stringify(meta, null, 1));
  await browser.close();
  server.close();
  consoleLog.end();
}

// Hard stop: nothing here may outlive its budget.
const kHardLimitMs = Number(process.env.CTS_HARD_LIMIT_S || 4 * 3600) * 1000;
setTimeout(() => { console.error('hard time limit reached'); process.exit(3); }, kHardLimitMs).unref();
main().then(() => process.exit(0), e => { console.error(e); process.exit(1); });
