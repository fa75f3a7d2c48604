// WebGL's object classes and WebIDL's conversions of arguments, shared by every method.
//
// A WebGL object (`WebGLBuffer`, …) is a JavaScript object holding the id the native side
// gave it; the context keeps one object per id, so an answer that names an object
// (`getParameter(ARRAY_BUFFER_BINDING)`) is the very object the program bound. Conversions
// follow WebIDL: numbers by ToNumber and the integer type's modulo, `null` for nullable
// objects, a `TypeError` for a value of the wrong kind or too few arguments.

import { types } from 'node:util';

/** The native context of a WebGL context object (`null` while lost or destroyed). */
export const NATIVE = Symbol('essl-gl native context');
/** A WebGL object's id, and the context that made it. */
export const ID = Symbol('essl-gl object id');
export const OWNER = Symbol('essl-gl object context');
/** The objects of a context by id (a `Map`). */
export const OBJECTS = Symbol('essl-gl objects');
/** A context's WebGL version: 1 or 2. */
export const VERSION = Symbol('essl-gl version');
/** Lets the package's own code construct what JavaScript may not (`new WebGLBuffer()`). */
export const KEY = Symbol('essl-gl constructor key');

/** `WebGLObject`: the base of the objects a context makes; its `label` is the program's. */
export class WebGLObject {
  constructor(key, owner, id) {
    if (key !== KEY) throw new TypeError('Illegal constructor');
    Object.defineProperty(this, OWNER, { value: owner });
    Object.defineProperty(this, ID, { value: id });
    this.label = '';
  }
}

export class WebGLBuffer extends WebGLObject {}
export class WebGLFramebuffer extends WebGLObject {}
export class WebGLProgram extends WebGLObject {}
export class WebGLRenderbuffer extends WebGLObject {}
export class WebGLShader extends WebGLObject {}
export class WebGLTexture extends WebGLObject {}
export class WebGLQuery extends WebGLObject {}
export class WebGLSampler extends WebGLObject {}
export class WebGLSync extends WebGLObject {}
export class WebGLTransformFeedback extends WebGLObject {}
export class WebGLVertexArrayObject extends WebGLObject {}

/** `WebGLUniformLocation`: not a `WebGLObject` in the IDL. */
export class WebGLUniformLocation {
  constructor(key, owner, id) {
    if (key !== KEY) throw new TypeError('Illegal constructor');
    Object.defineProperty(this, OWNER, { value: owner });
    Object.defineProperty(this, ID, { value: id });
  }
}

/** `WebGLActiveInfo`: a uniform's or attribute's name, size and type. */
export class WebGLActiveInfo {
  #name;
  #size;
  #type;
  constructor(key, info) {
    if (key !== KEY) throw new TypeError('Illegal constructor');
    this.#name = info.name;
    this.#size = info.size;
    this.#type = info.type;
  }
  get name() {
    return this.#name;
  }
  get size() {
    return this.#size;
  }
  get type() {
    return this.#type;
  }
}

/** `WebGLShaderPrecisionFormat`. */
export class WebGLShaderPrecisionFormat {
  #rangeMin;
  #rangeMax;
  #precision;
  constructor(key, p) {
    if (key !== KEY) throw new TypeError('Illegal constructor');
    this.#rangeMin = p.rangeMin;
    this.#rangeMax = p.rangeMax;
    this.#precision = p.precision;
  }
  get rangeMin() {
    return this.#rangeMin;
  }
  get rangeMax() {
    return this.#rangeMax;
  }
  get precision() {
    return this.#precision;
  }
}

/** The `TypeError` for a call given fewer arguments than it requires. */
export function argc(name, required, given) {
  return new TypeError(
    `Failed to execute '${name}': ${required} argument${required === 1 ? '' : 's'} required, but only ${given} present.`,
  );
}

/** ToNumber as WebIDL's numeric conversions start (a Symbol or BigInt is a `TypeError`). */
export function num(v) {
  if (typeof v === 'number') return v;
  if (typeof v === 'bigint' || typeof v === 'symbol') {
    throw new TypeError(`Cannot convert a ${typeof v} to a number`);
  }
  return Number(v);
}

/** `unsigned long` (`GLenum`, `GLuint`, `GLbitfield`). */
export function u32(v) {
  return num(v) >>> 0;
}

/** `long` (`GLint`, `GLsizei`). */
export function i32(v) {
  return num(v) | 0;
}

const TWO_64 = 2 ** 64;
const TWO_63 = 2 ** 63;

/** `long long` (`GLintptr`, `GLsizeiptr`, `GLint64`): truncated, modulo 2^64. */
export function i64(v) {
  let x = num(v);
  if (!Number.isFinite(x)) return 0;
  x = Math.trunc(x);
  if (x >= -TWO_63 && x < TWO_63) return x === 0 ? 0 : x;
  x = ((x % TWO_64) + TWO_64) % TWO_64;
  return x >= TWO_63 ? x - TWO_64 : x;
}

/** `unsigned long long` (`srcOffset`, `GLuint64`): truncated, modulo 2^64. */
export function u64(v) {
  let x = num(v);
  if (!Number.isFinite(x)) return 0;
  x = Math.trunc(x);
  if (x >= 0 && x < TWO_64) return x;
  const m = x % TWO_64;
  if (m >= 0) return m;
  // Negative: 2^64 + m, which rounds to 2^64 when m is small; the largest double below
  // 2^64 stands for it (-1 is 2^64 - 1 to WebIDL: an offset past any array).
  return Math.min(TWO_64 + m, TWO_64 - 2048);
}

/** An `unsigned long long` element offset as the native side takes it (past 2^32 - 1: that). */
export function offset32(v) {
  const x = u64(v);
  return x > 0xffffffff ? 0xffffffff : x;
}

/** `unrestricted float` (`GLfloat`, `GLclampf`). */
export function f32(v) {
  return num(v);
}

/** `boolean`. */
export function bool(v) {
  return !!v;
}

/** `DOMString` (a Symbol is a `TypeError`). */
export function str(v) {
  if (typeof v === 'string') return v;
  if (typeof v === 'symbol') throw new TypeError('Cannot convert a Symbol to a string');
  return `${v}`;
}

function iterable(v, name, i) {
  if (v === null || typeof v !== 'object' || typeof v[Symbol.iterator] !== 'function') {
    throw new TypeError(`Failed to execute '${name}': parameter ${i} is not an iterable object.`);
  }
  return v;
}

/** `sequence<DOMString>`. */
export function strings(v, name, i) {
  return Array.from(iterable(v, name, i), str);
}

/** `sequence<GLenum>` / `sequence<GLuint>` as a `Uint32Array`. */
export function u32seq(v, name, i) {
  return Uint32Array.from(iterable(v, name, i), u32);
}

/** `Float32List`: a `Float32Array` as it is (no copy), or a sequence converted. */
export function f32list(v, name, i) {
  if (types.isFloat32Array(v)) return v;
  return Float32Array.from(iterable(v, name, i), num);
}

/** `Int32List`. */
export function i32list(v, name, i) {
  if (types.isInt32Array(v)) return v;
  return Int32Array.from(iterable(v, name, i), i32);
}

/** `Uint32List`. */
export function u32list(v, name, i) {
  if (types.isUint32Array(v)) return v;
  return Uint32Array.from(iterable(v, name, i), u32);
}

/**
 * An object argument of interface `cls` as the native side takes it: its id, 0 for `null`.
 * `null`/`undefined` where the IDL does not allow it, or another kind of value, is a
 * `TypeError`. An object of another context passes its id: essl-gl answers
 * `INVALID_OPERATION`.
 */
export function oid(ctx, v, cls, nullable, name, i) {
  if (v instanceof cls) return v[ID];
  if ((v === null || v === undefined) && nullable) return 0;
  throw new TypeError(
    `Failed to execute '${name}': parameter ${i} is not of type '${cls.name}'.`,
  );
}

/** A new WebGL object for the id a create call returned (0: `null`). */
export function wrapNew(ctx, cls, id) {
  if (id === 0) return null;
  const o = new cls(KEY, ctx, id);
  if (cls !== WebGLUniformLocation) ctx[OBJECTS].set(id, o);
  return o;
}

/** A native answer as JavaScript has it: `{ webglObjectId }` records become the objects. */
export function answer(ctx, r) {
  if (r === null || typeof r !== 'object') return r;
  if (Array.isArray(r)) {
    for (let i = 0; i < r.length; i++) r[i] = answer(ctx, r[i]);
    return r;
  }
  if ('webglObjectId' in r) return ctx[OBJECTS].get(r.webglObjectId) ?? null;
  return r;
}

/** A `WebGLActiveInfo` or `null`. */
export function activeInfo(r) {
  return r === null ? null : new WebGLActiveInfo(KEY, r);
}

/** A `WebGLShaderPrecisionFormat` or `null`. */
export function precisionFormat(r) {
  return r === null ? null : new WebGLShaderPrecisionFormat(KEY, r);
}
