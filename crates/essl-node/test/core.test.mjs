// What the plugins and the loader share (lib/core.js): which modules they check, and which text
// they check for a module.
import {test} from 'node:test';
import assert from 'node:assert/strict';
import {existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync} from 'node:fs';
import {tmpdir} from 'node:os';
import {join} from 'node:path';
import {MAYBE_WANTED, SHADER, checkModule, file, wanted} from '../lib/core.js';

const FRAG = '#version 300 es\nprecision mediump float;\nuniform vec4 u_c;\nout vec4 o;\nvoid main() { o = u_c; }\n';

test('a # belongs to the path; a query does not', () => {
  assert.equal(file('/p/C#/light.frag?raw'), '/p/C#/light.frag');
  assert.equal(wanted('/p/C#/light.frag'), true);
  assert.equal(wanted('\0virtual.frag'), false);
});

test('a RegExp with the g flag includes every file it matches, not every other one', () => {
  const include = /\.frag$/g;
  assert.deepEqual(['/a.frag', '/b.frag', '/c.frag'].map(id => wanted(id, {include})), [true, true, true]);
});

test("a ?url module's code is not the shader: the file is checked", async () => {
  const dir = mkdtempSync(join(tmpdir(), 'essl-core-'));
  try {
    const f = join(dir, 'light.frag');
    writeFileSync(f, FRAG);
    const url = await checkModule(`${f}?url`, 'export default "data:text/plain;base64,AAAA"');
    assert.deepEqual(url.errors, []);
    // A ?raw module's code is the text as a JSON string: that text is checked.
    const raw = await checkModule(`${f}?raw`, `export default ${JSON.stringify(FRAG.replace('u_c;\nout', 'u_c;\nuniform float u_broken\nout'))}`);
    assert.equal(raw.errors.length, 1);
    // A webpack loader's source (the loaders before it may have changed the file's text).
    const given = await checkModule(f, FRAG.replace('o = u_c;', 'o = u_d;'), {}, true);
    assert.deepEqual(given.errors.map(e => e.code), ['undeclared-identifier']);
  } finally {
    rmSync(dir, {recursive: true, force: true});
  }
});

const threeDir = join(import.meta.dirname, '..', '..', '..', 'tests', 'js');
const haveThree = existsSync(join(threeDir, 'node_modules', 'three', 'package.json'));

test('preset three: a ShaderMaterial without a glsl tag or #version is checked', {skip: !haveThree && 'three is not installed (scripts/fetch-js-libs.sh)'}, async () => {
  const js = [
    "import { ShaderMaterial } from 'three';",
    'export const m = new ShaderMaterial({',
    '  vertexShader: `void main() { gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0); }`,',
    '  fragmentShader: `uniform vec3 tint; void main() { gl_FragColor = vec4(tint * colour, 1.0); }`,',
    '});',
  ].join('\n');
  const checked = await checkModule(join(threeDir, 'src', 'material.js'), js, {preset: 'three'});
  assert.ok(checked, 'the script is checked');
  assert.deepEqual(checked.errors.map(e => [e.code, e.range.start.line]), [['undeclared-identifier', 4]]);
});

test('a plugin option essl does not know is a TypeError, in the plugin and the loader', async () => {
  const {default: essl} = await import('../lib/vite.js');
  assert.throws(() => essl({failOnWarning: true}), {name: 'TypeError', message: /^essl\(\): unknown option failOnWarning \(known: .*failOnWarnings/});
  assert.equal(typeof essl({failOnWarnings: true, minify: true, include: /x/, exclude: 'y', load: false, lints: false}), 'object');
  const {createRequire} = await import('node:module');
  const loader = createRequire(import.meta.url)('../lib/webpack-loader.cjs');
  const err = await new Promise(resolve => {
    loader.call({async: () => resolve, getOptions: () => ({minfy: true}), resourcePath: '/x/a.frag', resourceQuery: ''}, FRAG);
  });
  assert.ok(err instanceof TypeError && /^essl\/webpack: unknown option minfy/.test(err.message), String(err));
});

test("the plugin's load leaves excluded shader files to other plugins", async () => {
  const {default: essl} = await import('../lib/vite.js');
  const dir = mkdtempSync(join(tmpdir(), 'essl-core-'));
  try {
    const f = join(dir, 'light.frag');
    writeFileSync(f, FRAG);
    assert.equal(essl().load.handler(f), `export default ${JSON.stringify(FRAG)};`);
    assert.equal(essl({exclude: 'light'}).load.handler(f), null);
    assert.equal(essl({include: /\.vert$/}).load.handler(f), null);
  } finally {
    rmSync(dir, {recursive: true, force: true});
  }
});

test('the webpack loader passes the source map and metadata of the loaders before it on', async () => {
  const {createRequire} = await import('node:module');
  const loader = createRequire(import.meta.url)('../lib/webpack-loader.cjs');
  const run = (resourcePath, source) =>
    new Promise(resolve => {
      const map = {version: 3, mappings: ''};
      const meta = {from: 'babel'};
      const ctx = {async: () => (...args) => resolve({args, map, meta}), getOptions: () => ({}), resourcePath, resourceQuery: '', addDependency() {}, emitWarning() {}};
      loader.call(ctx, source, map, meta);
    });
  const script = await run('/x/a.js', 'export const n = 1;\n');
  assert.equal(script.args[0], null);
  assert.equal(script.args[2], script.map);
  assert.equal(script.args[3], script.meta);
  const dir = mkdtempSync(join(tmpdir(), 'essl-core-'));
  try {
    const shader = await run(join(dir, 'a.frag'), FRAG);
    assert.deepEqual(shader.args.slice(0, 2), [null, FRAG]);
    assert.equal(shader.args[2], shader.map);
  } finally {
    rmSync(dir, {recursive: true, force: true});
  }
});

test('vite dev: creating the #include a failing shader missed reloads the page', async () => {
  const {default: essl} = await import('../lib/vite.js');
  const {EventEmitter} = await import('node:events');
  const dir = mkdtempSync(join(tmpdir(), 'essl-core-'));
  try {
    const f = join(dir, 'light.frag');
    writeFileSync(f, FRAG.replace('void main', '#include "common.glsl"\nvoid main'));
    const plugin = essl();
    const watcher = new EventEmitter();
    const sent = [];
    plugin.configResolved({command: 'serve'});
    plugin.configureServer({watcher, ws: {send: m => sent.push(m)}});
    const ctx = {addWatchFile() {}, warn() {}, error(e) { throw e; }, meta: {}};
    await assert.rejects(plugin.transform.handler.call(ctx, `export default ${JSON.stringify(readFileSync(f, 'utf8'))};`, f));
    watcher.emit('add', join(dir, 'other.js'));
    assert.deepEqual(sent, []);
    writeFileSync(join(dir, 'common.glsl'), 'float half(float x) { return x * 0.5; }\n');
    watcher.emit('add', join(dir, 'common.glsl'));
    assert.deepEqual(sent, [{type: 'full-reload'}]);
  } finally {
    rmSync(dir, {recursive: true, force: true});
  }
});

test("the hooks' filters let through every module the hooks act on", async () => {
  const {default: essl} = await import('../lib/vite.js');
  const plugin = essl();
  const ids = ['/p/light.frag', '/p/light.frag?raw', '/p/a.glsl?import&raw', '/p/main.ts', '/p/main.js?v=3', '/p/App.tsx',
    '/p/x.cjs', '/p/index.html?html-proxy&index=0.js', '/p/style.css', '/p/data.json', '/p/img.png?url', '\0virtual.frag'];
  for (const id of ids) {
    if (wanted(id)) assert.ok(plugin.transform.filter.id.test(id), id);
  }
  assert.equal(plugin.transform.filter.id, MAYBE_WANTED);
  assert.deepEqual(['/p/style.css', '/p/data.json', '/p/img.png?url'].map(id => MAYBE_WANTED.test(id)), [false, false, false]);
  // A `?raw` import is Vite's to load: the bundler need not call the plugin's `load`.
  assert.equal(plugin.load.filter.id, SHADER);
  assert.deepEqual(['/p/light.frag', '/p/light.frag?raw'].map(id => SHADER.test(id)), [true, false]);
});
