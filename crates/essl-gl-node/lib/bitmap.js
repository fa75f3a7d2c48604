// What a DOM library lacks of a browser's image decoding, for the sources WebGL takes:
// `createImageBitmap` and `ImageBitmap` (jsdom has neither), and `HTMLImageElement.decode()`.
// A bitmap holds its pixels as `imageSource` reads them (8-bit RGBA, top row first;
// unpremultiplied unless made with `premultiplyAlpha: 'premultiply'`); WebGL uploads it as it
// is, without `UNPACK_FLIP_Y_WEBGL` or `UNPACK_PREMULTIPLY_ALPHA_WEBGL`, as the WebGL
// specification says of ImageBitmaps. Images are decoded by the DOM library's own image
// element (jsdom's uses the `canvas` package, which applies a JPEG's EXIF orientation as
// browsers do).
import { types } from 'node:util';
import { BITMAP_PIXELS, imageSource, isImageSource } from './sources.js';

/** `ImageBitmap`: made only by `createImageBitmap`. */
export class ImageBitmap {
  constructor(key, pixels) {
    if (key !== BITMAP_PIXELS) throw new TypeError('Illegal constructor');
    this[BITMAP_PIXELS] = pixels;
  }

  /** Width in pixels (0 once closed). */
  get width() {
    return this[BITMAP_PIXELS]?.width ?? 0;
  }

  /** Height in pixels (0 once closed). */
  get height() {
    return this[BITMAP_PIXELS]?.height ?? 0;
  }

  /** Frees the pixels. */
  close() {
    this[BITMAP_PIXELS] = null;
  }
}

function isBlob(v) {
  return v !== null && typeof v === 'object' && typeof v.arrayBuffer === 'function' && typeof v.type === 'string';
}

/** An image element of `window` holding the encoded image `bytes`, once decoded. */
async function decodeBytes(window, bytes, type) {
  const img = new window.Image();
  const url = `data:${type || 'application/octet-stream'};base64,${Buffer.from(bytes).toString('base64')}`;
  img.src = url;
  await decode.call(img, window);
  return img;
}

/** Whether the `canvas` package loads: jsdom decodes images with it, and without it an image
 * element fires neither `load` nor `error`, so a `decode()` would wait forever. */
let canvasPackage = null;
function canvasLoads() {
  canvasPackage ??= import('canvas').then(
    () => true,
    () => false,
  );
  return canvasPackage;
}

/** `HTMLImageElement.decode()`: resolves once the image is loaded, rejects if it cannot be. */
async function decode(window) {
  if (/\bjsdom\b/.test(window.navigator?.userAgent ?? '') && !(await canvasLoads())) {
    throw new window.DOMException(
      'The source image cannot be decoded: jsdom decodes images with the `canvas` package, which is not installed or did not build.',
      'EncodingError',
    );
  }
  return new Promise((resolve, reject) => {
    const fail = () => reject(new window.DOMException('The source image cannot be decoded.', 'EncodingError'));
    if (this.complete && this.getAttribute('src') !== null) {
      if (this.naturalWidth > 0) resolve();
      else fail();
      return;
    }
    this.addEventListener('load', () => resolve(), { once: true });
    this.addEventListener('error', fail, { once: true });
  });
}

/** The `[sx, sy, sw, sh]` rectangle of `src`, clipped; pixels outside are transparent. */
function crop(src, [sx, sy, sw, sh]) {
  // A negative size takes the rectangle on the other side of the corner.
  if (sw < 0) [sx, sw] = [sx + sw, -sw];
  if (sh < 0) [sy, sh] = [sy + sh, -sh];
  const out = new Uint8Array(sw * sh * 4);
  for (let y = 0; y < sh; y++) {
    const from = sy + y;
    if (from < 0 || from >= src.height) continue;
    for (let x = 0; x < sw; x++) {
      const fx = sx + x;
      if (fx < 0 || fx >= src.width) continue;
      const i = (from * src.width + fx) * 4;
      out.set(src.data.subarray(i, i + 4), (y * sw + x) * 4);
    }
  }
  return { width: sw, height: sh, data: out };
}

function flipRows({ width, height, data }) {
  const out = new Uint8Array(width * height * 4);
  const row = width * 4;
  for (let y = 0; y < height; y++) out.set(data.subarray(y * row, (y + 1) * row), (height - 1 - y) * row);
  return { width, height, data: out };
}

function premultiply({ width, height, data }) {
  const out = Uint8Array.from(data);
  for (let i = 0; i < out.length; i += 4) {
    const a = out[i + 3];
    for (let c = 0; c < 3; c++) out[i + c] = Math.round((out[i + c] * a) / 255);
  }
  return { width, height, data: out };
}

/**
 * `createImageBitmap(source[, sx, sy, sw, sh][, options])` for `window`: sources are images,
 * blobs of encoded images, `ImageData`, canvases (WebGL ones included) and ImageBitmaps;
 * options `imageOrientation` (`'flipY'`) and `premultiplyAlpha` (`'premultiply'`).
 */
export function imageBitmapFactory(window) {
  return async function createImageBitmap(source, ...rest) {
    const name = 'createImageBitmap';
    let rect = null;
    let options = {};
    if (rest.length >= 4) {
      rect = rest.slice(0, 4).map((v) => Math.trunc(Number(v)));
      options = rest[4] ?? {};
      if (rect[2] === 0 || rect[3] === 0) {
        throw new RangeError(`Failed to execute '${name}': the source ${rect[2] === 0 ? 'width' : 'height'} is 0.`);
      }
    } else if (rest.length > 0) {
      options = rest[0] ?? {};
    }
    let pixels;
    if (source instanceof ImageBitmap) {
      pixels = source[BITMAP_PIXELS];
      if (pixels === null) {
        throw new window.DOMException(`Failed to execute '${name}': the ImageBitmap is closed.`, 'InvalidStateError');
      }
    } else if (isBlob(source)) {
      const img = await decodeBytes(window, await source.arrayBuffer(), source.type);
      pixels = imageSource(img, name);
    } else if (isImageSource(source) && !types.isArrayBufferView(source)) {
      if (source instanceof window.HTMLImageElement && !(source.complete && source.naturalWidth > 0)) {
        throw new window.DOMException(`Failed to execute '${name}': the image is not decoded.`, 'InvalidStateError');
      }
      pixels = imageSource(source, name);
    } else {
      throw new TypeError(
        `Failed to execute '${name}': The provided value is not of type '(Blob or HTMLCanvasElement or HTMLImageElement or ImageBitmap or ImageData or OffscreenCanvas)'.`,
      );
    }
    const taken = pixels.data;
    if (rect) pixels = crop(pixels, rect);
    if (options.imageOrientation === 'flipY') pixels = flipRows(pixels);
    if (options.premultiplyAlpha === 'premultiply') pixels = premultiply(pixels);
    // The bitmap owns its pixels: each step above made new ones; without any, copy them.
    const data = pixels.data === taken ? Uint8Array.from(taken) : pixels.data;
    return new ImageBitmap(BITMAP_PIXELS, { width: pixels.width, height: pixels.height, data });
  };
}

/** Gives `window` what this module offers where it lacks it. */
export function installImageDecoding(window) {
  const img = window.HTMLImageElement?.prototype;
  if (img && typeof img.decode !== 'function') {
    Object.defineProperty(img, 'decode', {
      value() {
        return decode.call(this, window);
      },
      writable: true,
      configurable: true,
    });
  }
  if (typeof window.createImageBitmap !== 'function') {
    Object.defineProperty(window, 'createImageBitmap', {
      value: imageBitmapFactory(window),
      writable: true,
      configurable: true,
    });
  }
  if (typeof window.ImageBitmap !== 'function') {
    Object.defineProperty(window, 'ImageBitmap', { value: ImageBitmap, writable: true, configurable: true });
  }
  if (typeof window.ImageData !== 'function') {
    Object.defineProperty(window, 'ImageData', { value: ImageData, writable: true, configurable: true });
  }
}

/**
 * `ImageData` for a window that has none (jsdom without a 2D canvas library): RGBA pixels in
 * a `Uint8ClampedArray`, from `new ImageData(width, height)` or `new ImageData(data, width[,
 * height])`, with the DOM's checks (a `RangeError` where it throws an `IndexSizeError`).
 */
export class ImageData {
  constructor(a, b, c) {
    let data;
    let width;
    let height;
    if (types.isUint8ClampedArray(a)) {
      width = b >>> 0;
      if (width === 0) throw new RangeError("Failed to construct 'ImageData': The source width is zero or not a number.");
      if (a.length === 0 || a.length % (4 * width) !== 0) {
        throw new RangeError("Failed to construct 'ImageData': The input data length is not a multiple of (4 * width).");
      }
      height = c === undefined ? a.length / (4 * width) : c >>> 0;
      if (a.length !== 4 * width * height) {
        throw new RangeError("Failed to construct 'ImageData': The input data length is not equal to (4 * width * height).");
      }
      data = a;
    } else if (typeof a === 'number' && b !== undefined) {
      width = a >>> 0;
      height = b >>> 0;
      if (width === 0 || height === 0) {
        throw new RangeError("Failed to construct 'ImageData': The source width or height is zero.");
      }
      data = new Uint8ClampedArray(width * height * 4);
    } else {
      throw new TypeError("Failed to construct 'ImageData': parameter 1 is not of type 'Uint8ClampedArray' or a number of pixels.");
    }
    Object.defineProperties(this, {
      data: { value: data, enumerable: true },
      width: { value: width, enumerable: true },
      height: { value: height, enumerable: true },
      colorSpace: { value: 'srgb', enumerable: true },
    });
  }
}
