// The `gl` package (headless-gl) as the peer of the conformance run: its contexts answer a
// jsdom canvas's getContext, so the suite's pages run on it as they run on essl-gl.
//
// `gl` is not a dependency of essl-gl: its install compiles ANGLE with node-gyp and needs X11
// development headers, and its contexts need an X display (run the pages under `xvfb-run`).
// $ESSL_HEADLESS_GL names the installed package's folder (…/node_modules/gl);
// scripts/gl-node-conformance.sh sets it when test-data/webgl/runs/gl holds an install.
//
// gl 8.1.6, the version npm has, makes WebGL 1 contexts only: its `createWebGL2Context`
// option is ignored, so a page asking for `webgl2` gets null, as a browser without WebGL 2
// answers.
import { createRequire } from 'node:module';
import { join } from 'node:path';

const dir = process.env.ESSL_HEADLESS_GL;
if (!dir) throw new Error('ESSL_HEADLESS_GL must name the folder of an installed `gl` package');
const require = createRequire(join(dir, 'package.json'));
const createGL = require(dir);
const { WebGLRenderingContext } = require(join(dir, 'src/javascript/webgl-rendering-context.js'));

const CLASSES = {
  WebGLBuffer: 'webgl-buffer',
  WebGLFramebuffer: 'webgl-framebuffer',
  WebGLProgram: 'webgl-program',
  WebGLRenderbuffer: 'webgl-renderbuffer',
  WebGLShader: 'webgl-shader',
  WebGLTexture: 'webgl-texture',
  WebGLUniformLocation: 'webgl-uniform-location',
  WebGLActiveInfo: 'webgl-active-info',
  WebGLShaderPrecisionFormat: 'webgl-shader-precision-format',
};

const WEBGL1 = new Set(['webgl', 'experimental-webgl']);
const CONTEXT = Symbol('headless-gl context');

/** Makes `window`'s canvases answer getContext('webgl') with a headless-gl context. */
export function installHeadlessGl(window) {
  const proto = window.HTMLCanvasElement.prototype;
  const getContext = proto.getContext;
  proto.getContext = function (type, attrs) {
    const t = `${type}`;
    if (t === 'webgl2') return null;
    if (!WEBGL1.has(t)) return this[CONTEXT] ? null : getContext.call(this, type, attrs);
    if (this[CONTEXT] === undefined) {
      const gl = createGL(Math.max(this.width, 1), Math.max(this.height, 1), attrs ?? {});
      if (gl) Object.defineProperty(gl, 'canvas', { value: this, configurable: true });
      this[CONTEXT] = gl;
    }
    return this[CONTEXT];
  };
  for (const dim of ['width', 'height']) {
    const d = Object.getOwnPropertyDescriptor(proto, dim);
    Object.defineProperty(proto, dim, {
      ...d,
      set(v) {
        d.set.call(this, v);
        const gl = this[CONTEXT];
        const resize = gl && gl.getExtension('STACKGL_resize_drawingbuffer');
        if (resize) resize.resize(Math.max(this.width, 1), Math.max(this.height, 1));
      },
    });
  }
  const globals = { WebGLRenderingContext };
  for (const [name, file] of Object.entries(CLASSES)) {
    globals[name] = require(join(dir, 'src/javascript', `${file}.js`))[name];
  }
  for (const [k, v] of Object.entries(globals)) {
    Object.defineProperty(window, k, { value: v, writable: true, configurable: true });
  }
}
