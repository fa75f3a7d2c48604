// Real builds with the plugins: Vite, Rollup and webpack (pinned in package-lock.json) on a
// small project (test/project) whose shaders are imported `.vert`/`.frag` files (linked as a
// pair), an `#include`d chunk and a `/* glsl */` template literal. An error planted in each
// (and a link error between the pair) fails the
// build with essl's message at the file, line and column the author wrote; the project as it
// is builds, with the included chunk in place in the output.
import {test} from 'node:test';
import assert from 'node:assert/strict';
import {cpSync, mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync} from 'node:fs';
import {tmpdir} from 'node:os';
import {dirname, join} from 'node:path';
import {fileURLToPath} from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));

// Each planted error: the file, the text replaced, what replaces it, and where essl reports it.
const PLANTED = [
  ['src/shaders/light.frag', 'u_color.rgb * lambert', 'u_colour.rgb * lambert', 'light.frag:9:19'],
  ['src/shaders/common.glsl', 'max(dot', 'max(dott', 'common.glsl:3:14'],
  // A link error: the fragment shader's input is not the vertex shader's output any more.
  ['src/shaders/light.vert', 'v_normal', 'v_norm', 'light.frag:4:9'],
  ['src/materials.js', 'u_outline * ${SCALE}', 'u_outline * ${SCALE} * u_missing', 'materials.js:8:37'],
];

function project(edit) {
  const dir = mkdtempSync(join(tmpdir(), 'essl-bundler-'));
  cpSync(join(here, 'project'), dir, {recursive: true});
  if (edit) {
    const [file, from, to] = edit;
    const path = join(dir, file);
    const text = readFileSync(path, 'utf8');
    assert.ok(text.includes(from), `${file} holds ${from}`);
    writeFileSync(path, text.replaceAll(from, to));
  }
  return dir;
}

async function modules() {
  try {
    return {
      vite: await import('vite'),
      rollup: await import('rollup'),
      webpack: (await import('webpack')).default,
    };
  } catch {
    return null;
  }
}

const tools = await modules();
const skip = tools ? false : 'vite, rollup and webpack are not installed (npm ci in crates/essl-node)';
if (skip && process.env.ESSL_REQUIRE_CORPORA === '1') throw new Error(skip);
const {default: essl} = await import('../lib/vite.js');
const loader = join(here, '..', 'lib', 'webpack-loader.cjs');
const {minify} = await import('../index.js');

async function viteBuild(dir, options = {}) {
  return tools.vite.build({
    root: dir,
    configFile: false,
    logLevel: 'silent',
    plugins: [essl(options)],
    build: {outDir: join(dir, 'dist'), minify: false},
  });
}

async function rollupBuild(dir, options = {}) {
  const bundle = await tools.rollup.rollup({input: join(dir, 'src/main.js'), plugins: [essl(options)], onwarn() {}});
  const {output} = await bundle.generate({format: 'es'});
  await bundle.close();
  return output[0].code;
}

function webpackBuild(dir, options = {}) {
  return new Promise((resolve, reject) => {
    tools.webpack(
      {
        mode: 'development',
        devtool: false,
        context: dir,
        entry: './src/main.js',
        output: {path: join(dir, 'dist'), filename: 'main.js'},
        module: {
          rules: [
            {test: /\.(glsl|vert|frag)$/, type: 'asset/source', use: [{loader, options}]},
            {test: /\.js$/, enforce: 'pre', use: [{loader, options}]},
          ],
        },
      },
      (err, stats) => {
        if (err) return reject(err);
        if (stats.hasErrors()) return reject(new Error(stats.toJson({all: false, errors: true}).errors.map(e => e.message).join('\n')));
        resolve(readFileSync(join(dir, 'dist', 'main.js'), 'utf8'));
      },
    );
  });
}

function output(dir) {
  const assets = join(dir, 'dist', 'assets');
  return readdirSync(assets).filter(f => f.endsWith('.js')).map(f => readFileSync(join(assets, f), 'utf8')).join('\n');
}

const BUILDS = {
  vite: async (dir, options) => (await viteBuild(dir, options), output(dir)),
  rollup: rollupBuild,
  webpack: webpackBuild,
};

for (const [name, build] of Object.entries(BUILDS)) {
  test(`${name}: the project builds, its chunk included`, {skip}, async () => {
    const dir = project(null);
    try {
      const code = await build(dir);
      assert.match(code, /float lambert\(vec3 n, vec3 l\)/);
      assert.doesNotMatch(code, /#include/);
    } finally {
      rmSync(dir, {recursive: true, force: true});
    }
  });
  test(`${name}: minify: true ships the minified shader files, interface names intact`, {skip}, async () => {
    const dir = project(null);
    try {
      const code = await build(dir, {minify: true});
      const fragment = minify(readFileSync(join(dir, 'src/shaders/light.frag'), 'utf8'), {
        filename: join(dir, 'src/shaders/light.frag'),
      });
      assert.equal(fragment.ok, true);
      // The bundle holds the minified text as a JS string literal.
      assert.ok(code.includes(JSON.stringify(fragment.text).slice(1, -1)), code);
      assert.match(code, /uniform vec3 u_lightDirection;uniform vec4 u_color;out vec4 outColor;/);
      assert.match(code, /in vec3 v_normal;/);
      assert.match(code, /in vec4 a_position;/);
      assert.doesNotMatch(code, /float lambert\(vec3 n, vec3 l\)/);
      // A template literal's shader in a script is left as it is.
      assert.match(code, /u_outline \* \$\{SCALE\}/);
    } finally {
      rmSync(dir, {recursive: true, force: true});
    }
  });
  for (const planted of PLANTED) {
    test(`${name}: an error in ${planted[0]} fails the build at ${planted[3]}`, {skip}, async () => {
      const dir = project(planted);
      try {
        await assert.rejects(build(dir), e => {
          const message = String(e.message);
          assert.ok(message.includes(`${planted[3]}`), message);
          assert.match(message, /error\[/);
          return true;
        });
      } finally {
        rmSync(dir, {recursive: true, force: true});
      }
    });
  }
}

// A `?raw` import (Vite's own loader makes its module; the plugin checks the file it names
// while the build goes on, and fails it at the end): an error fails the build at the file,
// line and column; the file as written builds, its text in the bundle.
const GLOW = '#version 300 es\nprecision mediump float;\nuniform vec4 u_glow;\nout vec4 outColor;\nvoid main() {\n  outColor = u_glow * 0.5;\n}\n';

function rawProject(glow) {
  const dir = project(null);
  writeFileSync(join(dir, 'src/shaders/glow.frag'), glow);
  const main = join(dir, 'src/main.js');
  const text = readFileSync(main, 'utf8');
  assert.ok(text.includes('outline};'), 'main.js lists the shaders');
  writeFileSync(main, `import glow from './shaders/glow.frag?raw';\n${text.replace('outline};', 'outline, glow};')}`);
  return dir;
}

test('vite: a ?raw import is checked: the file as written builds', {skip}, async () => {
  const dir = rawProject(GLOW);
  try {
    await viteBuild(dir);
    assert.match(output(dir), /outColor = u_glow \* 0\.5;/);
  } finally {
    rmSync(dir, {recursive: true, force: true});
  }
});

test('vite: an error in a ?raw import fails the build at glow.frag:6:14', {skip}, async () => {
  const dir = rawProject(GLOW.replace('u_glow * 0.5', 'u_glw * 0.5'));
  try {
    await assert.rejects(viteBuild(dir), e => {
      const message = String(e.message);
      assert.ok(message.includes('glow.frag:6:14'), message);
      assert.match(message, /error\[undeclared-identifier\]/);
      return true;
    });
  } finally {
    rmSync(dir, {recursive: true, force: true});
  }
});

test('vite: minify: true minifies a ?raw import in a one-shot build', {skip}, async () => {
  const dir = rawProject(GLOW);
  try {
    await viteBuild(dir, {minify: true});
    const minified = minify(GLOW, {filename: join(dir, 'src/shaders/glow.frag')});
    assert.equal(minified.ok, true);
    assert.match(minified.text, /uniform vec4 u_glow;out vec4 outColor;/);
    const code = output(dir);
    assert.ok(code.includes(JSON.stringify(minified.text).slice(1, -1)), code);
    assert.doesNotMatch(code, /outColor = u_glow \* 0\.5;/);
  } finally {
    rmSync(dir, {recursive: true, force: true});
  }
});
