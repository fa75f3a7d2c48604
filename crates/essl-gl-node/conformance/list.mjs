// The pages of the Khronos WebGL conformance suite a run covers, from the suite's own test
// lists (`00_test_list.txt`, with `--min-version` / `--max-version` as its harness reads
// them), and the folders left out because they need a browser's DOM sources.
import { readFileSync, existsSync } from 'node:fs';
import { join, dirname } from 'node:path';

/** Folders (under conformance/ and conformance2/) whose pages need what only a browser has. */
export const LEFT_OUT = [
  ['textures/image/', 'HTMLImageElement sources decoded by a browser'],
  ['textures/video/', 'HTMLVideoElement sources'],
  ['textures/svg_image/', 'SVG images rendered by a browser'],
  // essl-gl-node's installInWindow gives createImageBitmap; these folders (about 400 pages of
  // each source kind) are not yet in the runs, Chromium's included.
  ['textures/image_bitmap_from_', 'ImageBitmap from each kind of source (not yet run)'],
  ['textures/canvas', 'canvas 2D sources drawn by a browser'],
  ['textures/webgl_canvas/', 'a WebGL canvas composited by a browser as a source'],
  ['offscreencanvas/', 'OffscreenCanvas and workers'],
];

/**
 * Pages outside those folders that need the same: a `<video>` or SVG image as the texture
 * source, or workers.
 */
export const LEFT_OUT_PAGES = [
  [/^textures\/misc\/.*video/, 'HTMLVideoElement sources (as textures/video/)'],
  [/^textures\/misc\/.*svg-image/, 'SVG images rendered by a browser (as textures/svg_image/)'],
  [/workers?\.html$/, 'workers (as offscreencanvas/)'],
];

/** Why `page` is left out, or `null`. */
export function leftOut(page) {
  const rest = page.replace(/^conformance2?\//, '');
  for (const [prefix, why] of LEFT_OUT) {
    if (rest.startsWith(prefix)) return why;
  }
  for (const [pattern, why] of LEFT_OUT_PAGES) {
    if (pattern.test(rest)) return why;
  }
  return null;
}

function parseVersion(v) {
  return v.split('.').map((x) => parseInt(x, 10));
}

function atLeast(a, b) {
  const [x, y] = [parseVersion(a), parseVersion(b)];
  for (let i = 0; i < Math.max(x.length, y.length); i++) {
    const d = (x[i] ?? 0) - (y[i] ?? 0);
    if (d !== 0) return d > 0;
  }
  return true;
}

/**
 * The pages of list file `file` (relative to `root`) for suite `version` ("2.0.1" or "1.0.4"),
 * as webgl-test-harness.js's getFileList selects them.
 */
export function pages(root, file, version, inherited = { min: '1.0', max: null }) {
  const out = [];
  const dir = dirname(file);
  const text = readFileSync(join(root, file), 'utf8');
  for (const raw of text.split('\n')) {
    const line = raw.trim();
    if (line.length <= 4 || line.startsWith('#') || line.startsWith(';') || line.startsWith('//')) continue;
    const args = line.split(/\s+/);
    const opts = {};
    const names = [];
    for (let i = 0; i < args.length; i++) {
      if (args[i] === '--min-version') opts.min = args[++i];
      else if (args[i] === '--max-version') opts.max = args[++i];
      else if (args[i] === '--slow') opts.slow = true;
      else names.push(args[i]);
    }
    const name = join(dir, names.join(' '));
    const min = opts.min ?? inherited.min;
    const max = opts.max ?? inherited.max;
    if (!atLeast(version, min) || (max && !atLeast(max, version))) continue;
    if (name.endsWith('.txt')) {
      out.push(...pages(root, name, version, { min, max }));
    } else if (existsSync(join(root, name))) {
      out.push(name);
    }
  }
  return out;
}

/** The pages of a run: `{ webgl2: [...], webgl1: [...] }`, each page's folder-relative path. */
export function suite(root) {
  const webgl2 = [
    ...pages(root, 'conformance/00_test_list.txt', '2.0.1'),
    ...pages(root, 'conformance2/00_test_list.txt', '2.0.1'),
  ];
  const webgl1 = pages(root, 'conformance/00_test_list.txt', '1.0.4');
  return { webgl2, webgl1 };
}
