// The extension objects `getExtension` returns: those essl-gl implements (their constants),
// and `WEBGL_lose_context`, which the binding implements (a lost context is the binding's
// state). One object per name and context, as browsers return the same object each time.
import { loseContext, restoreContext } from './context.js';
import { VERSION } from './objects.js';

/** Constants of the extensions that have any. */
const CONSTANTS = {
  EXT_color_buffer_half_float: {
    RGBA16F_EXT: 0x881a,
    RGB16F_EXT: 0x881b,
    FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE_EXT: 0x8211,
    UNSIGNED_NORMALIZED_EXT: 0x8c17,
  },
  KHR_parallel_shader_compile: { COMPLETION_STATUS_KHR: 0x91b1 },
};

/** One class per extension, named as its IDL interface (`EXT_color_buffer_float`). */
const CLASSES = new Map();
function classOf(name) {
  let cls = CLASSES.get(name);
  if (!cls) {
    cls = { [name]: class {} }[name];
    for (const [k, v] of Object.entries(CONSTANTS[name] ?? {})) {
      Object.defineProperty(cls.prototype, k, { value: v, enumerable: true });
    }
    CLASSES.set(name, cls);
  }
  return cls;
}

/** The extensions a context offers (`getSupportedExtensions`). */
export function supportedExtensions(native, version) {
  const list = native.getSupportedExtensions().filter((e) => version === 2 || !WEBGL2_ONLY.has(e));
  return [...list, 'WEBGL_lose_context'].sort();
}

/** Extensions that exist only in WebGL 2 contexts. */
const WEBGL2_ONLY = new Set(['EXT_color_buffer_float']);

/** The object `getExtension(name)` returns, or `null`. */
export function extensionObject(ctx, native, name) {
  if (name.toLowerCase() === 'webgl_lose_context') {
    const cls = classOf('WEBGL_lose_context');
    const ext = new cls();
    Object.defineProperties(ext, {
      loseContext: { value: () => loseContext(ctx, false), enumerable: true },
      restoreContext: { value: () => restoreContext(ctx), enumerable: true },
    });
    return ext;
  }
  if (ctx[VERSION] !== 2 && WEBGL2_ONLY.has(canonical(name))) return null;
  const enabled = native.getExtension(name);
  if (enabled === null) return null;
  return new (classOf(enabled))();
}

function canonical(name) {
  return name.toUpperCase() === 'EXT_COLOR_BUFFER_FLOAT' ? 'EXT_color_buffer_float' : name;
}

