// three.js r187 draws the project's scenes on essl-gl as Chromium drew them: at least 99.5 % of
// the pixels within 3/255 of Chromium's picture (three/reference/*.png) — or the scene's bar in
// three/bars.json, for scenes whose differences lie on edges and lines, where GL rasterisation
// rules leave implementations free — and at least 99.9 % of the pixels away from edges.
// Skips when three is not installed (npm ci in crates/essl-gl-node).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const threeDir = join(here, '../three');
let THREE = null;
try {
  THREE = await import('three');
} catch {
  THREE = null;
}
const bars = JSON.parse(readFileSync(join(threeDir, 'bars.json'), 'utf8'));

const skip = THREE || process.env.ESSL_REQUIRE_CORPORA === '1' ? false : 'three is not installed (npm ci in crates/essl-gl-node)';

test('three.js scenes match Chromium\'s pictures', { skip }, async (t) => {
  assert.ok(THREE, 'three is not installed (npm ci in crates/essl-gl-node)');
  const { SCENES, SIZE } = await import('../three/scenes/index.js');
  const { drawScene } = await import('../three/draw.js');
  const { decodePng, flipRows, compare } = await import('../three/png.mjs');
  const { createContext } = await import('../index.js');
  const [width, height] = SIZE;
  for (const name of SCENES) {
    await t.test(name, async () => {
      const ref = join(threeDir, 'reference', `${name}.png`);
      assert.ok(existsSync(ref), `${ref} is missing`);
      const gl = createContext(width, height, { antialias: false, preserveDrawingBuffer: true });
      const mod = await import(`../three/scenes/${name}.js`);
      const r = await drawScene(THREE, mod, gl, gl.canvas, width, height, 1);
      gl.destroy();
      assert.equal(r.error, 0, 'getError after the frames');
      const c = compare(flipRows(width, height, r.pixels), decodePng(readFileSync(ref)).data, 3, width);
      const bar = bars[name] ?? 0.995;
      assert.ok(c.within >= bar, `${(c.within * 100).toFixed(2)} % of pixels within 3/255 (bar ${(bar * 100).toFixed(1)} %)`);
      assert.ok(c.withinAwayFromEdges >= 0.999, `${(c.withinAwayFromEdges * 100).toFixed(2)} % of pixels away from edges within 3/255 (bar 99.9 %)`);
    });
  }
});
