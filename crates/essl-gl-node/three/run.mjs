#!/usr/bin/env node
// Draws the scenes with three.js in Node on essl-gl and/or in headless Chromium, in one run:
// writes Chromium's pictures (--write-reference), compares essl-gl's with the committed
// ones, and reports per-frame medians of both (30 frames, each with a 1-pixel readPixels).
//
//   node three/run.mjs [--node] [--chromium] [--write-reference] [--only NAME] [--json FILE]
import { readFileSync, writeFileSync, existsSync, mkdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { SCENES, SIZE } from './scenes/index.js';
import { encodePng, decodePng, flipRows, compare } from './png.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const argv = process.argv.slice(2);
const has = (f) => argv.includes(f);
const value = (f) => (argv.includes(f) ? argv[argv.indexOf(f) + 1] : undefined);
const only = value('--only');
const scenes = SCENES.filter((s) => !only || s === only);
const [width, height] = SIZE;
const referenceDir = join(here, 'reference');

async function nodeRuns() {
  const THREE = await import('three');
  const { createContext } = await import('../index.js');
  const { drawScene } = await import('./draw.js');
  const out = {};
  for (const name of scenes) {
    const gl = createContext(width, height, { antialias: false, preserveDrawingBuffer: true });
    const mod = await import(`./scenes/${name}.js`);
    const r = await drawScene(THREE, mod, gl, gl.canvas, width, height);
    out[name] = { pixels: flipRows(width, height, r.pixels), median: r.median, error: r.error };
    gl.destroy();
  }
  return out;
}

async function chromiumRuns() {
  const { serve, launch } = await import('../conformance/chromium.mjs');
  const server = await serve(join(here, '..'));
  const browser = await launch();
  const out = {};
  try {
    for (const name of scenes) {
      const page = await browser.newPage({ viewport: { width: 400, height: 300 } });
      await page.goto(`${server.url}/three/page.html?scene=${name}`);
      await page.waitForFunction(() => window.result, null, { timeout: 300000 });
      const r = await page.evaluate(() => window.result);
      await page.close();
      if (r.failure) throw new Error(`${name} in Chromium: ${r.failure}`);
      const pixels = new Uint8Array(Buffer.from(r.pixels, 'base64'));
      out[name] = { pixels: flipRows(width, height, pixels), median: r.median, error: r.error, renderer: r.renderer };
    }
  } finally {
    await browser.close();
    server.close();
  }
  return out;
}

async function main() {
  const node = has('--node') || !has('--chromium') ? await nodeRuns() : null;
  const chromium = has('--chromium') ? await chromiumRuns() : null;
  if (chromium && has('--write-reference')) {
    mkdirSync(referenceDir, { recursive: true });
    for (const [name, r] of Object.entries(chromium)) {
      writeFileSync(join(referenceDir, `${name}.png`), encodePng(width, height, r.pixels));
    }
  }
  const rows = [];
  for (const name of scenes) {
    const row = { scene: name };
    const ref = join(referenceDir, `${name}.png`);
    if (node) {
      row.esslGlMs = node[name].median;
      row.esslGlError = node[name].error;
      if (existsSync(ref)) {
        const c = compare(node[name].pixels, decodePng(readFileSync(ref)).data, 3, width);
        row.within = c.within;
        row.withinAwayFromEdges = c.withinAwayFromEdges;
        row.worst = c.worst;
      }
      if (has('--save')) writeFileSync(join(value('--save'), `${name}.png`), encodePng(width, height, node[name].pixels));
    }
    if (chromium) {
      row.chromiumMs = chromium[name].median;
      row.chromiumError = chromium[name].error;
      row.chromiumRenderer = chromium[name].renderer;
    }
    rows.push(row);
    console.log(JSON.stringify(row));
  }
  if (value('--json')) writeFileSync(value('--json'), JSON.stringify(rows, null, 2));
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
