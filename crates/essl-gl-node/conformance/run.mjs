#!/usr/bin/env node
// Runs the WebGL conformance suite's pages against an implementation and writes one JSON
// line per page (resumable: pages already in the output are skipped).
//
//   node conformance/run.mjs --impl essl-gl|chromium|gl --context webgl2|webgl1 \
//     [--sdk DIR] [--pages FILE] [--only SUBSTRING] [--every N] [--jobs N] [--timeout S] --out FILE
//
// --sdk defaults to $ESSL_WEBGL_SDK, else test-data/webgl/sdk/tests of the repository
// (scripts/gl-node-conformance.sh fetches it). --pages reads page paths, one a line.
// --every N keeps every Nth page of the list (the first, the N+1th, …): a fixed sample.
// essl-gl and gl run each page in its own Node process (a page that crashes or hangs is
// recorded as such and the run goes on); chromium runs pages in tabs of one browser.
import { spawn } from 'node:child_process';
import { appendFileSync, existsSync, readFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { leftOut, suite } from './list.mjs';

const here = dirname(fileURLToPath(import.meta.url));

function args() {
  const a = { impl: 'essl-gl', context: 'webgl2', jobs: 2, timeout: 120 };
  const argv = process.argv.slice(2);
  for (let i = 0; i < argv.length; i++) {
    const k = argv[i].replace(/^--/, '');
    a[k] = argv[++i];
  }
  a.jobs = Number(a.jobs);
  a.timeout = Number(a.timeout);
  a.sdk = resolve(a.sdk ?? process.env.ESSL_WEBGL_SDK ?? join(here, '../../../test-data/webgl/sdk/tests'));
  if (!a.out) throw new Error('--out FILE is required');
  return a;
}

/** The pages of the run, in order. */
export function selectPages(a) {
  let pages;
  if (a.pages) {
    pages = readFileSync(a.pages, 'utf8').split('\n').map((l) => l.trim()).filter(Boolean);
  } else {
    pages = suite(a.sdk)[a.context].filter((p) => !leftOut(p));
  }
  if (a.only) pages = pages.filter((p) => p.includes(a.only));
  if (a.every) pages = pages.filter((_, i) => i % Number(a.every) === 0);
  return pages;
}

function done(out) {
  const seen = new Set();
  if (!existsSync(out)) return seen;
  for (const line of readFileSync(out, 'utf8').split('\n')) {
    if (!line.trim()) continue;
    try {
      seen.add(JSON.parse(line).page);
    } catch {
      // A line cut short by a killed run is run again.
    }
  }
  return seen;
}

/** One page in a child Node process, killed after the timeout (and a grace period). */
function nodePage(a, page, version) {
  return new Promise((resolvePage) => {
    const t0 = Date.now();
    const child = spawn(
      process.execPath,
      [join(here, 'page.mjs'), a.sdk, page, String(version), String(a.timeout), '--impl', a.impl],
      { stdio: ['ignore', 'pipe', 'pipe'] },
    );
    let out = '';
    let err = '';
    child.stdout.on('data', (d) => (out += d));
    child.stderr.on('data', (d) => (err += d));
    const kill = setTimeout(() => child.kill('SIGKILL'), (a.timeout + 30) * 1000);
    child.on('close', (code, signal) => {
      clearTimeout(kill);
      const line = out.split('\n').find((l) => l.startsWith('{'));
      let r;
      if (line) r = JSON.parse(line);
      else {
        r = { page, version, passed: 0, failed: 0, finished: false, failures: [], error: null };
        r.error = `process ended (${signal ?? `exit ${code}`}) without a result: ${err.slice(-800)}`;
        r.crashed = true;
      }
      r.seconds = (Date.now() - t0) / 1000;
      resolvePage(r);
    });
  });
}

async function main() {
  const a = args();
  const version = a.context === 'webgl1' ? 1 : 2;
  const seen = done(a.out);
  const pages = selectPages(a).filter((p) => !seen.has(p));
  console.error(`${a.impl} ${a.context}: ${pages.length} pages to run (${seen.size} done)`);
  let run;
  let close = async () => {};
  if (a.impl === 'chromium') {
    const { serve, launch, runPage } = await import('./chromium.mjs');
    const server = await serve(a.sdk);
    let browser = await launch();
    run = async (page) => {
      const t0 = Date.now();
      if (!browser.isConnected()) browser = await launch();
      const r = await runPage(browser, server.url, page, version, a.timeout * 1000);
      r.seconds = (Date.now() - t0) / 1000;
      return r;
    };
    close = async () => {
      await browser.close().catch(() => {});
      server.close();
    };
  } else {
    run = (page) => nodePage(a, page, version);
  }
  let next = 0;
  let count = 0;
  const worker = async () => {
    while (next < pages.length) {
      const page = pages[next++];
      const r = await run(page);
      appendFileSync(a.out, `${JSON.stringify(r)}\n`);
      count++;
      const status = r.error ? ` [${r.error.slice(0, 60)}]` : '';
      console.error(`${count}/${pages.length} ${page}: ${r.passed} passed, ${r.failed} failed${status}`);
    }
  };
  await Promise.all(Array.from({ length: a.jobs }, worker));
  await close();
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
