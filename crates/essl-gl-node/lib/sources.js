// `TexImageSource`s a Node program can have: `ImageData`-shaped objects (`{ width, height,
// data }` with a Uint8ClampedArray or Uint8Array of RGBA bytes), canvases of the `canvas`
// and `@napi-rs/canvas` packages (and jsdom's, which use `canvas`), their images, and
// canvases whose context is essl-gl's. Each is read as 8-bit RGBA, unpremultiplied, top row
// first — what a browser hands WebGL.

import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { types } from 'node:util';
import { native } from './native.js';

/** How a DOM canvas with an essl-gl context gives its pixels (set by canvas.js). */
let drawingBufferOf = () => null;
export function setDrawingBufferReader(f) {
  drawingBufferOf = f;
}

/** The pixels of an ImageBitmap (`bitmap.js`; `null` once closed). */
export const BITMAP_PIXELS = Symbol('essl-gl ImageBitmap pixels');

/** A canvas-like object of essl-gl's (its context draws into the drawing buffer). */
export const DRAWING_BUFFER = Symbol('essl-gl drawing buffer pixels');

/** Whether `v` is something `imageSource` can read. */
export function isImageSource(v) {
  if (v === null || typeof v !== 'object') return false;
  if (ArrayBuffer.isView(v)) return false;
  if (BITMAP_PIXELS in v) return true;
  if (typeof v[DRAWING_BUFFER] === 'function') return true;
  if (isImageData(v)) return true;
  if (typeof v.videoWidth === 'number') return true;
  return typeof v.getContext === 'function' || isImage(v);
}

function isImageData(v) {
  return (
    typeof v.width === 'number' &&
    typeof v.height === 'number' &&
    (types.isUint8ClampedArray(v.data) || types.isUint8Array(v.data))
  );
}

function isImage(v) {
  return typeof v.naturalWidth === 'number' || v.constructor?.name === 'Image';
}

/**
 * The pixels of an image source: `{ width, height, data }` with `data` RGBA8, top row
 * first, unpremultiplied (`bitmap: true` for an ImageBitmap, uploaded as it is). A source that cannot be read (an image not loaded, a canvas whose
 * package is missing) is a `TypeError`-free empty 0 × 0 image, as a browser uploads one.
 */
export function imageSource(v, name) {
  if (BITMAP_PIXELS in v) {
    // WebGL uploads a bitmap as it is: no UNPACK_FLIP_Y_WEBGL, no UNPACK_PREMULTIPLY_ALPHA_WEBGL.
    const p = v[BITMAP_PIXELS] ?? { width: 0, height: 0, data: new Uint8Array(0) };
    return { ...p, bitmap: true };
  }
  if (typeof v[DRAWING_BUFFER] === 'function') return v[DRAWING_BUFFER]();
  const webgl = drawingBufferOf(v);
  if (webgl) return webgl;
  if (isImageData(v)) {
    const { width, height } = v;
    const need = width * height * 4;
    if (v.data.length < need) {
      throw new TypeError(`Failed to execute '${name}': the ImageData has fewer than width × height × 4 bytes.`);
    }
    return { width, height, data: v.data };
  }
  if (typeof v.getContext === 'function') {
    const width = v.width | 0;
    const height = v.height | 0;
    if (width === 0 || height === 0) return { width: 0, height: 0, data: new Uint8Array(0) };
    const c2d = v.getContext('2d');
    if (c2d && typeof c2d.getImageData === 'function') {
      const img = c2d.getImageData(0, 0, width, height);
      return { width: img.width, height: img.height, data: img.data };
    }
    return { width, height, data: new Uint8Array(width * height * 4) };
  }
  if (isImage(v)) {
    const png = decodedPng(v);
    if (png) return png;
    const width = v.naturalWidth ?? v.width ?? 0;
    const height = v.naturalHeight ?? v.height ?? 0;
    const canvas = drawnImage(v, width, height);
    if (canvas) return canvas;
    return { width, height, data: new Uint8Array(width * height * 4) };
  }
  return { width: 0, height: 0, data: new Uint8Array(0) };
}

const PNG_SIGNATURE = Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]);

/** Image element → { src, pixels } of its last decode (`decodedPng`). */
const decodedImages = new WeakMap();

/**
 * A PNG image's pixels decoded from its file (a `data:` or `file:` URL), as a browser decodes
 * it for an upload: colour not multiplied by alpha. Drawing it onto a 2D canvas (the `canvas`
 * package keeps premultiplied colour) loses the colour of nearly transparent pixels and
 * quantizes ramps. `null` for another source, another format or a file that does not decode.
 */
function decodedPng(img) {
  const src = typeof img.src === 'string' ? img.src : '';
  // An image element keeps its decoded pixels while its src stays, as a browser keeps a
  // decoded image: a page that uploads one image many times reads and decodes it once.
  const kept = decodedImages.get(img);
  if (kept?.src === src) return kept.pixels;
  const pixels = readPng(src);
  decodedImages.set(img, { src, pixels });
  return pixels;
}

/** The pixels a PNG `data:` or `file:` URL holds; `null` for anything else. */
function readPng(src) {
  let bytes = null;
  try {
    if (src.startsWith('data:')) {
      const comma = src.indexOf(',');
      const meta = src.slice(5, comma);
      const body = src.slice(comma + 1);
      bytes = meta.endsWith(';base64') ? Buffer.from(body, 'base64') : Buffer.from(decodeURIComponent(body), 'latin1');
    } else if (src.startsWith('file:')) {
      bytes = readFileSync(fileURLToPath(src));
    }
  } catch {
    return null;
  }
  if (!bytes || bytes.length < 8 || !bytes.subarray(0, 8).equals(PNG_SIGNATURE)) return null;
  try {
    const { width, height, data } = native.decodePng(bytes);
    return { width, height, data: new Uint8Array(data.buffer, data.byteOffset, data.length) };
  } catch {
    return null;
  }
}

/** An image drawn onto a canvas of the package that made it, read back. */
function drawnImage(img, width, height) {
  const doc = img.ownerDocument;
  const canvas = doc?.createElement?.('canvas');
  if (!canvas || width === 0 || height === 0) return null;
  canvas.width = width;
  canvas.height = height;
  const c2d = canvas.getContext('2d');
  if (!c2d) return null;
  c2d.drawImage(img, 0, 0);
  const d = c2d.getImageData(0, 0, width, height);
  return { width, height, data: d.data };
}
