// essl's npm API against spglsl (ANGLE's translator compiled to WebAssembly, npm) on the WebGL
// conformance ES 3.00 and ES 1.00 corpora and dEQP (../shared/corpora or $ESSL_CORPORA), in
// one run: agreement with the expected answers under the corpora's scoring rules, and time
// per shader through each package's JavaScript API. spglsl checks one shader at a time (no
// linking), so a case it passes is one whose compile results alone give the answer.
//
//   node bench/peers.mjs [--limit N] [--rounds R]   (from crates/essl-node, after `npm run build`)
//
// Each corpus is timed in R rounds (default 5), the two packages alternating and taking turns
// to go first; the figure is each package's median round, so that a burst of load on a shared
// machine moves one round rather than the ratio; essl's round repeats a corpus for at least
// 500 ms. spglsl runs each round in a worker thread of
// its own, after its own warm-up: its WebAssembly instance breaks for good after some thousands
// of calls (`RuntimeError: null function or function signature mismatch`, then every call
// throws), and a fresh instance per round keeps its answers those of a working compiler.
//
// Prints a Markdown table for docs/performance.md.
import {readFileSync, existsSync} from 'node:fs';
import {join, dirname} from 'node:path';
import {fileURLToPath} from 'node:url';
import {execFileSync} from 'node:child_process';
import {Worker, isMainThread, parentPort, workerData} from 'node:worker_threads';

const here = dirname(fileURLToPath(import.meta.url));
const corpora = process.env.ESSL_CORPORA || join(here, '..', '..', '..', '..', 'shared', 'corpora');
if (!existsSync(corpora)) {
  console.error(`peers: no corpora at ${corpora} (set ESSL_CORPORA)`);
  process.exit(process.env.ESSL_REQUIRE_CORPORA === '1' ? 1 : 0);
}
const {spglslAngleCompile} = await import('spglsl');
const limitAt = process.argv.indexOf('--limit');
const limit = limitAt > 0 ? Number(process.argv[limitAt + 1]) : Infinity;
const roundsAt = process.argv.indexOf('--rounds');
const ROUNDS = roundsAt > 0 ? Number(process.argv[roundsAt + 1]) : 5;

function read(name) {
  return readFileSync(join(corpora, name), 'utf8').trim().split('\n').map(l => JSON.parse(l)).slice(0, limit);
}

// Each case as {vertex, fragment, target, want(compiledV, compiledF, linked) -> pass}.
const SETS = {
  'WebGL ES 3.00': read('webgl_conformance_es300.jsonl').map(c => ({
    vertex: c.vertex_source,
    fragment: c.fragment_source,
    target: 'webgl2',
    pass: (v, f, l) => (c.outcome === 'must_fail' ? !(v && f && l) : v && f && l),
  })),
  'WebGL ES 1.00 (WebGL 2 context)': read('webgl_conformance_es100.jsonl')
    .filter(c => c.chromium_webgl2)
    .map(c => {
      const want = c.chromium_webgl2;
      return {
        vertex: c.vertex_source,
        fragment: c.fragment_source,
        target: 'webgl2',
        pass: (v, f, l) => v === want.vertex && f === want.fragment && (!(v && f) || l === want.link),
      };
    }),
  dEQP: read('deqp_gles3.jsonl')
    .filter(c => c.version === '300 es')
    .map(c => ({
      vertex: c.vertex_source,
      fragment: c.fragment_source,
      target: 'webgl2',
      pass: (v, f, l) => {
        if (c.expect === 'compile_fail') return !(v && f);
        if (c.expect === 'link_fail') return v && f && !l;
        if (c.expect === 'compile_link_fail') return !(v && f && l);
        return v && f && l;
      },
    })),
};

const link = isMainThread ? (await import('../index.js')).link : null;

function essl(c) {
  const p = link(c.vertex, c.fragment, {target: c.target, lints: false});
  return [p.vertex.ok, p.fragment.ok, p.ok];
}

async function spglsl(c) {
  const one = async (src, language) => {
    try {
      const r = await spglslAngleCompile({mainSourceCode: src, language, compileMode: 'Validate'});
      return r.valid;
    } catch {
      return false;
    }
  };
  const v = await one(c.vertex, 'Vertex');
  const f = await one(c.fragment, 'Fragment');
  // No linker: a program of two valid shaders counts as linked.
  return [v, f, v && f];
}

async function warmUp(cases, run) {
  // One untimed pass over a few cases (spglsl's WebAssembly compile, essl's first calls).
  for (const c of cases.slice(0, 20)) await run(c);
}

// One timed round: the cases that pass (first pass), and wall-clock µs per shader. A round
// makes passes over the corpus until `minMs` have gone by: essl's pass over the ES 3.00 corpus
// takes under 20 ms, where the timer and a scheduler tick are a large share.
async function measure(cases, run, minMs = 0) {
  let passed = null;
  let passes = 0;
  const start = process.hrtime.bigint();
  let ns = 0;
  do {
    let p = 0;
    for (const c of cases) if (c.pass(...(await run(c)))) p++;
    passed ??= p;
    passes++;
    ns = Number(process.hrtime.bigint() - start);
  } while (ns < minMs * 1e6);
  return {passed, usPerShader: ns / 1000 / (cases.length * 2 * passes)};
}

const median = a => [...a].sort((x, y) => x - y)[a.length >> 1];

// One timed round of spglsl on a corpus, in a worker thread with a fresh instance.
function spglslRound(set) {
  return new Promise((resolve, reject) => {
    const w = new Worker(new URL(import.meta.url), {workerData: {set}, argv: process.argv.slice(2)});
    w.once('message', resolve);
    w.once('error', reject);
  });
}

if (!isMainThread) {
  const cases = SETS[workerData.set];
  await warmUp(cases, spglsl);
  parentPort.postMessage(await measure(cases, spglsl));
} else {
  const commit = (() => {
    try {
      return execFileSync('git', ['rev-parse', '--short', 'HEAD'], {encoding: 'utf8'}).trim();
    } catch {
      return '?';
    }
  })();
  console.log(`essl npm API vs spglsl ${JSON.parse(readFileSync(join(here, '..', 'node_modules', 'spglsl', 'package.json'))).version}, commit ${commit}, Node ${process.version}, ${(await import('node:os')).cpus()[0].model}\n`);
  console.log(`${ROUNDS} rounds per corpus, the packages alternating; medians\n`);
  console.log('| corpus | cases | essl agrees | spglsl agrees | essl µs/shader | spglsl µs/shader | spglsl / essl time | rounds: spglsl / essl |');
  console.log('|---|---|---|---|---|---|---|---|');
  for (const [name, cases] of Object.entries(SETS)) {
    await warmUp(cases, essl);
    const rounds = {essl: () => measure(cases, essl, 500), spglsl: () => spglslRound(name)};
    const runs = {essl: [], spglsl: []};
    for (let r = 0; r < ROUNDS; r++) {
      const order = r % 2 ? ['spglsl', 'essl'] : ['essl', 'spglsl'];
      for (const who of order) runs[who].push(await rounds[who]());
    }
    const e = median(runs.essl.map(x => x.usPerShader));
    const s = median(runs.spglsl.map(x => x.usPerShader));
    const each = runs.essl.map((x, i) => (runs.spglsl[i].usPerShader / x.usPerShader).toFixed(1)).join(', ');
    console.log(
      `| ${name} | ${cases.length} | ${runs.essl[0].passed} | ${runs.spglsl[0].passed} | ${e.toFixed(0)} | ${s.toFixed(0)} | ${(s / e).toFixed(1)}× | ${each} |`,
    );
  }
}
