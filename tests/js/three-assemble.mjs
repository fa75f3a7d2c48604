// Writes the GLSL that three.js hands to WebGL2 for the shader objects of its examples
// (`three/examples/jsm/shaders/*.js`): each exported object with a `vertexShader` and a
// `fragmentShader`, made into a material as ShaderPass makes it (`defines` copied, uniforms
// cloned) — a RawShaderMaterial where its vertex shader declares `position` itself, as
// OutputPass does for OutputShader — and built by three.js's own WebGLProgram in a WebGL2
// context (a mesh, no lights, no tone mapping, sRGB output), as NAME.vert + NAME.frag in the
// folder given (NAME: the file's name, `-`, the export's name), from the three.js that
// scripts/fetch-js-libs.sh installs beside this file:
//   node tests/js/three-assemble.mjs OUT_DIR
import {mkdirSync, readdirSync, writeFileSync} from 'node:fs';
import {dirname, join} from 'node:path';
import {fileURLToPath, pathToFileURL} from 'node:url';
import * as S from 'three';
import {build} from './three-build.mjs';

const out = process.argv[2];
mkdirSync(out, {recursive: true});
const shaders = join(dirname(fileURLToPath(import.meta.url)), 'node_modules/three/examples/jsm/shaders');

const raw = /^\s*(?:attribute|in)\s+vec3\s+position\s*;|^\s*uniform\s+mat4\s+(?:modelViewMatrix|projectionMatrix)\s*;/m;
const written = [];
for (const file of readdirSync(shaders).filter(f => f.endsWith('.js')).sort()) {
  const module = await import(pathToFileURL(join(shaders, file)).href);
  for (const [name, shader] of Object.entries(module)) {
    if (typeof shader?.vertexShader !== 'string' || typeof shader?.fragmentShader !== 'string') continue;
    const Kind = raw.test(shader.vertexShader) ? S.RawShaderMaterial : S.ShaderMaterial;
    const material = new Kind({name: shader.name || name, defines: Object.assign({}, shader.defines),
      uniforms: S.UniformsUtils.clone(shader.uniforms || {}), vertexShader: shader.vertexShader,
      fragmentShader: shader.fragmentShader, glslVersion: shader.glslVersion || null});
    const [vs, fs] = build(material);
    const base = `${file.replace(/\.js$/, '')}-${name}`;
    writeFileSync(join(out, `${base}.vert`), vs);
    writeFileSync(join(out, `${base}.frag`), fs);
    written.push(base);
  }
}
console.log(written.join(' '));
