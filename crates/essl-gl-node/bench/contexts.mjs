#!/usr/bin/env node
// Context creation time and the memory of contexts created and destroyed in a loop, on
// essl-gl in Node and (creation) on Chromium in the same run.
//
//   node --expose-gc bench/contexts.mjs [--chromium] [--count 100]
// Prints JSON: first and median creation times (ms), RSS every 10 contexts (MiB).
import { createContext, Canvas } from '../index.js';

const argv = process.argv.slice(2);
const count = argv.includes('--count') ? Number(argv[argv.indexOf('--count') + 1]) : 100;

function draw(gl) {
  gl.clearColor(0.2, 0.4, 0.6, 1);
  gl.clear(gl.COLOR_BUFFER_BIT);
  const b = gl.createBuffer();
  gl.bindBuffer(gl.ARRAY_BUFFER, b);
  gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(3 * 1024), gl.STATIC_DRAW);
  const t = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, t);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA, 256, 256, 0, gl.RGBA, gl.UNSIGNED_BYTE, null);
  const px = new Uint8Array(4);
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
}

function median(v) {
  const s = [...v].sort((a, b) => a - b);
  return s[Math.floor(s.length / 2)];
}

async function node() {
  const times = [];
  const rss = [];
  const mib = () => Math.round((process.memoryUsage().rss / 2 ** 20) * 10) / 10;
  for (let i = 0; i < count; i++) {
    const t0 = performance.now();
    const gl = createContext(256, 256);
    times.push(performance.now() - t0);
    draw(gl);
    gl.destroy();
    if (i % 10 === 9) {
      globalThis.gc?.();
      await new Promise((r) => setTimeout(r, 0));
      rss.push(mib());
    }
  }
  void Canvas;
  return { first: times[0], medianAfterFirst: median(times.slice(1)), maxAfterFirst: Math.max(...times.slice(1)), rssEvery10: rss };
}

async function chromium() {
  const { launch } = await import('../conformance/chromium.mjs');
  const browser = await launch();
  const page = await browser.newPage();
  await page.goto('about:blank');
  const r = await page.evaluate((n) => {
    const times = [];
    for (let i = 0; i < n; i++) {
      const c = document.createElement('canvas');
      c.width = c.height = 256;
      const t0 = performance.now();
      const gl = c.getContext('webgl2');
      gl.getParameter(gl.VERSION);
      times.push(performance.now() - t0);
      gl.getExtension('WEBGL_lose_context').loseContext();
    }
    return times;
  }, Math.min(count, 20));
  await browser.close();
  return { first: r[0], medianAfterFirst: median(r.slice(1)) };
}

const out = { essl_gl: await node() };
if (argv.includes('--chromium')) out.chromium = await chromium();
console.log(JSON.stringify(out));
