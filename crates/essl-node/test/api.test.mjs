// The JavaScript API: check, link, translate, format and runCli, each option, and bad input
// (a thrown TypeError or Error with a message; the process never crashes).
import {test} from 'node:test';
import assert from 'node:assert/strict';
import {existsSync, mkdtempSync, writeFileSync, rmSync, mkdirSync} from 'node:fs';
import {tmpdir} from 'node:os';
import {join} from 'node:path';
import {check, checkAsync, link, translate, format, runCli} from '../index.js';

const FS = `#version 300 es
precision mediump float;
uniform vec4 u_color;
out vec4 o;
void main() { o = u_color; }
`;
const VS = `#version 300 es
in vec4 a_position;
uniform mat4 u_matrix;
void main() { gl_Position = u_matrix * a_position; }
`;

test('a valid shader has no diagnostics', () => {
  const r = check(FS, {stage: 'fragment'});
  assert.equal(r.ok, true);
  assert.equal(r.errors, 0);
  assert.deepEqual(r.diagnostics, []);
  assert.equal(r.shaders[0].stage, 'fragment');
});

test('an error has its code, range, label, help, fix and text', () => {
  const r = check(FS.replace('o = u_color', 'o = vec4(normalise(u_color.xyz), 1.0)'), {stage: 'fragment'});
  assert.equal(r.errors, 1);
  const [d] = r.diagnostics;
  assert.equal(d.code, 'undeclared-function');
  assert.equal(d.severity, 'error');
  assert.deepEqual([d.range.start.line, d.range.start.column, d.range.end.column], [5, 24, 33]);
  assert.match(d.help, /normalize/);
  assert.equal(d.fix.edits[0].text, 'normalize');
  assert.match(d.rendered, /^error\[undeclared-function\]/);
  assert.match(d.rendered, /shader\.frag:5:24/);
  assert.equal(format(r), d.rendered);
  assert.equal(format(r.diagnostics), d.rendered);
});

test('checkAsync gives what check gives, many at once', async () => {
  const bad = FS.replace('u_color;\n}', 'u_colour;\n}').replace('o = u_color', 'o = u_colour');
  const results = await Promise.all(Array.from({length: 16}, (_, i) => checkAsync(i % 2 ? bad : FS, {stage: 'fragment'})));
  assert.deepEqual(results.map(r => r.errors), Array.from({length: 16}, (_, i) => i % 2));
  assert.deepEqual(results[1], check(bad, {stage: 'fragment'}));
  await assert.rejects(checkAsync(FS, {stage: 'geometry'}), TypeError);
  await assert.rejects(checkAsync(FS, {rules: {nope: 'deny'}}), TypeError);
  await assert.rejects(checkAsync(null), TypeError);
});

test('checkAsync settles each check of a batch on its own', async () => {
  // Asked for in one turn of the event loop, these go to the addon together.
  const settled = await Promise.allSettled([
    checkAsync(FS, {stage: 'fragment'}),
    checkAsync(FS, {stage: 'fragment', rules: {nope: 'deny'}}),
    checkAsync('#version 300 es\nvoid main() { gl_Position = vec4(0.0); }\n', {filename: 'bad.frag'}),
    checkAsync(VS, {stage: 'vertex'}),
  ]);
  assert.deepEqual(settled.map(s => s.status), ['fulfilled', 'rejected', 'fulfilled', 'fulfilled']);
  assert.ok(settled[1].reason instanceof TypeError);
  assert.match(settled[1].reason.message, /^essl\.checkAsync: .*nope/);
  assert.equal(settled[0].value.errors, 0);
  assert.ok(settled[2].value.errors > 0);
  assert.deepEqual(settled[3].value, check(VS, {stage: 'vertex'}));
});

test('every error in one call, and secondary ranges', () => {
  const r = check(FS.replace('o = u_color;', 'float a = b; int c = 1.0; o = u_color;'), {stage: 'fragment'});
  assert.deepEqual(r.diagnostics.map(d => d.code), ['undeclared-identifier', 'type-mismatch']);
});

test('target webgl1 refuses GLSL ES 3.00', () => {
  assert.equal(check(FS, {stage: 'fragment', target: 'webgl2'}).errors, 0);
  const r = check(FS, {stage: 'fragment', target: 'webgl1'});
  assert.ok(r.errors > 0);
});

test('defines are macros the shader reads', () => {
  const src = FS.replace('o = u_color;', 'o = u_color * SCALE;');
  assert.equal(check(src, {stage: 'fragment'}).errors, 1);
  assert.equal(check(src, {stage: 'fragment', defines: {SCALE: '2.0'}}).errors, 0);
  assert.equal(check(src, {stage: 'fragment', defines: {SCALE: 2}}).errors, 1, 'the int 2 times a vec4');
});

test('#include from the file folder and from includeDirs; includes: false leaves the line', () => {
  const dir = mkdtempSync(join(tmpdir(), 'essl-api-'));
  try {
    mkdirSync(join(dir, 'chunks'));
    writeFileSync(join(dir, 'chunks', 'tint.glsl'), 'vec4 tint(vec4 c) { return c * 0.5; }\n');
    const src = FS.replace('out vec4 o;', 'out vec4 o;\n#include "tint.glsl"').replace('o = u_color', 'o = tint(u_color)');
    const filename = join(dir, 'a.frag');
    assert.ok(check(src, {filename}).errors > 0, 'not found beside the file');
    const r = check(src, {filename, includeDirs: [join(dir, 'chunks')]});
    assert.equal(r.errors, 0, format(r));
    assert.match(r.shaders[0].text, /vec4 tint/);
    assert.ok(r.shaders[0].files.some(f => f.endsWith('tint.glsl')));
    const left = check(src, {filename: join(dir, 'chunks', 'b.frag'), includes: false});
    assert.ok(left.errors > 0, 'WebGL has no #include');
    assert.ok(!left.diagnostics.some(d => d.code === 'include-not-found'));
  } finally {
    rmSync(dir, {recursive: true, force: true});
  }
});

test('rules, lints, denyWarnings and a config file', () => {
  const src = FS.replace('o = u_color;', 'o = u_color / (u_color.g - u_color.b);');
  const warned = check(src, {stage: 'fragment'});
  assert.equal(warned.errors, 0);
  const codes = warned.diagnostics.filter(d => d.severity === 'warning').map(d => d.code);
  assert.ok(codes.length > 0, 'a lint finding');
  assert.equal(check(src, {stage: 'fragment', lints: false}).diagnostics.length, 0);
  assert.equal(check(src, {stage: 'fragment', rules: {[codes[0]]: 'allow'}}).warnings, codes.length - 1);
  assert.ok(check(src, {stage: 'fragment', rules: {[codes[0]]: 'deny'}}).errors > 0);
  assert.ok(check(src, {stage: 'fragment', denyWarnings: true}).errors > 0);
  const dir = mkdtempSync(join(tmpdir(), 'essl-api-'));
  try {
    writeFileSync(join(dir, 'essl.toml'), 'target = "webgl1"\n');
    assert.ok(check(FS, {stage: 'fragment', config: join(dir, 'essl.toml')}).errors > 0);
    assert.ok(check(FS, {filename: join(dir, 'a.frag')}).errors > 0, 'the nearest essl.toml');
  } finally {
    rmSync(dir, {recursive: true, force: true});
  }
});

test('variants: the lints check the code an #ifdef flag compiles in', () => {
  const src = FS.replace('uniform vec4 u_color;', 'uniform vec4 u_color;\nuniform float u_fogStart, u_fogEnd;')
    .replace('o = u_color;', 'o = u_color;\n#ifdef USE_FOG\n  o *= (u_fogEnd - gl_FragCoord.z) / (u_fogEnd - u_fogStart);\n#endif\n');
  const found = check(src, {stage: 'fragment'}).diagnostics.filter(d => d.severity === 'warning');
  assert.equal(found.length, 1, JSON.stringify(found));
  assert.equal(found[0].range.start.line, 8);
  assert.ok(found[0].notes.some(n => n.includes('`USE_FOG`')), found[0].notes.join('\n'));
  assert.equal(check(src, {stage: 'fragment', variants: 0}).warnings, 0);
  assert.equal(check(src, {stage: 'fragment', variants: false}).warnings, 0);
  assert.equal(check(src, {stage: 'fragment', variants: true}).warnings, 1);
  assert.equal(check(src, {stage: 'fragment', defines: {USE_FOG: 1}, variants: 0}).warnings, 1);
  assert.throws(() => check(src, {stage: 'fragment', variants: -1}), {name: 'TypeError', message: /options.variants must be a boolean or a whole number/});
});

test('a JS module: its shaders found, ${} constants put in, positions in the module', () => {
  const js = `const N = '4';\nexport const fs = /* glsl */\`${FS.replace('o = u_color;', 'o = u_color * float(${N}) + missing;')}\`;\n`;
  const r = check(js, {filename: 'module.js'});
  assert.equal(r.shaders.length, 1);
  assert.equal(r.errors, 1);
  assert.equal(r.diagnostics[0].range.start.line, 6);
  assert.ok(r.diagnostics[0].file.endsWith('module.js'));
});

test('a JS module with two shaders given to one program is linked', () => {
  const js = `const vs = \`${VS}\`;\nconst fs = \`${FS}\`;\ngl.shaderSource(a, vs); gl.shaderSource(b, fs);\nconst p = createProgram(gl, vs, fs);\n`;
  const r = check(js, {filename: 'program.js'});
  assert.equal(r.errors, 0, format(r));
  assert.equal(r.programs.length, 1);
  assert.deepEqual(r.programs[0].uniforms.map(u => u.name).sort(), ['u_color', 'u_matrix']);
});

test('link: the program as linkProgram makes it', () => {
  const p = link(VS, FS);
  assert.equal(p.ok, true);
  assert.deepEqual(p.uniforms.map(u => [u.name, u.type]), [['u_matrix', 'FLOAT_MAT4'], ['u_color', 'FLOAT_VEC4']]);
  assert.deepEqual(p.attributes.map(a => [a.name, a.type]), [['a_position', 'FLOAT_VEC4']]);
  const bad = link(
    VS.replace('void main', 'out vec3 v_n;\nvoid main'),
    FS.replace('out vec4 o;', 'out vec4 o;\nin vec4 v_n;').replace('o = u_color', 'o = u_color + v_n'),
  );
  assert.equal(bad.ok, false);
  assert.equal(bad.diagnostics[0].code, 'varying-type-mismatch');
});

test('translate: WGSL text, SPIR-V words and the binding map', () => {
  const w = translate(VS, FS, {to: 'wgsl'});
  assert.match(w.vertex, /@vertex/);
  assert.match(w.fragment, /@fragment/);
  assert.ok(JSON.stringify(w.bindings).includes('u_color'));
  const s = translate(VS, FS, {to: 'spirv'});
  assert.ok(s.vertex instanceof Uint32Array);
  assert.equal(s.vertex[0], 0x07230203);
  assert.throws(() => translate(VS, FS.replace('u_color;', 'u_colour;')), /fragment shader has 1 error/);
  assert.throws(() => translate(VS, FS, {to: 'dxil'}), TypeError);
});

test('bad input is a TypeError or an Error with a message', () => {
  assert.throws(() => check(42), {name: 'TypeError', message: 'essl.check: source must be a string, not a number'});
  assert.throws(() => check(undefined), TypeError);
  assert.throws(() => check(FS, 'fragment'), /options must be an object, not a string/);
  assert.throws(() => check(FS, {stage: 'compute'}), {name: 'TypeError', message: /options.stage must be 'vertex' or 'fragment'/});
  assert.throws(() => check(FS, {target: 'webgl3'}), {name: 'TypeError', message: /options.target/});
  assert.throws(() => check(FS, {stagee: 'vertex'}), {name: 'TypeError', message: /options.stagee is not an option/});
  // A stage the file name contradicts (the name would win, silently).
  assert.throws(() => check(FS, {stage: 'vertex', filename: 'light.frag'}), {
    name: 'TypeError',
    message: "essl.check: options.stage is 'vertex', but options.filename 'light.frag' names a fragment shader",
  });
  assert.throws(() => check(FS, {stage: 'vertex', filename: 'light.fs.glsl'}), /names a fragment shader/);
  assert.equal(check(FS, {stage: 'fragment', filename: 'light.frag'}).errors, 0);
  assert.equal(check(FS, {stage: 'fragment', filename: 'light.glsl'}).shaders[0].stage, 'fragment');
  assert.throws(() => check(FS, {rules: {'no-such-rule': 'deny'}}), {name: 'TypeError', message: /no-such-rule/});
  assert.throws(() => check(FS, {defines: ['A']}), {name: 'TypeError', message: /options.defines must be an object/});
  assert.throws(() => check(FS, {preset: 'babylon'}), {name: 'TypeError', message: /options.preset/});
  assert.throws(() => check('x'.repeat(64 << 20), {stage: 'fragment'}), /over essl's limit/);
  assert.throws(() => link(VS), {name: 'TypeError', message: /fragment must be a string/});
  assert.throws(() => format('x'), TypeError);
  assert.throws(() => runCli('lint'), TypeError);
});

test('hostile text: deep nesting, a macro bomb and lone surrogates are diagnostics', () => {
  const deep = FS.replace('o = u_color;', `o = u_color * ${'('.repeat(5000)}1.0${')'.repeat(5000)};`);
  assert.ok(check(deep, {stage: 'fragment'}).errors > 0);
  let bomb = '#define A0 x\n';
  for (let i = 1; i < 40; i++) bomb += `#define A${i} A${i - 1} A${i - 1}\n`;
  assert.ok(check(`${bomb}A39\n`, {stage: 'fragment'}).errors > 0);
  assert.equal(typeof check(FS + '// \ud800\n', {stage: 'fragment'}).errors, 'number');
});

test('runCli is the essl command', () => {
  const dir = mkdtempSync(join(tmpdir(), 'essl-api-'));
  try {
    writeFileSync(join(dir, 'a.frag'), FS.replace('u_color;\n', 'u_colour;\n'));
    assert.equal(runCli(['lint', '--format', 'concise', join(dir, 'a.frag')]), 1);
    writeFileSync(join(dir, 'a.frag'), FS);
    assert.equal(runCli(['lint', join(dir, 'a.frag')]), 0);
    assert.equal(runCli(['--version']), 0);
    assert.equal(runCli(['no-such-command']), 2);
  } finally {
    rmSync(dir, {recursive: true, force: true});
  }
});

// The pinned three.js that scripts/fetch-js-libs.sh installs for the `three` preset.
const threeDir = join(import.meta.dirname, '..', '..', '..', 'tests', 'js');
const haveThree = existsSync(join(threeDir, 'node_modules', 'three', 'package.json'));

test('preset three: a ShaderMaterial checked with three.js prelude', {skip: !haveThree && 'three is not installed (scripts/fetch-js-libs.sh)'}, () => {
  const js = [
    "import { ShaderMaterial } from 'three';",
    'export const m = new ShaderMaterial({',
    '  vertexShader: /* glsl */`',
    '    void main() { gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0); }`,',
    '  fragmentShader: /* glsl */`',
    '    uniform vec3 tint;',
    '    void main() { gl_FragColor = vec4(tint * colour, 1.0); }`,',
    '});',
  ].join('\n');
  const filename = join(threeDir, 'src', 'material.js');
  const r = check(js, {filename, preset: 'three'});
  assert.deepEqual(r.diagnostics.map(d => [d.code, d.range.start.line, d.range.start.column]), [['undeclared-identifier', 7, 46]]);
  assert.ok(check(js, {filename}).errors > 1, 'without the preset, the prelude names are undeclared');
});

test('a config that names no file is an error, not a check of nothing', () => {
  const fs = '#version 300 es\nprecision mediump float;\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n';
  const config = join(tmpdir(), 'essl-no-such-config', 'essl.toml');
  assert.throws(() => check(fs, {stage: 'fragment', config}), {name: 'Error', message: /^essl\.check: .*essl\.toml: no such file or directory/});
});

test('link and translate refuse one filename or stage for two shaders; defines JSON cannot carry are TypeErrors', () => {
  const vs = '#version 300 es\nin vec4 p;\nvoid main() { gl_Position = p; }\n';
  const fs = '#version 300 es\nprecision mediump float;\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n';
  assert.throws(() => link(vs, fs, {filename: 'a.vert'}), {name: 'TypeError', message: /^essl\.link: options\.filename would name both shaders; use options\.vertexFilename/});
  assert.throws(() => translate(vs, fs, {stage: 'vertex'}), {name: 'TypeError', message: /^essl\.translate: options\.stage would name both shaders/});
  assert.equal(link(vs, fs, {vertexFilename: 'a.vert', fragmentFilename: 'a.frag'}).ok, true);
  for (const bad of [1n, NaN, Infinity, null, {}, [1]]) {
    assert.throws(() => check(fs, {stage: 'fragment', defines: {A: bad}}), {name: 'TypeError', message: /^essl\.check: options\.defines\.A must be a string, a finite number or a boolean/});
  }
  assert.equal(check(fs, {stage: 'fragment', defines: {A: '1', B: 2, C: true}}).ok, true);
});

test('messages name options, not the command line; format takes only diagnostics', () => {
  assert.throws(() => check('void main() {}'), {name: 'TypeError', message: /pass options\.stage \('vertex' or 'fragment'\)$/});
  assert.throws(() => format([1, 2]), {name: 'TypeError', message: /^essl\.format: expected diagnostics or a result/});
  const r = check('#version 300 es\nvoid main() { x; }\n', {stage: 'fragment'});
  assert.match(format(r), /error\[undeclared-identifier\]/);
  assert.match(format(r.diagnostics), /error\[undeclared-identifier\]/);
});
