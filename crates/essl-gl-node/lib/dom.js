// A DOM library's canvases with essl-gl's contexts: `installInWindow(window)` makes a
// jsdom window's `<canvas>` answer `getContext('webgl2' | 'webgl' | 'experimental-webgl')`
// with an essl-gl context (its size follows the element's width and height), and defines
// WebGL's interfaces on the window (`WebGL2RenderingContext`, `WebGLBuffer`, …) so that
// `instanceof` works in the page's scripts. '2d' and other types keep the library's answer.
import * as objects from './objects.js';
import { contextFor, resizeFor } from './canvas.js';
import { contextClass } from './realm.js';

const WEBGL = new Set(['webgl', 'webgl2', 'experimental-webgl']);

/** Installs essl-gl into a jsdom `window` (call it before the page's scripts run). */
export function installInWindow(window) {
  const proto = window.HTMLCanvasElement.prototype;
  const getContext = proto.getContext;
  proto.getContext = function (type, attrs) {
    if (WEBGL.has(`${type}`)) return contextFor(this, type, attrs);
    return getContext.call(this, type, attrs);
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
