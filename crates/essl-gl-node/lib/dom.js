// A DOM library's canvases with essl-gl's contexts: `installInWindow(window)` makes a
// jsdom window's `<canvas>` answer `getContext('webgl2' | 'webgl' | 'experimental-webgl')`
// with an essl-gl context (its size follows the element's width and height), and defines
// WebGL's interfaces on the window (`WebGL2RenderingContext`, `WebGLBuffer`, …) so that
// `instanceof` works in the page's scripts. '2d' and other types keep the library's answer.
// Where the window lacks them, it gets `createImageBitmap`, `ImageBitmap` and
// `HTMLImageElement.decode()` (`bitmap.js`).
import * as objects from './objects.js';
import { installImageDecoding } from './bitmap.js';
import { contextFor, contextOf, resizeFor } from './canvas.js';
import { NATIVE } from './objects.js';
import { contextClass } from './realm.js';

const WEBGL = new Set(['webgl', 'webgl2', 'experimental-webgl']);

/** Marks a 2D context whose `drawImage` reads WebGL canvases. */
const PATCHED = Symbol('essl-gl drawImage');

/** Installs essl-gl into a jsdom `window` (call it before the page's scripts run). */
export function installInWindow(window) {
  const proto = window.HTMLCanvasElement.prototype;
  const getContext = proto.getContext;
  proto.getContext = function (type, attrs) {
    if (WEBGL.has(`${type}`)) return contextFor(this, type, attrs);
    const c = getContext.call(this, type, attrs);
    if (`${type}` === '2d') drawsWebGL(window, c);
    return c;
  };
  for (const dim of ['width', 'height']) {
    const d = Object.getOwnPropertyDescriptor(proto, dim);
    Object.defineProperty(proto, dim, {
      ...d,
      set(v) {
        d.set.call(this, v);
        resizeFor(this);
      },
    });
  }
  patchReadback(window, proto);
  installImageDecoding(window);
  const globals = {
    WebGLRenderingContext: contextClass(window, 1),
    WebGL2RenderingContext: contextClass(window, 2),
  };
  for (const name of [
    'WebGLObject', 'WebGLBuffer', 'WebGLFramebuffer', 'WebGLProgram', 'WebGLRenderbuffer',
    'WebGLShader', 'WebGLTexture', 'WebGLQuery', 'WebGLSampler', 'WebGLSync',
    'WebGLTransformFeedback', 'WebGLVertexArrayObject', 'WebGLUniformLocation',
    'WebGLActiveInfo', 'WebGLShaderPrecisionFormat',
  ]) {
    globals[name] = objects[name];
  }
  for (const [k, v] of Object.entries(globals)) {
    Object.defineProperty(window, k, { value: v, writable: true, configurable: true });
  }
}

/**
 * What a page reads of a WebGL canvas: `toDataURL` and `toBlob` give the drawing buffer (a
 * PNG); a 2D context's `drawImage` draws it (`drawsWebGL`) when the DOM library has a 2D
 * canvas (jsdom with the `canvas` package).
 */
function patchReadback(window, proto) {
  const toDataURL = proto.toDataURL;
  proto.toDataURL = function (...args) {
    const ctx = contextOf(this);
    if (!ctx) return toDataURL.apply(this, args);
    const n = ctx[NATIVE];
    if (n === null || this.width === 0 || this.height === 0) return 'data:,';
    return `data:image/png;base64,${n.toPng().toString('base64')}`;
  };
  const toBlob = proto.toBlob;
  proto.toBlob = function (callback, ...args) {
    const ctx = contextOf(this);
    if (!ctx) return toBlob.call(this, callback, ...args);
    const n = ctx[NATIVE];
    const blob = n === null ? null : new window.Blob([n.toPng()], { type: 'image/png' });
    setTimeout(() => callback(blob), 0);
  };
}

/**
 * Makes the 2D context `c` draw WebGL canvases (`drawImage`) through a 2D canvas holding their
 * pixels. jsdom's 2D contexts are the `canvas` package's, each with its own `drawImage` that
 * unwraps jsdom's elements, so each context is wrapped as its canvas hands it out.
 */
function drawsWebGL(window, c) {
  if (!c || typeof c.drawImage !== 'function' || c[PATCHED]) return;
  c[PATCHED] = true;
  const drawImage = c.drawImage;
  c.drawImage = function (image, ...args) {
    const ctx = image && contextOf(image);
    if (!ctx) return drawImage.call(this, image, ...args);
    const n = ctx[NATIVE];
    const w = n === null ? 0 : n.drawingBufferWidth;
    const h = n === null ? 0 : n.drawingBufferHeight;
    const copy = window.document.createElement('canvas');
    copy.width = w;
    copy.height = h;
    const pixels = copy.getContext('2d');
    if (pixels && w > 0 && h > 0) {
      const data = pixels.createImageData(w, h);
      data.data.set(n.drawingBufferPixels());
      pixels.putImageData(data, 0, 0);
    }
    return drawImage.call(this, copy, ...args);
  };
}
