// The GLSL three.js's own WebGLProgram hands to WebGL2 for a material: built in a WebGL2
// context with a recording stand-in for the GL calls (a mesh, no lights, no tone mapping, sRGB
// output). Shared by three-assemble.mjs (the shader objects of examples/jsm/shaders) and
// three-materials.mjs (the materials the classes of examples/jsm make).
import * as S from 'three';
import {WebGLPrograms} from 'three/src/renderers/webgl/WebGLPrograms.js';

/** [vertex, fragment]: the texts WebGL2 receives for `material`. */
export function build(material) {
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
  const object = new S.Mesh(new S.BoxGeometry(), material);
  const params = programs.getParameters(material, lights, [], {isScene: true, fog: null,
    environment: null}, object, []);
  params.uniforms = programs.getUniforms(material);
  programs.acquireProgram(params, programs.getProgramCacheKey(params));
  return sources;
}
