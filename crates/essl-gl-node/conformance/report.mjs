#!/usr/bin/env node
// Turns the JSON lines of conformance runs into the committed results and the tables of
// docs/conformance.md.
//
//   node conformance/report.mjs --runs DIR [--write-results] [--markdown FILE] [--intro FILE] [--every N]
//
// DIR holds {chromium,essl-gl,gl}-{webgl2,webgl1}.jsonl from conformance/run.mjs.
// --write-results writes conformance/results/<impl>-<context>.json (per page: passed,
// failed, finished, error), the expectation the test suite's sample compares with.
// --markdown replaces the section of FILE that starts with the heading SECTION (or appends it).
// --every N says the runs took every Nth page (run.mjs --every N).
import { execSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { arch, cpus, platform } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { LEFT_OUT, LEFT_OUT_PAGES } from './list.mjs';

const here = dirname(fileURLToPath(import.meta.url));
export const SECTION = '## The WebGL conformance suite in Node (essl-gl-node)';

function args() {
  const a = {};
  const argv = process.argv.slice(2);
  for (let i = 0; i < argv.length; i++) {
    const k = argv[i].replace(/^--/, '');
    a[k] = argv[i + 1]?.startsWith('--') || argv[i + 1] === undefined ? true : argv[++i];
  }
  return a;
}

/** Page → result, from a JSON-lines file (the last line of a page wins). */
export function readRuns(file) {
  const out = new Map();
  if (!existsSync(file)) return out;
  for (const line of readFileSync(file, 'utf8').split('\n')) {
    if (!line.trim()) continue;
    const r = JSON.parse(line);
    out.set(r.page, r);
  }
  return out;
}

/** A page's folder as the tables group it (`conformance2/textures/misc`). */
function folder(page) {
  const parts = page.split('/');
  const depth = parts[1] === 'textures' || parts[1] === 'extensions' ? 3 : 2;
  return parts.slice(0, Math.min(depth, parts.length - 1)).join('/');
}

/** Rows per folder and a total: pages, Chromium's passes, essl-gl's, pages identical. */
export function table(chromium, essl, peer) {
  const rows = new Map();
  const total = { folder: '**all**', pages: 0, chromium: 0, essl: 0, matched: 0, identical: 0, crashed: 0, peer: 0 };
  for (const [page, c] of chromium) {
    const e = essl.get(page);
    if (!e) continue;
    const f = folder(page);
    if (!rows.has(f)) rows.set(f, { folder: f, pages: 0, chromium: 0, essl: 0, matched: 0, identical: 0, crashed: 0, peer: 0 });
    const p = peer?.get(page);
    for (const r of [rows.get(f), total]) {
      r.pages++;
      r.chromium += c.passed;
      r.essl += e.passed;
      r.matched += Math.min(c.passed, e.passed);
      if (c.passed === e.passed && c.failed === e.failed) r.identical++;
      if (e.crashed) r.crashed++;
      if (p) r.peer += Math.min(c.passed, p.passed);
    }
  }
  return { rows: [...rows.values()].sort((a, b) => a.folder.localeCompare(b.folder)), total };
}

function pct(a, b) {
  return b === 0 ? '–' : `${((100 * a) / b).toFixed(2)} %`;
}

function markdownTable(t, peerName) {
  const head = `| folder | pages | assertions Chromium passes | of those essl-gl passes | essl-gl passes (all) | pages identical |${peerName ? ` ${peerName} passes |` : ''}`;
  const sep = `|---|---:|---:|---:|---:|---:|${peerName ? '---:|' : ''}`;
  const line = (r) =>
    `| ${r.folder} | ${r.pages} | ${r.chromium} | ${r.matched} (${pct(r.matched, r.chromium)}) | ${r.essl} | ${r.identical} |${peerName ? ` ${r.peer} (${pct(r.peer, r.chromium)}) |` : ''}`;
  return [head, sep, ...t.rows.map(line), line(t.total)].join('\n');
}

function main() {
  const a = args();
  const dir = a.runs;
  const contexts = ['webgl2', 'webgl1'];
  const parts = [];
  for (const ctx of contexts) {
    const chromium = readRuns(join(dir, `chromium-${ctx}.jsonl`));
    const essl = readRuns(join(dir, `essl-gl-${ctx}.jsonl`));
    const gl = readRuns(join(dir, `gl-${ctx}.jsonl`));
    if (a['write-results']) {
      mkdirSync(join(here, 'results'), { recursive: true });
      for (const [impl, runs] of [['chromium', chromium], ['essl-gl', essl], ['gl', gl]]) {
        if (runs.size === 0) continue;
        const out = {};
        for (const [page, r] of [...runs].sort()) {
          out[page] = { passed: r.passed, failed: r.failed, finished: r.finished, error: r.error ? r.error.slice(0, 200) : null };
        }
        writeFileSync(join(here, 'results', `${impl}-${ctx}.json`), `${JSON.stringify(out, null, 1)}\n`);
      }
    }
    if (chromium.size === 0 || essl.size === 0) continue;
    const t = table(chromium, essl, gl.size ? gl : null);
    const title = ctx === 'webgl2' ? 'WebGL 2 context (the suite\'s 2.0.1 list)' : 'WebGL 1 context (conformance/, the suite\'s 1.0.4 list)';
    parts.push(`### ${title}\n\n${markdownTable(t, gl.size ? 'headless-gl' : null)}\n`);
    const worst = [...chromium]
      .filter(([p]) => essl.has(p))
      .map(([p, c]) => ({ p, lost: c.passed - Math.min(c.passed, essl.get(p).passed), e: essl.get(p) }))
      .filter((x) => x.lost > 0)
      .sort((x, y) => y.lost - x.lost)
      .slice(0, 25);
    if (worst.length) {
      parts.push(`Pages where essl-gl passes fewest of Chromium's assertions (${ctx}):\n\n${worst
        .map((x) => `- \`${x.p}\`: ${x.lost} fewer${x.e.error ? ` (${x.e.error.slice(0, 80).replace(/\n/g, ' ')})` : ''}`)
        .join('\n')}\n`);
    }
    console.log(`${ctx}: ${t.total.matched}/${t.total.chromium} (${pct(t.total.matched, t.total.chromium)}), identical pages ${t.total.identical}/${t.total.pages}, crashed ${t.total.crashed}`);
  }
  if (a.markdown && parts.length) {
    const leftOut = [
      ...LEFT_OUT.map(([p, why]) => `- \`${p}*\`: ${why}`),
      ...LEFT_OUT_PAGES.map(([re, why]) => `- pages matching \`${re.source.replace(/\\/g, '')}\`: ${why}`),
    ].join('\n');
    const sample = a.every
      ? `This run took every ${a.every}th page of each context's list (\`run.mjs --every ${a.every}\`, the first page, the ${Number(a.every) + 1}th, …), in one invocation of \`scripts/gl-node-conformance.sh --every ${a.every}\`: Chromium's pages first, then essl-gl's, context by context.\n`
      : '';
    const where = machine();
    const section = `${SECTION}\n\n${a.intro ? readFileSync(a.intro, 'utf8') : ''}\n${sample}${where}\n\n${parts.join('\n')}\nFolders and pages left out (in both contexts), and why:\n\n${leftOut}\n`;
    const file = a.markdown;
    const old = existsSync(file) ? readFileSync(file, 'utf8') : '';
    const at = old.indexOf(SECTION);
    writeFileSync(file, `${at >= 0 ? old.slice(0, at) : `${old.trimEnd()}\n\n`}${section}`);
  }
}

/** Where the tables were made: commit, cores, CPU, Chromium and Mesa versions. */
function machine() {
  const run = (cmd) => {
    try {
      return execSync(cmd, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }).trim();
    } catch {
      return '?';
    }
  };
  const commit = run('git rev-parse --short HEAD');
  const dirty = run("git status --porcelain --untracked-files=no -- ../../crates ../../scripts ':(exclude)conformance/results'") ? ' (with uncommitted changes)' : '';
  const cpu = run("grep -m1 'model name' /proc/cpuinfo | cut -d: -f2").trim();
  const chromium = run('chromium --version').split(' built')[0];
  const mesa = run("dpkg-query -W -f '${Version}' mesa-vulkan-drivers");
  return `Made at commit \`${commit}\`${dirty} on ${cpus().length} cores (${cpu}), ${platform()} ${arch()}: essl-gl on Mesa ${mesa}'s lavapipe, ${chromium} on SwiftShader.`;
}

main();
