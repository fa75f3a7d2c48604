// Contexts for canvases of another JavaScript realm (a jsdom window runs its scripts in a
// VM context of its own): the page's `instanceof Int32Array` and `instanceof TypeError`
// must hold for what a context returns and throws, so such a context is of a subclass whose
// methods hand over values made with the page's constructors. The main realm's classes stay
// as they are.
import { types } from 'node:util';
import { WebGLRenderingContext, WebGL2RenderingContext } from './context.js';

const CLASSES = new WeakMap();

/** The global object `canvas` belongs to (a jsdom window, or this realm's). */
export function realmOf(canvas) {
  const win = canvas?.ownerDocument?.defaultView;
  return win && win.Int32Array && win.Int32Array !== Int32Array ? win : globalThis;
}

/** The context class of WebGL `version` for `realm`. */
export function contextClass(realm, version) {
  const base = version === 2 ? WebGL2RenderingContext : WebGLRenderingContext;
  if (realm === globalThis) return base;
  let classes = CLASSES.get(realm);
  if (!classes) {
    classes = { 1: subclass(realm, WebGLRenderingContext), 2: subclass(realm, WebGL2RenderingContext) };
    CLASSES.set(realm, classes);
  }
  return classes[version];
}

function subclass(realm, base) {
  const cls = { [base.name]: class extends base {} }[base.name];
  // The interface object's constants are its own properties (Object.entries finds them).
  for (const k of Object.keys(base)) {
    Object.defineProperty(cls, k, Object.getOwnPropertyDescriptor(base, k));
  }
  const proto = base.prototype;
  for (const name of Object.getOwnPropertyNames(proto)) {
    const d = Object.getOwnPropertyDescriptor(proto, name);
    if (name === 'constructor' || typeof d.value !== 'function') continue;
    const f = d.value;
    const wrapped = {
      [name](...args) {
        let r;
        try {
          r = f.apply(this, args);
        } catch (e) {
          throw intoRealm(realm, e);
        }
        return intoRealm(realm, r);
      },
    }[name];
    Object.defineProperty(cls.prototype, name, { ...d, value: wrapped });
  }
  return cls;
}

const TYPED = ['Int8Array', 'Uint8Array', 'Uint8ClampedArray', 'Int16Array', 'Uint16Array', 'Int32Array', 'Uint32Array', 'Float32Array', 'Float64Array'];

/** `v` with this realm's arrays, plain objects and errors remade in `realm`. */
export function intoRealm(realm, v) {
  if (v === null || (typeof v !== 'object' && typeof v !== 'function')) return v;
  if (v instanceof Error) {
    const E = realm[v.name] ?? realm.Error;
    return new E(v.message);
  }
  if (ArrayBuffer.isView(v) && !types.isDataView(v)) {
    for (const t of TYPED) {
      if (v instanceof globalThis[t]) return new realm[t](v);
    }
    return v;
  }
  if (Array.isArray(v)) {
    const a = new realm.Array(v.length);
    for (let i = 0; i < v.length; i++) a[i] = intoRealm(realm, v[i]);
    return a;
  }
  if (Object.getPrototypeOf(v) === Object.prototype) {
    const o = new realm.Object();
    for (const [k, x] of Object.entries(v)) o[k] = intoRealm(realm, x);
    return o;
  }
  return v;
}
