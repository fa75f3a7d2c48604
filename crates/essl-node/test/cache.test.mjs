// The plugin's cache of checks between builds: a second build takes a module's check from the
// cache (seen by a kept warning's text, changed in the cache file), and a change to the
// module, to a file its `#include` read or to the nearest `essl.toml` checks it again; results
// with errors are not kept; `cache: false` writes nothing.
import {test} from 'node:test';
import assert from 'node:assert/strict';
import {existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync} from 'node:fs';
import {tmpdir} from 'node:os';
import {join} from 'node:path';

let rollup = null;
try {
  rollup = await import('rollup');
} catch {
  // Not installed: the tests skip.
}
const skip = rollup ? false : 'rollup is not installed (npm ci in crates/essl-node)';
if (skip && process.env.ESSL_REQUIRE_CORPORA === '1') throw new Error(skip);
const {default: essl} = await import('../lib/vite.js');

const FRAG = `#version 300 es
precision highp float;
uniform float u_inner, u_outer;
in float v_d;
out vec4 o;
#include "ramp.glsl"
void main() { o = vec4(ramp(v_d)); }
`;
const RAMP = 'float ramp(float d) { return clamp((d - u_outer) / (u_inner - u_outer), 0.0, 1.0); }\n';

function project() {
  const dir = mkdtempSync(join(tmpdir(), 'essl-cache-'));
  mkdirSync(join(dir, 'src'));
  writeFileSync(join(dir, 'src', 'light.frag'), FRAG);
  writeFileSync(join(dir, 'src', 'ramp.glsl'), RAMP);
  writeFileSync(join(dir, 'src', 'main.js'), "import light from './light.frag';\nexport default light;\n");
  return dir;
}

async function build(dir, options) {
  const warnings = [];
  const bundle = await rollup.rollup({
    input: join(dir, 'src', 'main.js'),
    plugins: [essl(options)],
    onwarn: w => warnings.push(w.message),
  });
  const {output} = await bundle.generate({format: 'es'});
  await bundle.close();
  return {warnings, code: output[0].code};
}

const kept = cache => JSON.parse(readFileSync(join(cache, 'checks.json'), 'utf8'));

// Marks every kept warning, so that a build that takes its check from the cache shows it.
function mark(cache) {
  const file = kept(cache);
  for (const [, entry] of file.entries) for (const w of entry.checked.warnings) w.rendered = `KEPT ${w.rendered}`;
  writeFileSync(join(cache, 'checks.json'), JSON.stringify(file));
}

test('a second build takes an unchanged check from the cache', {skip}, async () => {
  const dir = project();
  const cache = join(dir, 'cache');
  try {
    const first = await build(dir, {cache});
    assert.ok(first.warnings.some(w => w.includes('division-by-difference')), first.warnings.join('\n'));
    assert.equal(kept(cache).entries.length, 1);
    mark(cache);
    const second = await build(dir, {cache});
    assert.ok(second.warnings.some(w => w.includes('KEPT warning[division-by-difference]')), second.warnings.join('\n'));
    assert.equal(second.code, first.code, 'the text the module exports, includes in place');
  } finally {
    rmSync(dir, {recursive: true, force: true});
  }
});

test('a module that includes nothing is kept without its text and exported whole', {skip}, async () => {
  const dir = project();
  const cache = join(dir, 'cache');
  try {
    writeFileSync(join(dir, 'src', 'light.frag'), FRAG.replace('#include "ramp.glsl"', RAMP));
    const first = await build(dir, {cache});
    const [[, entry]] = kept(cache).entries;
    assert.equal(typeof entry.checked.text, 'number', 'the text is the module\'s own');
    assert.equal(entry.checked.files, undefined, 'the module read no other file');
    mark(cache);
    const second = await build(dir, {cache});
    assert.ok(second.warnings.some(w => w.includes('KEPT warning[division-by-difference]')), second.warnings.join('\n'));
    assert.equal(second.code, first.code);
    assert.ok(second.code.includes('u_inner - u_outer'), second.code);
  } finally {
    rmSync(dir, {recursive: true, force: true});
  }
});

test('a change to an included file, the module or essl.toml checks it again', {skip}, async () => {
  const dir = project();
  const cache = join(dir, 'cache');
  const fresh = async () => {
    mark(cache);
    const {warnings} = await build(dir, {cache});
    const found = warnings.filter(w => w.includes('division-by-difference'));
    return found.length > 0 && found.every(w => !w.includes('KEPT '));
  };
  try {
    await build(dir, {cache});
    writeFileSync(join(dir, 'src', 'ramp.glsl'), RAMP.replace('0.0, 1.0', '0.0, 2.0'));
    assert.ok(await fresh(), 'an included file changed');
    writeFileSync(join(dir, 'src', 'light.frag'), `${FRAG}// edited\n`);
    assert.ok(await fresh(), 'the module changed');
    writeFileSync(join(dir, 'essl.toml'), '[rules]\n"division-by-difference" = "warn"\n');
    // The addon keeps settings read for one second.
    await new Promise(r => setTimeout(r, 1100));
    assert.ok(await fresh(), 'an essl.toml appeared');
    mark(cache);
    const again = await build(dir, {cache});
    assert.ok(again.warnings.some(w => w.includes('KEPT warning')), 'nothing changed: from the cache');
  } finally {
    rmSync(dir, {recursive: true, force: true});
  }
});

test('a check with errors is not kept; cache: false writes nothing', {skip}, async () => {
  const dir = project();
  const cache = join(dir, 'cache');
  try {
    writeFileSync(join(dir, 'src', 'ramp.glsl'), RAMP.replace('clamp', 'clamb'));
    await assert.rejects(build(dir, {cache}), /clamb/);
    assert.ok(!existsSync(join(cache, 'checks.json')) || kept(cache).entries.length === 0);
    await assert.rejects(build(dir, {cache}), /clamb/);
    writeFileSync(join(dir, 'src', 'ramp.glsl'), RAMP);
    await build(dir, {cache: false});
    assert.ok(!existsSync(join(cache, 'checks.json')) || kept(cache).entries.length === 0);
    assert.ok(!existsSync(join(dir, 'node_modules')), 'no default cache folder either');
    assert.throws(() => essl({cache: 3}), /options.cache must be a boolean or a folder's path/);
  } finally {
    rmSync(dir, {recursive: true, force: true});
  }
});

test('an essl.toml the options name is read again when it changes', {skip}, async () => {
  const dir = project();
  const cache = join(dir, 'cache');
  const config = join(dir, 'lint.toml');
  const lints = async () => (await build(dir, {cache, config})).warnings.filter(w => w.includes('division-by-difference'));
  try {
    writeFileSync(config, '[rules]\n"division-by-difference" = "allow"\n');
    assert.equal((await lints()).length, 0);
    writeFileSync(config, '[rules]\n"division-by-difference" = "warn"\n');
    // The addon keeps settings read for one second.
    await new Promise(r => setTimeout(r, 1100));
    assert.equal((await lints()).length, 1);
  } finally {
    rmSync(dir, {recursive: true, force: true});
  }
});

test('in vite dev, a check sees an included file changed since the last one', {skip}, async () => {
  const dir = project();
  const plugin = essl({cache: join(dir, 'cache')});
  plugin.configResolved({command: 'serve', root: dir});
  plugin.buildStart();
  const id = join(dir, 'src', 'light.frag');
  const code = plugin.load.handler(id);
  const context = {
    warnings: [],
    meta: {},
    addWatchFile() {},
    warn(w) {
      this.warnings.push(w);
    },
    error(e) {
      throw e;
    },
  };
  try {
    const first = await plugin.transform.handler.call(context, code, id);
    assert.match(first.code, /clamp\(\(d - u_outer\)/);
    writeFileSync(join(dir, 'src', 'ramp.glsl'), RAMP.replace('clamp', 'clamb'));
    await assert.rejects(plugin.transform.handler.call(context, code, id), /clamb/);
    writeFileSync(join(dir, 'src', 'ramp.glsl'), RAMP);
    const fixed = await plugin.transform.handler.call(context, code, id);
    assert.equal(fixed.code, first.code);
  } finally {
    rmSync(dir, {recursive: true, force: true});
  }
});
