// minify and minifyAsync: comments, white space and local names go; uniform, attribute,
// varying and output names stay; the result compiles and links as the original did; a shader
// with errors is not minified; bad arguments throw TypeErrors.
import {test} from 'node:test';
import assert from 'node:assert/strict';
import {check, link, minify, minifyAsync} from '../index.js';

const VS = `#version 300 es
// a lit vertex
in vec4 a_position;
in vec3 a_normal;
uniform mat4 u_matrix;
uniform mat3 u_normalMatrix;
out vec3 v_normal;
vec4 project(vec4 position) { return u_matrix * position; }
void main() {
  gl_Position = project(a_position);  /* clip space */
  v_normal = u_normalMatrix * a_normal;
}
`;
const FS = `#version 300 es
precision highp float;
struct Light { vec3 direction; vec3 color; };
uniform Light u_light;
uniform Material { vec4 u_tint; };
in vec3 v_normal;
out vec4 outColor;
float lambert(vec3 normal, vec3 toLight) {
  float amount = max(dot(normal, toLight), 0.0);
  return amount;
}
void main() {
  vec3 normal = normalize(v_normal);
  outColor = vec4(u_light.color * lambert(normal, -u_light.direction), 1.0) * u_tint;
}
`;

test('minify shortens local names and keeps every interface name', () => {
  const r = minify(FS, {stage: 'fragment'});
  assert.equal(r.ok, true);
  assert.ok(r.text.length < FS.length * 0.8, r.text);
  assert.deepEqual(Object.keys(r.renamed).sort(), ['amount', 'lambert', 'normal', 'toLight']);
  for (const name of ['u_light', 'direction', 'color', 'Material', 'u_tint', 'v_normal', 'outColor', 'Light']) {
    assert.match(r.text, new RegExp(`\\b${name}\\b`));
  }
  assert.match(r.text, /^#version 300 es\n/);
  assert.doesNotMatch(r.text, /\/\/|\/\*/);
});

test('the minified pair compiles and links with the same uniforms and attributes', () => {
  const vs = minify(VS, {stage: 'vertex'}).text;
  const fs = minify(FS, {stage: 'fragment'}).text;
  assert.equal(check(vs, {stage: 'vertex'}).ok, true);
  const before = link(VS, FS);
  const after = link(vs, fs);
  assert.equal(after.ok, true);
  assert.deepEqual(after.uniforms, before.uniforms);
  assert.deepEqual(after.attributes, before.attributes);
});

test('rename: false removes comments and white space only', () => {
  const r = minify(VS, {stage: 'vertex', rename: false});
  assert.deepEqual(r.renamed, {});
  assert.match(r.text, /vec4 project\(vec4 position\)\{return u_matrix\*position;\}/);
});

test('a WebGL 1 shader keeps its attributes and varyings', () => {
  const es1 = 'attribute vec4 a_position;\nvarying vec4 v_color;\nvoid main() {\n  vec4 p = a_position;\n  v_color = p;\n  gl_Position = p;\n}\n';
  const r = minify(es1, {stage: 'vertex', target: 'webgl1'});
  assert.equal(r.text, 'attribute vec4 a_position;varying vec4 v_color;void main(){vec4 a=a_position;v_color=a;gl_Position=a;}');
});

test('defines are those the shader is checked and minified with', () => {
  const src = '#version 300 es\nprecision highp float;\nout vec4 o;\n#ifdef USE_FOG\nuniform float fog;\n#endif\nvoid main() { float k = 1.0;\n#ifdef USE_FOG\n k *= fog;\n#endif\n o = vec4(k); }\n';
  const r = minify(src, {stage: 'fragment', defines: {USE_FOG: true}});
  assert.equal(r.ok, true);
  assert.match(r.text, /uniform float fog;/);
  assert.equal(check(r.text, {stage: 'fragment', defines: {USE_FOG: true}}).ok, true);
  assert.equal(check(r.text, {stage: 'fragment'}).ok, true);
});

test('a shader with errors is not minified; its diagnostics say why', () => {
  const r = minify(FS.replace('normalize(v_normal)', 'normalise(v_normal)'), {stage: 'fragment'});
  assert.equal(r.ok, false);
  assert.equal(r.text, null);
  assert.equal(r.diagnostics[0].code, 'undeclared-function');
});

test('minifyAsync gives the same text', async () => {
  assert.equal((await minifyAsync(FS, {stage: 'fragment'})).text, minify(FS, {stage: 'fragment'}).text);
});

test('bad arguments throw TypeErrors with a message', () => {
  assert.throws(() => minify(42), {name: 'TypeError', message: 'essl.minify: source must be a string, not a number'});
  assert.throws(() => minify(FS, 'fragment'), {name: 'TypeError', message: /options must be an object/});
  assert.throws(() => minify(FS, {stage: 'fragment', rename: 'yes'}), {
    name: 'TypeError',
    message: 'essl.minify: options.rename must be a boolean, not a string',
  });
  assert.throws(() => minify(FS, {stage: 'fragment', preset: 'three'}), {name: 'TypeError', message: /preset 'three' is not minified/});
  assert.throws(() => minify('const s = 1;', {filename: 'a.js'}), {name: 'TypeError', message: /one shader's text/});
  assert.throws(() => minify(FS, {stage: 'fragment', bogus: 1}), {name: 'TypeError'});
});

test('the plugins take minify as a boolean only', async () => {
  const {default: essl} = await import('../lib/vite.js');
  assert.throws(() => essl({minify: 'yes'}), {name: 'TypeError', message: 'essl(): options.minify must be a boolean'});
  assert.equal(essl({minify: true}).name, 'essl');
});
