// Writes the GLSL that deck.gl's layers hand to WebGL2: each layer's getShaders(), assembled
// by luma.gl as a Model does (the LayerManager's assembler, with deck.gl's default module and
// hooks), as NAME.vert + NAME.frag in the folder given, from the deck.gl and luma.gl that
// scripts/fetch-js-libs.sh installs beside this file:
//   node tests/js/deck-assemble.mjs OUT_DIR
import {mkdirSync, writeFileSync} from 'node:fs';
import {join} from 'node:path';
import {LayerManager} from '@deck.gl/core';
import * as layers from '@deck.gl/layers';

const out = process.argv[2];
mkdirSync(out, {recursive: true});
const device = {type: 'webgl', info: {shadingLanguage: 'glsl', shadingLanguageVersion: 300, gpu: 'unknown'},
  limits: {}, features: new Set()};
const {context} = new LayerManager(device, {});
const platformInfo = {type: 'webgl', shaderLanguage: 'glsl', shaderLanguageVersion: 300, gpu: 'unknown',
  limits: {}, features: new Set()};

// Each layer with shaders of its own, and the arguments its getShaders takes.
const cases = [
  ['arc', layers.ArcLayer], ['bitmap', layers.BitmapLayer], ['column', layers.ColumnLayer],
  ['grid-cell', layers.GridCellLayer], ['icon', layers.IconLayer], ['line', layers.LineLayer],
  ['path', layers.PathLayer], ['point-cloud', layers.PointCloudLayer],
  ['scatterplot', layers.ScatterplotLayer],
  ['solid-polygon-top', layers.SolidPolygonLayer, 'top'],
  ['solid-polygon-side', layers.SolidPolygonLayer, 'side'],
  ['multi-icon', layers._MultiIconLayer], ['text-background', layers._TextBackgroundLayer]
];
const written = [];
for (const [name, Layer, arg] of cases) {
  if (!Layer) {
    console.error(`no layer for ${name}`);
    continue;
  }
  const layer = new Layer({id: name, data: []});
  const shaders = Layer.prototype.getShaders.call({props: layer.props, context}, arg);
  const seen = new Set();
  const modules = shaders.modules.filter(m => (seen.has(m.name) ? false : (seen.add(m.name), true)));
  const {vs, fs} = context.shaderAssembler.assembleGLSLShaderPair({
    platformInfo, ...shaders, modules, defines: {...shaders.defines},
    pluginInjections: {}, pluginVertexInputs: {}, pluginVaryings: {}
  });
  writeFileSync(join(out, `${name}.vert`), vs);
  writeFileSync(join(out, `${name}.frag`), fs);
  written.push(name);
}
console.log(written.join(' '));
