// Where a context lives: `createContext`, a small canvas-like object for programs without a
// DOM (`Canvas`: `width`, `height`, `getContext`, events), and `contextFor`, which gives any
// canvas-like object (jsdom's `HTMLCanvasElement` included) an essl-gl context.
import { native } from './native.js';
import { NATIVE, KEY } from './objects.js';
import {
  WebGLRenderingContext, WebGL2RenderingContext, attributes, loseContext, drawingBufferSource,
  STATE,
} from './context.js';
import { DRAWING_BUFFER, setDrawingBufferReader } from './sources.js';
import { contextClass, realmOf } from './realm.js';

const CONTEXTS = new WeakMap();

/**
 * The context of `type` (`'webgl2'`, `'webgl'`, `'experimental-webgl'`) for `canvas`,
 * made on first use at the canvas's size, as `canvas.getContext(type, attributes)` answers:
 * the same context again for the same type, `null` for another type once one exists, and
 * `null` for a type that is not WebGL.
 */
export function contextFor(canvas, type, attrs) {
  const t = `${type}`;
  const version = t === 'webgl2' ? 2 : t === 'webgl' || t === 'experimental-webgl' ? 1 : 0;
  const existing = CONTEXTS.get(canvas);
  if (existing) return version === existing.version ? existing.ctx : null;
  if (version === 0) return null;
  const a = attributes(attrs);
  const size = () => [Math.max(1, canvas.width | 0), Math.max(1, canvas.height | 0)];
  const make = () => {
    const [w, h] = size();
    return new native.NativeContext(w, h, nativeAttributes(a), version);
  };
  const cls = contextClass(realmOf(canvas), version);
  const ctx = new cls(KEY, canvas, make(), a, make);
  CONTEXTS.set(canvas, { ctx, version });
  return ctx;
}

setDrawingBufferReader((canvas) => {
  const c = CONTEXTS.get(canvas);
  return c ? drawingBufferSource(c.ctx) : null;
});

/** The essl-gl context of `canvas`, or `null`. */
export function contextOf(canvas) {
  return CONTEXTS.get(canvas)?.ctx ?? null;
}

/** Resizes the drawing buffer of `canvas`'s context (if any) to the canvas's size. */
export function resizeFor(canvas) {
  const c = CONTEXTS.get(canvas);
  const n = c?.ctx[NATIVE];
  if (n) n.resize(Math.max(1, canvas.width | 0), Math.max(1, canvas.height | 0));
}

function nativeAttributes(a) {
  return {
    alpha: a.alpha,
    depth: a.depth,
    stencil: a.stencil,
    antialias: a.antialias,
    premultipliedAlpha: a.premultipliedAlpha,
    preserveDrawingBuffer: a.preserveDrawingBuffer,
    failIfMajorPerformanceCaveat: a.failIfMajorPerformanceCaveat,
  };
}

/** A canvas for programs without a DOM: what WebGL code reads of an `HTMLCanvasElement`. */
export class Canvas extends EventTarget {
  #width;
  #height;
  constructor(width = 300, height = 150) {
    super();
    this.#width = dimension(width);
    this.#height = dimension(height);
    this.style = {};
  }
  get width() {
    return this.#width;
  }
  set width(v) {
    this.#width = dimension(v);
    resizeFor(this);
  }
  get height() {
    return this.#height;
  }
  set height(v) {
    this.#height = dimension(v);
    resizeFor(this);
  }
  get clientWidth() {
    return this.#width;
  }
  get clientHeight() {
    return this.#height;
  }
  getBoundingClientRect() {
    const [width, height] = [this.#width, this.#height];
    return { x: 0, y: 0, left: 0, top: 0, right: width, bottom: height, width, height };
  }
  getContext(type, attrs) {
    return contextFor(this, type, attrs);
  }
  /** The drawing buffer as a PNG file (a `Buffer`). */
  toBuffer() {
    const c = CONTEXTS.get(this);
    const n = c?.ctx[NATIVE];
    if (!n) throw new Error('essl-gl: the canvas has no live WebGL context');
    return n.toPng();
  }
  [DRAWING_BUFFER]() {
    const c = CONTEXTS.get(this);
    return c ? drawingBufferSource(c.ctx) : { width: 0, height: 0, data: new Uint8Array(0) };
  }
}

/** A canvas dimension as the `unsigned long` attribute converts it. */
function dimension(v) {
  const n = Number(v) >>> 0;
  return n;
}

/**
 * A WebGL context of `width` × `height` without a DOM: `version` 2 (a
 * `WebGL2RenderingContext`, the default) or 1. Its `canvas` is a `Canvas`.
 */
export function createContext(width, height, attrs, options) {
  const version = options?.version ?? 2;
  if (version !== 1 && version !== 2) throw new TypeError('essl-gl: version must be 1 or 2');
  const canvas = new Canvas(width, height);
  return canvas.getContext(version === 2 ? 'webgl2' : 'webgl', attrs);
}

/** Extra methods of essl-gl's contexts, beyond WebGL's IDL. */
const EXTRAS = {
  /** Frees the GPU device and memory now; the context is lost for good. */
  destroy() {
    loseContext(this, true);
  },
  /** Gives the drawing buffer (and the canvas) a new size. */
  resize(width, height) {
    const canvas = this.canvas;
    if (canvas instanceof Canvas) {
      canvas.width = width;
      canvas.height = height;
    } else {
      const n = this[NATIVE];
      if (n) n.resize(Math.max(1, width >>> 0), Math.max(1, height >>> 0));
    }
  },
  /** The drawing buffer as a PNG file (a `Buffer`); `null` when lost. */
  toPNG() {
    const n = this[NATIVE];
    return n === null ? null : n.toPng();
  },
  /** The drawing buffer as `{ width, height, data }`, RGBA8 top row first. */
  getImageData() {
    return drawingBufferSource(this);
  },
  /** Whether `destroy()` ran. */
  get destroyed() {
    return this[STATE] === 'destroyed';
  },
};

for (const cls of [WebGLRenderingContext, WebGL2RenderingContext]) {
  for (const [k, d] of Object.entries(Object.getOwnPropertyDescriptors(EXTRAS))) {
    Object.defineProperty(cls.prototype, k, { ...d, enumerable: false });
  }
}
