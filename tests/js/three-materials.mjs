// Writes the GLSL that three.js hands to WebGL2 for the materials the classes of its examples
// make (`three/examples/jsm`: postprocessing passes, objects, lines, materials, helpers, …):
// every exported class whose constructor runs in Node with one of a few argument lists (none;
// a scene and a camera; a resolution and bloom settings; a scene, a camera and a size; a
// geometry and options), every ShaderMaterial reachable from the instance (its properties, three
// levels deep), each distinct pair of texts once, built by three.js's own WebGLProgram
// (three-build.mjs) as NAME.vert + NAME.frag in the folder given, NAME being the class's file
// (`/` as `_`), `-`, the class and `-`, a count. OUT_DIR/materials.json says where each text
// is written in the package: `FILE@BYTE` (the first file under examples/jsm holding the text
// as it stands, FILE relative to examples/jsm), or null for a text the script computes.
//   node tests/js/three-materials.mjs OUT_DIR
import {mkdirSync, readdirSync, readFileSync, statSync, writeFileSync} from 'node:fs';
import {dirname, join, relative} from 'node:path';
import {fileURLToPath, pathToFileURL} from 'node:url';
import * as S from 'three';
import {build} from './three-build.mjs';

const out = process.argv[2];
mkdirSync(out, {recursive: true});
const jsm = join(dirname(fileURLToPath(import.meta.url)), 'node_modules/three/examples/jsm');
// Folders without WebGL materials, or whose modules need a network or a browser to load.
const SKIP = /^(libs|shaders|tsl|transpiler|inspector|loaders|exporters|webxr|physics|capabilities|renderers)$/;
// Constructors that reach for a canvas get one that has no context.
globalThis.document = {
  createElement: () => ({getContext: () => null, style: {}}),
  createElementNS: () => ({getContext: () => null, style: {}}),
};

const files = [];
(function walk(d) {
  for (const f of readdirSync(d).sort()) {
    const p = join(d, f);
    if (statSync(p).isDirectory()) {
      if (!SKIP.test(f)) walk(p);
    } else if (p.endsWith('.js')) {
      files.push(p);
    }
  }
})(jsm);
const everyFile = [];
(function walk(d) {
  for (const f of readdirSync(d).sort()) {
    const p = join(d, f);
    if (statSync(p).isDirectory()) walk(p);
    else if (p.endsWith('.js')) everyFile.push([relative(jsm, p), readFileSync(p)]);
  }
})(jsm);

/** `FILE@BYTE` of the first file holding `text` as written, or null. */
function where(text) {
  const needle = Buffer.from(text);
  for (const [rel, bytes] of everyFile) {
    const at = bytes.indexOf(needle);
    if (at >= 0) return `${rel}@${at}`;
  }
  return null;
}

function materials(o, seen, depth, found) {
  if (!o || typeof o !== 'object' || seen.has(o) || depth > 3 || ArrayBuffer.isView(o)) return;
  seen.add(o);
  if (o.isShaderMaterial) found.push(o);
  for (const v of Object.values(o)) materials(v, seen, depth + 1, found);
}

const camera = new S.PerspectiveCamera();
const scene = new S.Scene();
const geometry = new S.PlaneGeometry();
const ARGUMENTS = [
  [],
  [scene, camera],
  [new S.Vector2(256, 256), 1, 0.5, 0.8],
  [scene, camera, 256, 256],
  [geometry, {}],
];
const quiet = console.warn;
const manifest = {};
const done = new Set();
for (const file of files) {
  let module;
  try {
    module = await import(pathToFileURL(file).href);
  } catch {
    continue;
  }
  for (const [name, Class] of Object.entries(module)) {
    if (typeof Class !== 'function' || !/^[A-Z]/.test(name)) continue;
    const found = [];
    console.warn = () => {};
    for (const args of ARGUMENTS) {
      try {
        materials(new Class(...args), new Set(), 0, found);
        break;
      } catch {
        // The next argument list.
      }
    }
    console.warn = quiet;
    let count = 0;
    for (const m of found) {
      const key = `${m.vertexShader}\0${m.fragmentShader}\0${JSON.stringify(m.defines || {})}`;
      if (done.has(key)) continue;
      done.add(key);
      const base = `${relative(jsm, file).replace(/\.js$/, '').replaceAll('/', '_')}-${name}-${count++}`;
      const [vs, fs] = build(m);
      writeFileSync(join(out, `${base}.vert`), vs);
      writeFileSync(join(out, `${base}.frag`), fs);
      manifest[base] = {vertex: where(m.vertexShader), fragment: where(m.fragmentShader)};
    }
  }
}
writeFileSync(join(out, 'materials.json'), JSON.stringify(manifest, null, 1));
console.log(Object.keys(manifest).length);
