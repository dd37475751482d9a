#!/usr/bin/env node
// Summarise the raw results written by run_cts.js: node summarize.js OUT_DIR > summary.md
// Reads OUT_DIR/<config>/meta.json and OUT_DIR/<config>/*.json (the CTS's results JSON).
'use strict';
const fs = require('fs');
const path = require('path');

const out = process.argv[2];
if (!out) { console.error('usage: summarize.js OUT_DIR'); process.exit(2); }

const kStage = { c: 'compute', f: 'fragment', v: 'vertex' };
const kMode = { c: 'clamp-to-edge', r: 'repeat', m: 'mirror-repeat' };

function parseName(name) {
  // webgpu:shader,execution,expression,call,builtin,FILE:TEST:k=v;k=v
  const parts = name.split(':');
  const file = parts[1].split(',').pop();
  const test = parts[2];
  const params = {};
  for (const kv of (parts.slice(3).join(':') || '').split(';')) {
    if (!kv) continue;
    const i = kv.indexOf('=');
    params[kv.slice(0, i)] = JSON.parse(kv.slice(i + 1));
  }
  return { file, test, params };
}

function paramText(p) {
  const s = [];
  if (p.stage !== undefined) s.push(kStage[p.stage] || p.stage);
  if (p.format !== undefined) s.push(p.format);
  if (p.filt !== undefined) s.push(p.filt);
  for (const k of ['mode', 'modeU', 'modeV']) if (p[k] !== undefined) s.push(`${k}=${kMode[p[k]] || p[k]}`);
  if (p.offset !== undefined) s.push(`offset=${p.offset}`);
  for (const [k, v] of Object.entries(p)) {
    if (!['stage', 'format', 'filt', 'mode', 'modeU', 'modeV', 'offset'].includes(k)) s.push(`${k}=${v}`);
  }
  return s.join(', ');
}

// Shorten one CTS log message: first line, plus the call / got / expected lines if any.
function shorten(log) {
  const lines = log.split('\n');
  const keep = [lines[0].trim().replace(/^EXPECTATION FAILED: result was not as expected:$/, 'EXPECTATION FAILED:')];
  for (const l of lines.slice(1)) {
    const t = l.trim();
    if (/^(call|got|expected):/.test(t)) {
      keep.push(t.replace(/\s+/g, ' ').replace('texture: T, sampler: S, ', '')
        .replace(/derivativeBase \* derivativeMult\(([^)]*)\)/, 'dBase*dMult($1)')
        .replace(/(\d\.\d{4})\d+/g, '$1'));
    }
    if (/^at /.test(t)) break;
  }
  return keep.join(' ; ').slice(0, 330);
}

const configs = fs.readdirSync(out).filter(d => fs.existsSync(path.join(out, d, 'meta.json'))).sort();
const md = [];
md.push('# WebGPU CTS comparison-sampler results');
md.push('');
for (const c of configs) {
  const dir = path.join(out, c);
  const meta = JSON.parse(fs.readFileSync(path.join(dir, 'meta.json'), 'utf8'));
  const a = meta.adapter || {};
  let version = '?';
  const cases = [];
  for (const f of fs.readdirSync(dir).filter(f => f.endsWith('.json') && f !== 'meta.json').sort()) {
    const j = JSON.parse(fs.readFileSync(path.join(dir, f), 'utf8'));
    version = j.version;
    for (const [name, r] of j.results) cases.push({ name, ...parseName(name), ...r });
  }
  md.push(`## Configuration \`${c}\``);
  md.push('');
  md.push(`- Chromium ${meta.browserVersion}, compatibility mode: ${meta.compat}`);
  md.push(`- Chromium flags: \`${meta.chromiumFlags.join(' ')}\``);
  md.push(`- CTS version (as the CTS reports it): ${version}`);
  md.push(`- Adapter: vendor=\`${a.vendor}\` architecture=\`${a.architecture}\` device=\`${a.device}\` ` +
          `description=\`${a.description}\` isFallbackAdapter=${a.isFallbackAdapter}` +
          (a.error ? ` error=${a.error}` : ''));
  md.push(`- Adapter features: ${(a.features || []).join(', ')}`);
  md.push(`- Wall time: ${meta.totalSeconds.toFixed(0)} s for ${cases.length} cases`);
  for (const r of meta.runs) {
    if (r.timedOut || r.crashed || r.error) {
      md.push(`- PROBLEM in \`${r.query}\`: ${r.timedOut ? 'timed out (running: ' + r.runningCaseAtTimeout + ') ' : ''}` +
              `${r.crashed ? 'page crashed ' : ''}${r.error || ''}`);
    }
  }
  md.push('');

  // Totals per test, then per test x format.
  const count = (list) => {
    const n = { pass: 0, fail: 0, skip: 0, warn: 0, other: 0 };
    for (const x of list) n[x.status in n ? x.status : 'other']++;
    return n;
  };
  const groupBy = (list, key) => {
    const m = new Map();
    for (const x of list) { const k = key(x); if (!m.has(k)) m.set(k, []); m.get(k).push(x); }
    return m;
  };
  md.push('| test | format | cases | pass | fail | skip | warn |');
  md.push('| --- | --- | ---: | ---: | ---: | ---: | ---: |');
  for (const [t, list] of groupBy(cases, x => `${x.file}:${x.test}`)) {
    const n = count(list);
    md.push(`| ${t} | **all** | ${list.length} | ${n.pass} | ${n.fail} | ${n.skip} | ${n.warn} |`);
    for (const [fmt, l2] of groupBy(list, x => x.params.format)) {
      const m = count(l2);
      md.push(`| | ${fmt} | ${l2.length} | ${m.pass} | ${m.fail} | ${m.skip} | ${m.warn} |`);
    }
  }
  const all = count(cases);
  md.push(`| **total** | | ${cases.length} | ${all.pass} | ${all.fail} | ${all.skip} | ${all.warn} |`);
  md.push('');

  // Skips, grouped by message.
  const skips = cases.filter(x => x.status === 'skip');
  if (skips.length) {
    md.push(`### Skips (${skips.length})`);
    md.push('');
    const byMsg = groupBy(skips, x => shorten(((x.logs || []).find(l => /SKIP/.test(l)) || (x.logs || [''])[0])
      .replace(/^\(in subcase: [^)]*\) /, '')));
    for (const [msg, l] of byMsg) {
      md.push(`- ${l.length} case(s): \`${msg}\``);
      for (const [t, l2] of groupBy(l, x => `${x.file}:${x.test}`)) {
        md.push(`  - ${t}: formats ${[...new Set(l2.map(x => x.params.format))].join(', ')}`);
      }
    }
    md.push('');
  }

  // Failing cases: subcase analysis.
  const fails = cases.filter(x => x.status !== 'pass' && x.status !== 'skip');
  for (const x of fails) {
    x.badSub = new Map(); // subcase param -> Set of values that failed
    x.nSub = new Set();
    x.nBad = new Set();
    x.firstMsg = '(no message)';
    for (const l of x.logs || []) {
      const m = /^\(in subcase: ([^)]*)\) /.exec(l);
      const sub = m ? m[1] : '';
      if (m) x.nSub.add(sub);
      if (/INFO: subcase ran/.test(l) || /^\s*(\([^)]*\) )?DEBUG/.test(l)) continue;
      if (x.firstMsg === '(no message)') x.firstMsg = shorten(l.slice(m ? m[0].length : 0));
      x.nBad.add(sub);
      for (const kv of sub.split(';')) {
        if (!kv) continue;
        const i = kv.indexOf('=');
        const k = kv.slice(0, i), v = kv.slice(i + 1).replace(/"/g, '');
        if (!x.badSub.has(k)) x.badSub.set(k, new Set());
        x.badSub.get(k).add(v);
      }
    }
  }
  const subText = x => [...x.badSub].map(([k, v]) => `${k}∈{${[...v].join(',')}}`).join(' ');
  if (fails.length) {
    md.push(`### Failures by pattern (${fails.length} failing cases)`);
    md.push('');
    md.push('Cases grouped by test, stage, filter, offset; "failing cases" is out of all cases of that group.');
    md.push('');
    md.push('| test | stage | filt | offset | failing cases | formats | address modes | failing subcases (union) |');
    md.push('| --- | --- | --- | --- | ---: | --- | --- | --- |');
    const key = x => `${x.file}:${x.test}|${x.params.stage ?? ''}|${x.params.filt ?? ''}|${x.params.offset ?? ''}`;
    const totals = groupBy(cases, key);
    for (const [k, l] of groupBy(fails, key)) {
      const [t, st, fi, off] = k.split('|');
      const modes = new Set(l.map(x => ['mode', 'modeU', 'modeV'].filter(m => x.params[m] !== undefined)
        .map(m => `${m}=${x.params[m]}`).join(',')));
      const union = new Map();
      for (const x of l) for (const [sk, sv] of x.badSub) {
        if (!union.has(sk)) union.set(sk, new Set());
        for (const v of sv) union.get(sk).add(v);
      }
      md.push(`| ${t} | ${kStage[st] || '-'} | ${fi || '-'} | ${off || '-'} | ${l.length}/${totals.get(k).length} | ` +
        `${[...new Set(l.map(x => x.params.format))].join(', ')} | ${modes.size} of ${new Set(totals.get(k).map(x =>
          ['mode', 'modeU', 'modeV'].filter(m => x.params[m] !== undefined).map(m => `${m}=${x.params[m]}`).join(','))).size}: ` +
        `${[...modes].join('; ')} | ${[...union].map(([a, b]) => `${a}∈{${[...b].join(',')}}`).join(' ')} |`);
    }
    md.push('');
    md.push(`### Every failing case (${fails.length})`);
    md.push('');
    md.push('Address modes: c=clamp-to-edge, r=repeat, m=mirror-repeat. "bad/all" counts subcases.');
    md.push('');
    md.push('| test | case parameters | bad/all | failing subcase values | first failure message (shortened) |');
    md.push('| --- | --- | --- | --- | --- |');
    for (const x of fails) {
      const p = Object.entries(x.params).map(([k, v]) => `${k}=${v}`).join(' ');
      md.push(`| ${x.file}:${x.test} | ${p} | ${x.nBad.size}/${x.nSub.size} | ${subText(x)} | ` +
        `${x.firstMsg.replace(/\|/g, '\\|')} |`);
    }
    md.push('');
  }
}
process.stdout.write(md.join('\n') + '\n');
