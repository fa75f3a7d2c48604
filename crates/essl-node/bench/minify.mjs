// essl's minify against spglsl's (ANGLE's translator in WebAssembly, npm: `compileMode:
// 'Optimize', minify: true`, names kept; and with `mangle: true`, which renames attributes
// and varyings too) on the webgl2fundamentals shaders and the WebGL conformance ES 3.00 and
// ES 1.00 corpora (../shared/corpora or $ESSL_CORPORA), in one run. For every pair both
// shaders of which essl accepts: the bytes before and after, whether each output compiles
// (essl's check, and ANGLE's through spglsl's Validate mode), and whether the minified pair
// links with the original's active uniforms and attributes.
//
//   node bench/minify.mjs [--limit N]      (from crates/essl-node, after `npm run build`)
//
// Prints a Markdown table for docs/javascript.md.
import {readFileSync, existsSync} from 'node:fs';
import {join, dirname} from 'node:path';
import {fileURLToPath} from 'node:url';
import {execFileSync} from 'node:child_process';
import {check, link, minify} from '../index.js';

const here = dirname(fileURLToPath(import.meta.url));
const corpora = process.env.ESSL_CORPORA || join(here, '..', '..', '..', '..', 'shared', 'corpora');
if (!existsSync(corpora)) {
  console.error(`minify bench: no corpora at ${corpora} (set ESSL_CORPORA)`);
  process.exit(process.env.ESSL_REQUIRE_CORPORA === '1' ? 1 : 0);
}
const {spglslAngleCompile} = await import('spglsl');
const limitAt = process.argv.indexOf('--limit');
const limit = limitAt > 0 ? Number(process.argv[limitAt + 1]) : Infinity;

function read(name) {
  return readFileSync(join(corpora, name), 'utf8').trim().split('\n').map(l => JSON.parse(l)).slice(0, limit);
}

// Each set: pairs {vertex, fragment, target}; a lone shader has the other stage null.
const SETS = {
  webgl2fundamentals: read('webgl2fundamentals_shaders.jsonl').map(c => ({
    vertex: c.stage === 'vertex' ? c.source : null,
    fragment: c.stage === 'fragment' ? c.source : null,
    target: 'webgl2',
  })),
  'WebGL conformance ES 3.00': read('webgl_conformance_es300.jsonl').map(c => ({
    vertex: c.vertex_source,
    fragment: c.fragment_source,
    target: 'webgl2',
  })),
  'WebGL conformance ES 1.00': read('webgl_conformance_es100.jsonl').map(c => ({
    vertex: c.vertex_source,
    fragment: c.fragment_source,
    target: 'webgl1',
  })),
};

const STAGES = [
  ['vertex', 'Vertex'],
  ['fragment', 'Fragment'],
];

async function angleValid(src, language) {
  try {
    return (await spglslAngleCompile({mainSourceCode: src, language, compileMode: 'Validate'})).valid;
  } catch {
    return false;
  }
}

async function spglslMinify(src, language, mangle) {
  try {
    const r = await spglslAngleCompile({mainSourceCode: src, language, compileMode: 'Optimize', minify: true, mangle});
    return r.valid && typeof r.output === 'string' ? r.output : null;
  } catch {
    return null;
  }
}

/** What WebGL reads of a linked program. */
const face = p => JSON.stringify([p.ok, p.uniforms, p.attributes]);

const MINIFIERS = {
  essl: async (src, stage, target) => {
    try {
      return minify(src, {stage, target, lints: false}).text;
    } catch {
      return null;
    }
  },
  spglsl: (src, stage, target, language) => spglslMinify(src, language, false),
  'spglsl mangle': (src, stage, target, language) => spglslMinify(src, language, true),
};

async function run(cases) {
  const tally = {};
  for (const name of Object.keys(MINIFIERS)) tally[name] = {before: 0, after: 0, shaders: 0, failed: 0, essl: 0, angle: 0, pairs: 0, same: 0};
  for (const c of cases) {
    const accepted = STAGES.map(([stage]) => c[stage] !== null && check(c[stage], {stage, target: c.target, lints: false}).ok);
    if (!STAGES.every(([stage], i) => c[stage] === null || accepted[i])) continue;
    // Each minifier's output per stage (null: it failed).
    const outs = {};
    for (const [name, m] of Object.entries(MINIFIERS)) {
      outs[name] = {};
      for (const [stage, language] of STAGES) {
        if (c[stage] !== null) outs[name][stage] = await m(c[stage], stage, c.target, language);
      }
    }
    for (const [name, out] of Object.entries(outs)) {
      const t = tally[name];
      for (const [stage, language] of STAGES) {
        if (c[stage] === null) continue;
        const text = out[stage];
        t.shaders++;
        if (text === null) {
          t.failed++;
          continue;
        }
        // Bytes over the shaders every minifier minified, so that the totals compare.
        if (Object.values(outs).every(o => o[stage] !== null)) {
          t.before += Buffer.byteLength(c[stage]);
          t.after += Buffer.byteLength(text);
        }
        if (check(text, {stage, target: c.target, lints: false}).ok) t.essl++;
        if (await angleValid(text, language)) t.angle++;
      }
      if (c.vertex !== null && c.fragment !== null && out.vertex && out.fragment) {
        t.pairs++;
        const before = link(c.vertex, c.fragment, {target: c.target, lints: false});
        try {
          if (face(link(out.vertex, out.fragment, {target: c.target, lints: false})) === face(before)) t.same++;
        } catch {
          // A text essl cannot read as a shader: not the same program.
        }
      }
    }
  }
  return tally;
}

const commit = (() => {
  try {
    return execFileSync('git', ['rev-parse', '--short', 'HEAD'], {encoding: 'utf8'}).trim();
  } catch {
    return '?';
  }
})();
const version = JSON.parse(readFileSync(join(here, '..', 'node_modules', 'spglsl', 'package.json'))).version;
console.log(`essl minify vs spglsl ${version}, commit ${commit}, Node ${process.version}, ${(await import('node:os')).cpus()[0].model}\n`);
console.log('| corpus | minifier | shaders | minified | bytes before → after (shaders all three minified) | smaller | output compiles (essl / ANGLE) | pairs linking as before |');
console.log('|---|---|---|---|---|---|---|---|');
for (const [corpus, cases] of Object.entries(SETS)) {
  const tally = await run(cases);
  for (const [name, t] of Object.entries(tally)) {
    const minified = t.shaders - t.failed;
    const saved = (100 * (1 - t.after / Math.max(1, t.before))).toFixed(1);
    console.log(
      `| ${corpus} | ${name} | ${t.shaders} | ${minified} | ${t.before} → ${t.after} | ${saved} % | ${t.essl} / ${t.angle} | ${t.pairs ? `${t.same} of ${t.pairs}` : '–'} |`,
    );
  }
}
