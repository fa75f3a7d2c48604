// Assembles GLSL shader pairs with the luma.gl (and deck.gl) that the project has installed,
// as luma.gl's Model (or a deck.gl layer's getShaders) does on a WebGL2 device; run by essl's
// `luma` preset with the project's folder as the working folder.
//
// stdin:  {"programs": [{"id", "deck", "vs", "fs", "defines", "modules": [ref]}]}, where a ref
//         is {"package", "export"} (a module the package exports) or {"local": {"name", "vs",
//         "fs", "defines", "dependencies": [ref]}} (a module written in the project).
// stdout: {"versions": {package: version}, "programs": [{"id", "vs", "fs"} | {"id", "error"}]}
import {readFileSync} from 'node:fs';
import {join} from 'node:path';

const input = JSON.parse(await new Promise(resolve => {
  let text = '';
  process.stdin.setEncoding('utf8');
  process.stdin.on('data', d => (text += d));
  process.stdin.on('end', () => resolve(text));
}));

const versions = {};
const packages = {};
async function load(name) {
  if (!(name in packages)) {
    try {
      packages[name] = await import(name);
      try {
        const file = join(process.cwd(), 'node_modules', name, 'package.json');
        versions[name] = JSON.parse(readFileSync(file, 'utf8')).version;
      } catch {}
    } catch (e) {
      packages[name] = null;
    }
  }
  return packages[name];
}

const shadertools = await load('@luma.gl/shadertools');
if (!shadertools) {
  process.stdout.write(JSON.stringify({error: 'cannot import @luma.gl/shadertools'}));
  process.exit(0);
}
const gpu = 'unknown';
const platformInfo = {type: 'webgl', shaderLanguage: 'glsl', shaderLanguageVersion: 300, gpu,
  limits: {}, features: new Set()};

// deck.gl configures luma's assembler (its default module `geometry`, the DECKGL_FILTER_* hooks)
// and adds its default modules (`layer`) when a LayerManager is made.
let deck = null;
const anyDeck = input.programs.some(p => p.deck);
if (anyDeck) {
  const core = await load('@deck.gl/core');
  if (core && core.LayerManager) {
    const device = {type: 'webgl', info: {shadingLanguage: 'glsl', shadingLanguageVersion: 300, gpu},
      limits: {}, features: new Set()};
    try {
      deck = new core.LayerManager(device, {}).context;
    } catch {}
  }
}

async function module(ref) {
  if (ref.package) {
    const p = await load(ref.package);
    const m = p && p[ref.export];
    if (!m) throw new Error(`${ref.package} exports no module \`${ref.export}\``);
    return m;
  }
  const l = ref.local;
  return {
    name: l.name,
    vs: l.vs ?? undefined,
    fs: l.fs ?? undefined,
    defines: l.defines || {},
    dependencies: await Promise.all((l.dependencies || []).map(module))
  };
}

const out = [];
for (const p of input.programs) {
  try {
    let modules = await Promise.all(p.modules.map(module));
    let assembler = new shadertools.GLSLShaderAssembler();
    if (p.deck && deck) {
      modules = [...modules, ...deck.defaultShaderModules];
      assembler = deck.shaderAssembler;
    }
    const seen = new Set();
    modules = modules.filter(m => (seen.has(m.name) ? false : (seen.add(m.name), true)));
    const r = assembler.assembleGLSLShaderPair({
      platformInfo,
      vs: p.vs,
      fs: p.fs,
      modules,
      defines: p.defines || {},
      pluginInjections: {},
      pluginVertexInputs: {},
      pluginVaryings: {}
    });
    out.push({id: p.id, vs: r.vs, fs: r.fs});
  } catch (e) {
    out.push({id: p.id, error: String((e && e.message) || e)});
  }
}
process.stdout.write(JSON.stringify({versions, programs: out}));
