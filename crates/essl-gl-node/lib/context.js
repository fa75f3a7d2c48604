// `WebGLRenderingContext` and `WebGL2RenderingContext`: the generated methods, the
// overloads, the attributes (`canvas`, `drawingBufferWidth`, …), extensions, and a lost
// context (`WEBGL_lose_context`, `destroy()`), over one native essl-gl context.
import {
  CONSTANTS_1, CONSTANTS_2, METHODS_1, METHODS_2, OPERATIONS_1, OPERATIONS_2,
} from './generated.js';
import { NATIVE, OBJECTS, VERSION, KEY, argc, str } from './objects.js';
import { OVERLOADS } from './overloads.js';
import { extensionObject, supportedExtensions } from './extensions.js';
import { DRAWING_BUFFER } from './sources.js';

/** The context's attributes as given (a normalized `WebGLContextAttributes`). */
export const ATTRIBUTES = Symbol('essl-gl attributes');
export const CANVAS = Symbol('essl-gl canvas');
/** 'live', 'lost' (restorable), 'destroyed'. */
export const STATE = Symbol('essl-gl state');
const LOST_ERRORS = Symbol('essl-gl errors of a lost context');
const EXTENSIONS = Symbol('essl-gl extensions enabled');
const RESTORE = Symbol('essl-gl restore allowed');
const MAKE = Symbol('essl-gl make native');
const SCHEDULED = Symbol('essl-gl frame end scheduled');

const CONTEXT_LOST_WEBGL = 0x9242;
const INVALID_OPERATION = 0x502;

/** Normalizes `WebGLContextAttributes` as WebIDL's dictionary conversion does. */
export function attributes(a) {
  if (a !== undefined && a !== null && typeof a !== 'object' && typeof a !== 'function') {
    throw new TypeError("Failed to execute 'getContext': the attributes are not an object.");
  }
  const get = (k, d) => (a == null || a[k] === undefined ? d : !!a[k]);
  const powerPreference = a?.powerPreference === undefined ? 'default' : str(a.powerPreference);
  if (!['default', 'low-power', 'high-performance'].includes(powerPreference)) {
    throw new TypeError(`The provided value '${powerPreference}' is not a valid enum value of type WebGLPowerPreference.`);
  }
  return {
    alpha: get('alpha', true),
    depth: get('depth', true),
    stencil: get('stencil', false),
    antialias: get('antialias', true),
    premultipliedAlpha: get('premultipliedAlpha', true),
    preserveDrawingBuffer: get('preserveDrawingBuffer', false),
    powerPreference,
    failIfMajorPerformanceCaveat: get('failIfMajorPerformanceCaveat', false),
    desynchronized: get('desynchronized', false),
    xrCompatible: get('xrCompatible', false),
  };
}

/** Methods and attributes both classes share. */
const COMMON = {
  getContextAttributes() {
    if (this[NATIVE] === null) return null;
    return { ...this[ATTRIBUTES] };
  },
  isContextLost() {
    return this[STATE] !== 'live';
  },
  getError() {
    const n = this[NATIVE];
    if (n === null) return this[LOST_ERRORS].shift() ?? 0;
    return n.getError();
  },
  getSupportedExtensions() {
    const n = this[NATIVE];
    if (n === null) return null;
    return supportedExtensions(n, this[VERSION]);
  },
  getExtension(name) {
    if (arguments.length < 1) throw argc('getExtension', 1, arguments.length);
    const s = str(name);
    const n = this[NATIVE];
    if (n === null) return null;
    const key = s.toLowerCase();
    const have = this[EXTENSIONS];
    if (have.has(key)) return have.get(key);
    const ext = extensionObject(this, n, s);
    if (ext !== null) have.set(key, ext);
    return ext;
  },
  makeXRCompatible() {
    return Promise.resolve();
  },
};

/** The attributes of the IDL's interface, as accessors. */
function defineAttributes(proto) {
  Object.defineProperties(proto, {
    canvas: {
      get() {
        return this[CANVAS];
      },
      enumerable: true,
      configurable: true,
    },
    drawingBufferWidth: {
      get() {
        const n = this[NATIVE];
        return n === null ? 0 : n.drawingBufferWidth;
      },
      enumerable: true,
      configurable: true,
    },
    drawingBufferHeight: {
      get() {
        const n = this[NATIVE];
        return n === null ? 0 : n.drawingBufferHeight;
      },
      enumerable: true,
      configurable: true,
    },
    drawingBufferFormat: {
      get() {
        return this._drawingBufferFormat ?? 0x8058;
      },
      enumerable: true,
      configurable: true,
    },
    drawingBufferColorSpace: {
      get() {
        return this._drawingBufferColorSpace ?? 'srgb';
      },
      set(v) {
        const s = str(v);
        if (s === 'srgb' || s === 'display-p3') this._drawingBufferColorSpace = s;
      },
      enumerable: true,
      configurable: true,
    },
    unpackColorSpace: {
      get() {
        return this._unpackColorSpace ?? 'srgb';
      },
      set(v) {
        const s = str(v);
        if (s === 'srgb' || s === 'display-p3') this._unpackColorSpace = s;
      },
      enumerable: true,
      configurable: true,
    },
  });
}

/** Copies methods onto a prototype as the IDL's operations are: enumerable, writable. */
function defineMethods(proto, methods, names) {
  for (const name of names) {
    const m = methods[name];
    if (m === undefined) continue;
    Object.defineProperty(proto, name, { value: m, writable: true, enumerable: true, configurable: true });
  }
}

/** Constants on the interface object and its prototype (read-only, enumerable). */
function defineConstants(cls, constants) {
  for (const [k, v] of Object.entries(constants)) {
    const d = { value: v, writable: false, enumerable: true, configurable: false };
    Object.defineProperty(cls, k, d);
    Object.defineProperty(cls.prototype, k, d);
  }
}

/** State every context instance carries. */
function init(ctx, key, canvas, native, attrs, version, make) {
  if (key !== KEY) throw new TypeError('Illegal constructor');
  Object.defineProperties(ctx, {
    [NATIVE]: { value: native, writable: true },
    [OBJECTS]: { value: new Map(), writable: true },
    [VERSION]: { value: version },
    [ATTRIBUTES]: { value: attrs },
    [CANVAS]: { value: canvas, writable: true },
    [STATE]: { value: 'live', writable: true },
    [LOST_ERRORS]: { value: [], writable: true },
    [EXTENSIONS]: { value: new Map(), writable: true },
    [RESTORE]: { value: false, writable: true },
    [MAKE]: { value: make },
    [SCHEDULED]: { value: false, writable: true },
    _drawingBufferFormat: { value: undefined, writable: true },
    _drawingBufferColorSpace: { value: undefined, writable: true },
    _unpackColorSpace: { value: undefined, writable: true },
  });
}

export class WebGLRenderingContext {
  constructor(key, canvas, native, attrs, make) {
    init(this, key, canvas, native, attrs, 1, make);
  }
}

export class WebGL2RenderingContext {
  constructor(key, canvas, native, attrs, make) {
    init(this, key, canvas, native, attrs, 2, make);
  }
}

const ALL = { ...METHODS_1, ...METHODS_2, ...OVERLOADS, ...COMMON };
defineMethods(WebGLRenderingContext.prototype, ALL, OPERATIONS_1);
defineMethods(WebGL2RenderingContext.prototype, ALL, OPERATIONS_2);
defineAttributes(WebGLRenderingContext.prototype);
defineAttributes(WebGL2RenderingContext.prototype);
defineConstants(WebGLRenderingContext, CONSTANTS_1);
defineConstants(WebGL2RenderingContext, { ...CONSTANTS_1, ...CONSTANTS_2 });
for (const cls of [WebGLRenderingContext, WebGL2RenderingContext]) {
  Object.defineProperty(cls.prototype, Symbol.toStringTag, { value: cls.name, configurable: true });
}

/**
 * The calls after which a browser has a frame to present when the task returns: draws and
 * clears (the drawing buffer changed), fences and queries (their results become available
 * once control is back in the event loop).
 */
export const FRAME_CALLS = [
  'clear', 'clearBufferfv', 'clearBufferiv', 'clearBufferuiv', 'clearBufferfi', 'drawArrays',
  'drawElements', 'drawArraysInstanced', 'drawElementsInstanced', 'drawRangeElements',
  'blitFramebuffer', 'fenceSync', 'endQuery',
];
for (const cls of [WebGLRenderingContext, WebGL2RenderingContext]) {
  for (const name of FRAME_CALLS) {
    const f = cls.prototype[name];
    if (typeof f !== 'function') continue;
    const wrapped = {
      [name](...args) {
        const r = f.apply(this, args);
        frameChanged(this);
        return r;
      },
    }[name];
    Object.defineProperty(cls.prototype, name, { value: wrapped, writable: true, enumerable: true, configurable: true });
  }
}

/** After a call of `FRAME_CALLS` (or an extension's draw): the frame ends with the task. */
export function frameChanged(ctx) {
  if (!ctx[SCHEDULED] && ctx[NATIVE] !== null) scheduleFrameEnd(ctx);
}

/**
 * Ends the frame once the current task returns, as a browser does before its next task:
 * queries and fences of the frame become available, and the drawing buffer of a canvas in
 * a document is cleared unless `preserveDrawingBuffer`.
 */
function scheduleFrameEnd(ctx) {
  ctx[SCHEDULED] = true;
  setImmediate(() => {
    ctx[SCHEDULED] = false;
    const n = ctx[NATIVE];
    // Only a canvas in a document is composited (and so cleared); jsdom's elements say
    // whether they are, essl-gl's own Canvas never is.
    if (n !== null) n.present(ctx[CANVAS]?.isConnected === true);
  });
}

/**
 * Loses the context (`WEBGL_lose_context.loseContext()`, or `destroy()` for good): calls do
 * nothing from now on, `getError` answers `CONTEXT_LOST_WEBGL` once, and the canvas gets a
 * `webglcontextlost` event in a later task; if its listener calls `preventDefault()`, the
 * context may be restored.
 */
export function loseContext(ctx, forGood) {
  if (ctx[STATE] === 'lost' && !forGood) {
    ctx[LOST_ERRORS].push(INVALID_OPERATION);
    return;
  }
  const n = ctx[NATIVE];
  if (n !== null) n.destroy();
  ctx[NATIVE] = null;
  const wasLive = ctx[STATE] === 'live';
  ctx[STATE] = forGood ? 'destroyed' : 'lost';
  ctx[OBJECTS] = new Map();
  ctx[EXTENSIONS] = new Map();
  if (!wasLive || forGood) return;
  ctx[LOST_ERRORS] = [CONTEXT_LOST_WEBGL];
  setTimeout(() => {
    const e = contextEvent(ctx[CANVAS], 'webglcontextlost');
    dispatch(ctx[CANVAS], e);
    ctx[RESTORE] = e === null ? false : e.defaultPrevented;
  }, 0);
}

/** `WEBGL_lose_context.restoreContext()`: a fresh native context, then `webglcontextrestored`. */
export function restoreContext(ctx) {
  if (ctx[STATE] !== 'lost' || !ctx[RESTORE]) {
    const n = ctx[NATIVE];
    if (n !== null) n.synthesizeError(INVALID_OPERATION, 'restoreContext', 'the context is not lost');
    else if (ctx[STATE] === 'lost') ctx[LOST_ERRORS].push(INVALID_OPERATION);
    return;
  }
  setTimeout(() => {
    if (ctx[STATE] !== 'lost' || !ctx[RESTORE]) return;
    ctx[NATIVE] = ctx[MAKE]();
    ctx[STATE] = 'live';
    ctx[LOST_ERRORS] = [];
    ctx[RESTORE] = false;
    dispatch(ctx[CANVAS], contextEvent(ctx[CANVAS], 'webglcontextrestored'));
  }, 0);
}

/** A `WebGLContextEvent` of the canvas's window (or Node's `Event`). */
function contextEvent(canvas, type) {
  const win = canvas?.ownerDocument?.defaultView;
  const Event = win?.Event ?? globalThis.Event;
  if (typeof Event !== 'function') return null;
  const e = new Event(type, { cancelable: true });
  Object.defineProperty(e, 'statusMessage', { value: '', enumerable: true });
  return e;
}

function dispatch(canvas, e) {
  if (e !== null && canvas && typeof canvas.dispatchEvent === 'function') canvas.dispatchEvent(e);
}

/** What `imageSource` reads of a canvas whose context is this one. */
export function drawingBufferSource(ctx) {
  const n = ctx[NATIVE];
  if (n === null) return { width: 0, height: 0, data: new Uint8Array(0) };
  return { width: n.drawingBufferWidth, height: n.drawingBufferHeight, data: n.drawingBufferPixels() };
}

export { DRAWING_BUFFER };
