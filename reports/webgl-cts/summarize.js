#!/usr/bin/env node
// Summarise run_webgl_cts.js results as Markdown.
// usage: node summarize.js OUT_DIR [CONFIG...]   (default configs: every OUT_DIR/*/results.json)
'use strict';
const fs = require('fs');
const path = require('path');

const out = path.resolve(process.argv[2] || '.');
let configs = process.argv.slice(3);
if (configs.length === 0) {
  configs = fs.readdirSync(out).filter(d => fs.existsSync(path.join(out, d, 'results.json')));
}
const R = {};
for (const c of configs) {
  const f = path.join(out, c, 'results.json');
  if (fs.existsSync(f)) R[c] = JSON.parse(fs.readFileSync(f, 'utf8'));
}
configs = configs.filter(c => R[c]);
const readOpt = f => (fs.existsSync(path.join(out, f)) ? fs.readFileSync(path.join(out, f), 'utf8').trim() : '?');

const short = (s, n = 220) => {
  s = String(s).replace(/\s+/g, ' ').trim();
  return s.length > n ? s.slice(0, n - 1) + '…' : s;
};
const md = s => String(s).replace(/\|/g, '\\|').replace(/</g, '&lt;');
const isDeqp = p => p.startsWith('deqp/');
const isShadow = p => p.includes('/textureshadow/');
const pageName = p => {
  const [file, q = ''] = p.split('?');
  const rest = q.split('&').filter(x => x && !/^webglVersion=/.test(x)).join('&');
  return file.replace(/^deqp\/functional\/gles3\//, 'deqp/…/') + (rest ? '?' + rest : '');
};

// Per page and config: counts, dEQP case verdicts, status.
function pageStats(run) {
  const dom = run.dom || { pass: [], fail: [], warn: [], failContext: [] };
  const st = { shownPass: dom.pass.length, shownFail: dom.fail.length, warn: dom.warn.length,
               harnessPass: run.pass, harnessFail: run.fail, skip: run.skip, seconds: run.seconds,
               finished: run.finished, timedOut: run.timedOut, crashed: run.crashed, error: run.error,
               pageErrors: run.pageErrors || [], domSummary: run.domSummary,
               contextLost: run.contextLost || 0, browserEvents: run.browserEvents || [] };
  if (run.deqpCases) {
    const cases = run.deqpCases;
    const failed = new Set();
    for (const f of dom.fail) {
      const c = cases.find(n => f.startsWith(n + ':'));
      if (c) failed.add(c);
    }
    st.cases = cases.length;
    st.casesFailed = [...failed];
    st.lowQuality = [...new Set(dom.pass.filter(m => /Low-quality result/.test(m)).map(m => m.split(':')[0]))];
  }
  return st;
}
function status(st) {
  const f = [];
  if (!st.finished) f.push('not finished');
  if (st.timedOut) f.push(`timeout (${st.timedOut})`);
  if (st.crashed) f.push('crashed');
  if (st.error) f.push('error');
  if (st.pageErrors.length) f.push(`${st.pageErrors.length} page error(s)`);
  if (st.contextLost) f.push('WebGL context lost');
  if (st.browserEvents.some(e => /GPU process exited/.test(e))) f.push('GPU process crashed');
  return f.join(', ');
}
function cell(st) {
  if (!st) return 'not run';
  let s;
  if (st.cases !== undefined && st.cases > 0) {
    s = `${st.cases - st.casesFailed.length}/${st.cases} cases` +
        (st.casesFailed.length ? ` (**${st.casesFailed.length} failed**)` : '');
    if (st.lowQuality.length) s += `, ${st.lowQuality.length} low-quality`;
  } else {
    s = `${st.shownPass} PASS / ${st.shownFail ? `**${st.shownFail} FAIL**` : '0 FAIL'}`;
  }
  const x = status(st);
  return x ? `${s}; **${x}**` : s;
}

const allPages = [];
for (const c of configs) for (const p of R[c].pages) if (!allPages.includes(p.page)) allPages.push(p.page);
const S = {}; // S[page][config] = stats
for (const c of configs) {
  for (const p of R[c].pages) (S[p.page] = S[p.page] || {})[c] = pageStats(p);
}

const o = [];
const w = s => o.push(s);
w('# WebGL CTS depth / shadow / sampler pages: results');
w('');
w(`WebGL repository commit: \`${readOpt('webgl-commit.txt')}\`; browser: ${readOpt('chromium-version.txt')}` +
  ` (playwright reports ${[...new Set(configs.map(c => R[c].browserVersion))].join(', ')}).`);
w('');
w('## Back ends');
w('');
w('| config | WebGL 1 | WebGL 2 | UNMASKED_RENDERER_WEBGL | UNMASKED_VENDOR_WEBGL | started | run time |');
w('| --- | --- | --- | --- | --- | --- | --- |');
for (const c of configs) {
  const pr = R[c].probe || {};
  const g1 = pr.webgl1 || {}, g2 = pr.webgl2 || {};
  w(`| \`${c}\` | ${g1.available ? 'yes' : '**no**'} | ${g2.available ? 'yes' : '**no**'} | ` +
    `\`${md(g2.unmaskedRenderer || g1.unmaskedRenderer || pr.error || '?')}\` | \`${md(g2.unmaskedVendor || g1.unmaskedVendor || '?')}\` | ` +
    `${R[c].started} | ${R[c].totalSeconds ? R[c].totalSeconds.toFixed(0) + ' s' : '**incomplete**'} |`);
}
w('');
w('Chromium flags and environment per config:');
w('');
for (const c of configs) {
  w(`- \`${c}\`: \`${R[c].chromiumFlags.join(' ')}\`` +
    (Object.keys(R[c].env).length ? `; env \`${Object.entries(R[c].env).map(([k, v]) => `${k}=${v}`).join(' ')}\`` : ''));
}
w('');
w('WebGL 2 extensions (depth/stencil/shadow-related ones in bold):');
w('');
for (const c of configs) {
  const ex = ((R[c].probe || {}).webgl2 || {}).extensions || [];
  w(`- \`${c}\`: ${ex.map(e => (/depth|stencil|shadow|clamp|float_linear/i.test(e) ? `**${e}**` : e)).join(', ')}`);
}
w('');
w('WebGL 1 extensions related to depth: ' + configs.map(c => `\`${c}\`: ${
  (((R[c].probe || {}).webgl1 || {}).extensions || []).filter(e => /depth|stencil|shadow/i.test(e)).join(', ') || 'none'}`).join('; '));
w('');

w('## Counts per page and back end');
w('');
w('Non-dEQP pages: the PASS / FAIL lines the page prints (the same results the official runner counts). ' +
  'dEQP pages: test cases passed / run (a case fails if any FAIL line names it); "low-quality" = cases ' +
  'that passed only with the dEQP low-quality threshold. WARNING lines (dEQP skip list, non-fatal checks) are listed further down.');
w('');
w(`| page | ${configs.map(c => `\`${c}\``).join(' | ')} |`);
w(`| --- | ${configs.map(() => '---').join(' | ')} |`);
for (const p of allPages.filter(p => !isShadow(p))) {
  w(`| \`${md(pageName(p))}\` | ${configs.map(c => cell((S[p] || {})[c])).join(' | ')} |`);
}
w('');

// textureshadow: aggregated by target.filter, then every page.
const shadowPages = allPages.filter(isShadow);
if (shadowPages.length) {
  w('### dEQP texture shadow (`deqp/functional/gles3/textureshadow/`)');
  w('');
  w(`${shadowPages.length} pages; each page is one target x filter x compare function with 3 cases (formats ` +
    'depth_component16, depth_component32f, depth24_stencil8). Aggregated per target and filter ' +
    '(8 compare functions = 24 cases):');
  w('');
  const groups = {};
  for (const p of shadowPages) {
    const m = p.match(/textureshadow\/(2d_array|2d|cube)_((?:nearest|linear)(?:_mipmap_(?:nearest|linear))?)_(less_or_equal|greater_or_equal|not_equal|less|greater|equal|always|never)\.html/);
    const k = m ? `${m[1]} ${m[2]}` : p;
    (groups[k] = groups[k] || []).push(p);
  }
  w(`| target, filter | ${configs.map(c => `\`${c}\``).join(' | ')} |`);
  w(`| --- | ${configs.map(() => '---').join(' | ')} |`);
  const tot = {};
  for (const [k, ps] of Object.entries(groups)) {
    const cells = configs.map(c => {
      let n = 0, f = 0, lq = 0, sec = 0, bad = 0;
      for (const p of ps) {
        const st = (S[p] || {})[c];
        if (!st) { bad++; continue; }
        n += st.cases || 0; f += (st.casesFailed || []).length; lq += (st.lowQuality || []).length; sec += st.seconds;
        if (status(st)) bad++;
      }
      const t = tot[c] = tot[c] || { n: 0, f: 0, lq: 0, sec: 0, bad: 0 };
      t.n += n; t.f += f; t.lq += lq; t.sec += sec; t.bad += bad;
      return `${n - f}/${n}${f ? ` (**${f} failed**)` : ''}${lq ? `, ${lq} low-quality` : ''}${bad ? `, **${bad} page(s) with problems**` : ''}, ${sec.toFixed(0)} s`;
    });
    w(`| ${k} | ${cells.join(' | ')} |`);
  }
  w(`| **all** | ${configs.map(c => { const t = tot[c] || { n: 0, f: 0, lq: 0, sec: 0, bad: 0 };
    return `**${t.n - t.f}/${t.n}**${t.f ? ` (**${t.f} failed**)` : ''}${t.lq ? `, ${t.lq} low-quality` : ''}${t.bad ? `, ${t.bad} page(s) with problems` : ''}, ${t.sec.toFixed(0)} s`; }).join(' | ')} |`);
  w('');
  w('<details><summary>Every textureshadow page</summary>');
  w('');
  w(`| page | ${configs.map(c => `\`${c}\``).join(' | ')} |`);
  w(`| --- | ${configs.map(() => '---').join(' | ')} |`);
  for (const p of shadowPages) {
    w(`| \`${md(p.replace(/.*textureshadow\//, '').replace(/\?.*/, ''))}\` | ${configs.map(c => {
      const st = (S[p] || {})[c];
      return st ? `${cell(st)}, ${st.seconds.toFixed(1)} s` : 'not run'; }).join(' | ')} |`);
  }
  w('');
  w('</details>');
  w('');
}

// Every FAIL line, grouped by page and back end.
w('## Failures');
w('');
let anyFail = false;
const failKey = {}; // page -> msg -> Set(configs)
for (const p of allPages) {
  const per = [];
  for (const c of configs) {
    const run = R[c].pages.find(r => r.page === p);
    if (!run || !run.dom || !run.dom.fail.length) continue;
    const cnt = new Map();
    run.dom.fail.forEach((f, i) => {
      const k = short(f);
      const ctx = (run.dom.failContext || [])[i] || [];
      if (!cnt.has(k)) cnt.set(k, { n: 0, ctx: new Map() });
      const e = cnt.get(k); e.n++;
      const ck = ctx.map(x => short(x, 120)).join(' / ');
      e.ctx.set(ck, (e.ctx.get(ck) || 0) + 1);
      ((failKey[p] = failKey[p] || {})[k] = failKey[p][k] || new Set()).add(c);
    });
    per.push([c, run.dom.fail.length, cnt]);
  }
  if (!per.length) continue;
  anyFail = true;
  w(`### \`${md(pageName(p))}\``);
  w('');
  for (const [c, n, cnt] of per) {
    w(`- **${c}**: ${n} FAIL line(s)`);
    for (const [k, e] of cnt) {
      const ctxs = [...e.ctx].filter(([ck]) => ck);
      if (ctxs.length === 1) w(`  - ${e.n} x \`${md(k)}\` (after: ${md(ctxs[0][0])})`);
      else {
        w(`  - ${e.n} x \`${md(k)}\``);
        for (const [ck, cn] of ctxs) w(`    - ${cn} x after: ${md(ck)}`);
      }
    }
  }
  w('');
}
if (!anyFail) w('No FAIL lines on any page and back end.');
w('');
if (anyFail) {
  w('### Which failures are common to all back ends');
  w('');
  w('| page | FAIL line | back ends |');
  w('| --- | --- | --- |');
  for (const [p, msgs] of Object.entries(failKey)) {
    for (const [m, set] of Object.entries(msgs)) {
      const b = set.size === configs.length ? `all (${configs.length})` : [...set].join(', ');
      w(`| \`${md(pageName(p))}\` | \`${md(short(m, 140))}\` | ${b} |`);
    }
  }
  w('');
}

// Problems other than FAIL lines.
w('## Timeouts, crashes, page errors');
w('');
let anyProb = false;
for (const p of allPages) {
  for (const c of configs) {
    const st = (S[p] || {})[c];
    if (!st) continue;
    const x = status(st);
    if (!x) continue;
    anyProb = true;
    w(`- \`${md(pageName(p))}\` on \`${c}\`: ${x}, ${st.seconds.toFixed(0)} s${st.error ? `; error: \`${md(short(st.error, 300))}\`` : ''}` +
      `${st.browserEvents.length ? `; browser stderr: ${st.browserEvents.map(e => `\`${md(short(e, 200))}\``).join(', ')}` : ''}` +
      `${st.pageErrors.length ? `; page errors: ${st.pageErrors.map(e => `\`${md(short(e, 200))}\``).join(', ')}` : ''}`);
  }
}
if (!anyProb) w('None: every page called notifyFinished (printed TEST COMPLETE) on every back end, no page crashed or threw.');
w('');

// WARNING lines.
w('## WARNING lines');
w('');
w('dEQP prints WARNING (not counted as a result) for cases on its skip list (`deqp/framework/common/tcuSkipList.js`) ' +
  'and for some non-fatal checks. With a `filter`, the dEQP runner walks the whole test tree, so the skip-list ' +
  'warnings of the other shadertexturefunction groups are printed on every filtered page; they are listed once here.');
w('');
const warns = new Map(); // msg -> Map(config -> pages)
for (const c of configs) {
  for (const r of R[c].pages) {
    for (const m of ((r.dom || {}).warn || [])) {
      const k = short(m, 200);
      if (!warns.has(k)) warns.set(k, new Map());
      const mm = warns.get(k);
      if (!mm.has(c)) mm.set(c, new Set());
      mm.get(c).add(pageName(r.page).replace(/\?.*/, ''));
    }
  }
}
if (!warns.size) w('None.');
for (const [k, mm] of warns) {
  const cs = [...mm.keys()];
  const pages = [...new Set([].concat(...[...mm.values()].map(s => [...s])))];
  w(`- \`${md(k)}\` — ${cs.length === configs.length ? 'all back ends' : cs.join(', ')}; page(s): ${pages.length > 3 ? pages.length + ' pages' : pages.map(x => `\`${md(x)}\``).join(', ')}`);
}
w('');

// dEQP low-quality passes.
w('## dEQP cases that passed only at low quality');
w('');
let anyLq = false;
for (const c of configs) {
  const lq = [];
  for (const p of allPages) { const st = (S[p] || {})[c]; if (st && st.lowQuality) lq.push(...st.lowQuality); }
  if (lq.length) { anyLq = true; w(`- **${c}** (${lq.length}): ${lq.map(x => `\`${x}\``).join(', ')}`); }
}
if (!anyLq) w('None.');
w('');

// Harness totals (the official runner's numbers; for dEQP pages they include internal checks).
w('## Harness totals');
w('');
w('Calls to `webglTestHarness.reportResults` (what the official runner counts). For dEQP pages these include the ' +
  'framework\'s internal `assertMsgOptions` checks (often hundreds of thousands per page), so they are not case counts.');
w('');
w(`| config | pages | pages finished | reported pass | reported fail | reported skip |`);
w('| --- | --- | --- | --- | --- | --- |');
for (const c of configs) {
  const ps = R[c].pages;
  w(`| \`${c}\` | ${ps.length} | ${ps.filter(p => p.finished).length} | ${ps.reduce((s, p) => s + p.pass, 0)} | ` +
    `${ps.reduce((s, p) => s + p.fail, 0)} | ${ps.reduce((s, p) => s + p.skip, 0)} |`);
}
w('');
process.stdout.write(o.join('\n') + '\n');
