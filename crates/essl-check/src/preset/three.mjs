// What three.js puts around a ShaderMaterial's (or RawShaderMaterial's) shaders in a WebGL2
// context, from the three.js the project has installed: its WebGLProgram run against a stand-in
// GL context that records the sources. Run by essl's `three` preset in the project's folder.
//
// stdin:  {"materials": [{"id", "raw", "glsl3", "instanced", "defines", "name",
//          "includes": [chunk]}]}
// stdout: {"version", "chunks": [names], "materials": [{"id", "vertex", "fragment",
//          "expanded": {chunk: {"vertex", "fragment"} | {"error"}}} | {"id", "error"}]}
// `vertex`/`fragment` are the text before the author's; `expanded` is each chunk as an
// `#include <chunk>` line of the author's becomes (its includes, light counts and unrolled loops
// in place).
import {readFileSync} from 'node:fs';
import {join} from 'node:path';

const input = JSON.parse(await new Promise(resolve => {
  let text = '';
  process.stdin.setEncoding('utf8');
  process.stdin.on('data', d => (text += d));
  process.stdin.on('end', () => resolve(text));
}));

const THREE = await import('three');
const {WebGLPrograms} = await import('three/src/renderers/webgl/WebGLPrograms.js');
const S = await import('three/src/Three.js');
// What an app runs: the chunks of the build, whose GLSL three's build minifies.
Object.assign(S.ShaderChunk, THREE.ShaderChunk);
let version = null;
try {
  version = JSON.parse(readFileSync(join(process.cwd(), 'node_modules/three/package.json'), 'utf8')).version;
} catch {}

// Sources the stand-in GL context was given, in order.
function build(material, instanced) {
  const sources = [];
  const gl = {VERTEX_SHADER: 0x8b31, FRAGMENT_SHADER: 0x8b30, createProgram: () => ({}),
    createShader: t => ({t}), shaderSource: (sh, src) => sources.push(src), compileShader() {},
    attachShader() {}, bindAttribLocation() {}, linkProgram() {}};
  const renderer = {getContext: () => gl, getRenderTarget: () => null,
    state: {buffers: {depth: {getReversed: () => false}}},
    toneMapping: S.NoToneMapping, outputColorSpace: S.SRGBColorSpace,
    shadowMap: {enabled: false, type: S.PCFShadowMap}, debug: {checkShaderErrors: true}};
  const caps = {precision: 'highp', logarithmicDepthBuffer: false, getMaxPrecision: p => p};
  const lights = {sun: [], sunShadowMap: [], directional: [], directionalShadowMap: [], point: [],
    pointShadowMap: [], spot: [], spotLightMap: [], spotShadowMap: [], rectArea: [], hemi: [],
    numSpotLightShadowsWithMaps: 0, numLightProbes: 0};
  const programs = WebGLPrograms(renderer, {get: () => null}, {has: () => false}, caps, {},
    {numPlanes: 0, numIntersection: 0});
  const object = instanced ? new S.InstancedMesh(new S.BoxGeometry(), material, 1)
    : new S.Mesh(new S.BoxGeometry(), material);
  const params = programs.getParameters(material, lights, [], {isScene: true, fog: null,
    environment: null}, object, []);
  params.uniforms = programs.getUniforms(material);
  programs.acquireProgram(params, programs.getProgramCacheKey(params));
  return sources;
}

const MARK = '/*essl-author*/';
function material(m, vertexShader, fragmentShader) {
  const Kind = m.raw ? S.RawShaderMaterial : S.ShaderMaterial;
  const parameters = {vertexShader, fragmentShader, defines: m.defines || {}, name: m.name || ''};
  if (m.glsl3) parameters.glslVersion = S.GLSL3;
  return new Kind(parameters);
}

const out = [];
for (const m of input.materials) {
  try {
    const [vs, fs] = build(material(m, MARK, MARK), m.instanced);
    const result = {id: m.id, vertex: vs.slice(0, vs.indexOf(MARK)),
      fragment: fs.slice(0, fs.indexOf(MARK)), expanded: {}};
    for (const chunk of m.includes || []) {
      try {
        const [v, f] = build(material(m, `${MARK}\n#include <${chunk}>\n${MARK}`,
          `${MARK}\n#include <${chunk}>\n${MARK}`), m.instanced);
        const inner = s => s.slice(s.indexOf(MARK) + MARK.length + 1, s.lastIndexOf(MARK) - 1);
        result.expanded[chunk] = {vertex: inner(v), fragment: inner(f)};
      } catch (e) {
        result.expanded[chunk] = {error: String((e && e.message) || e)};
      }
    }
    out.push(result);
  } catch (e) {
    out.push({id: m.id, error: String((e && e.message) || e)});
  }
}
process.stdout.write(JSON.stringify({version, chunks: Object.keys(THREE.ShaderChunk), materials: out}));
