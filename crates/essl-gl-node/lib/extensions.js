// The extension objects `getExtension` returns: those essl-gl implements (their constants),
// and `WEBGL_lose_context`, which the binding implements (a lost context is the binding's
// state). One object per name and context, as browsers return the same object each time.
import { FRAME_CALLS, frameChanged, loseContext, restoreContext } from './context.js';
import { NATIVE, VERSION, WebGLShader, argc, i32, i32list, num, oid, u32 } from './objects.js';
import { METHODS_2 } from './generated.js';

/** ASTC's block sizes, in the order of their enums. */
const ASTC_SIZES = [
  [4, 4], [5, 4], [5, 5], [6, 5], [6, 6], [8, 5], [8, 6],
  [8, 8], [10, 5], [10, 6], [10, 8], [10, 10], [12, 10], [12, 12],
];

/** Constants of the extensions that have any. */
const CONSTANTS = {
  EXT_color_buffer_half_float: {
    RGBA16F_EXT: 0x881a,
    RGB16F_EXT: 0x881b,
    FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE_EXT: 0x8211,
    UNSIGNED_NORMALIZED_EXT: 0x8c17,
  },
  WEBGL_color_buffer_float: {
    RGBA32F_EXT: 0x8814,
    FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE_EXT: 0x8211,
    UNSIGNED_NORMALIZED_EXT: 0x8c17,
  },
  OES_texture_half_float: { HALF_FLOAT_OES: 0x8d61 },
  WEBGL_compressed_texture_s3tc: {
    COMPRESSED_RGB_S3TC_DXT1_EXT: 0x83f0,
    COMPRESSED_RGBA_S3TC_DXT1_EXT: 0x83f1,
    COMPRESSED_RGBA_S3TC_DXT3_EXT: 0x83f2,
    COMPRESSED_RGBA_S3TC_DXT5_EXT: 0x83f3,
  },
  WEBGL_compressed_texture_s3tc_srgb: {
    COMPRESSED_SRGB_S3TC_DXT1_EXT: 0x8c4c,
    COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT: 0x8c4d,
    COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT: 0x8c4e,
    COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT: 0x8c4f,
  },
  WEBGL_compressed_texture_etc: {
    COMPRESSED_R11_EAC: 0x9270,
    COMPRESSED_SIGNED_R11_EAC: 0x9271,
    COMPRESSED_RG11_EAC: 0x9272,
    COMPRESSED_SIGNED_RG11_EAC: 0x9273,
    COMPRESSED_RGB8_ETC2: 0x9274,
    COMPRESSED_SRGB8_ETC2: 0x9275,
    COMPRESSED_RGB8_PUNCHTHROUGH_ALPHA1_ETC2: 0x9276,
    COMPRESSED_SRGB8_PUNCHTHROUGH_ALPHA1_ETC2: 0x9277,
    COMPRESSED_RGBA8_ETC2_EAC: 0x9278,
    COMPRESSED_SRGB8_ALPHA8_ETC2_EAC: 0x9279,
  },
  WEBGL_compressed_texture_etc1: { COMPRESSED_RGB_ETC1_WEBGL: 0x8d64 },
  EXT_texture_compression_rgtc: {
    COMPRESSED_RED_RGTC1_EXT: 0x8dbb,
    COMPRESSED_SIGNED_RED_RGTC1_EXT: 0x8dbc,
    COMPRESSED_RED_GREEN_RGTC2_EXT: 0x8dbd,
    COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT: 0x8dbe,
  },
  EXT_texture_compression_bptc: {
    COMPRESSED_RGBA_BPTC_UNORM_EXT: 0x8e8c,
    COMPRESSED_SRGB_ALPHA_BPTC_UNORM_EXT: 0x8e8d,
    COMPRESSED_RGB_BPTC_SIGNED_FLOAT_EXT: 0x8e8e,
    COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT_EXT: 0x8e8f,
  },
  WEBGL_depth_texture: { UNSIGNED_INT_24_8_WEBGL: 0x84fa },
  EXT_sRGB: {
    SRGB_EXT: 0x8c40,
    SRGB_ALPHA_EXT: 0x8c42,
    SRGB8_ALPHA8_EXT: 0x8c43,
    FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING_EXT: 0x8210,
  },
  EXT_texture_filter_anisotropic: {
    TEXTURE_MAX_ANISOTROPY_EXT: 0x84fe,
    MAX_TEXTURE_MAX_ANISOTROPY_EXT: 0x84ff,
  },
  WEBGL_compressed_texture_astc: Object.fromEntries(
    ASTC_SIZES.flatMap(([w, h], i) => [
      [`COMPRESSED_RGBA_ASTC_${w}x${h}_KHR`, 0x93b0 + i],
      [`COMPRESSED_SRGB8_ALPHA8_ASTC_${w}x${h}_KHR`, 0x93d0 + i],
    ]),
  ),
  WEBGL_stencil_texturing: { DEPTH_STENCIL_TEXTURE_MODE_WEBGL: 0x90ea, STENCIL_INDEX_WEBGL: 0x1901 },
  EXT_polygon_offset_clamp: { POLYGON_OFFSET_CLAMP_EXT: 0x8e1b },
  WEBGL_debug_renderer_info: { UNMASKED_VENDOR_WEBGL: 0x9245, UNMASKED_RENDERER_WEBGL: 0x9246 },
  EXT_depth_clamp: { DEPTH_CLAMP_EXT: 0x864f },
  WEBGL_polygon_mode: {
    POLYGON_MODE_WEBGL: 0x0b40,
    POLYGON_OFFSET_LINE_WEBGL: 0x2a02,
    LINE_WEBGL: 0x1b01,
    FILL_WEBGL: 0x1b02,
  },
  EXT_clip_control: {
    LOWER_LEFT_EXT: 0x8ca1,
    UPPER_LEFT_EXT: 0x8ca2,
    NEGATIVE_ONE_TO_ONE_EXT: 0x935e,
    ZERO_TO_ONE_EXT: 0x935f,
    CLIP_ORIGIN_EXT: 0x935c,
    CLIP_DEPTH_MODE_EXT: 0x935d,
  },
  WEBGL_clip_cull_distance: {
    MAX_CLIP_DISTANCES_WEBGL: 0x0d32,
    MAX_CULL_DISTANCES_WEBGL: 0x82f9,
    MAX_COMBINED_CLIP_AND_CULL_DISTANCES_WEBGL: 0x82fa,
    ...Object.fromEntries(
      Array.from({ length: 8 }, (_, i) => [`CLIP_DISTANCE${i}_WEBGL`, 0x3000 + i]),
    ),
  },
  OES_vertex_array_object: { VERTEX_ARRAY_BINDING_OES: 0x85b5 },
  ANGLE_instanced_arrays: { VERTEX_ATTRIB_ARRAY_DIVISOR_ANGLE: 0x88fe },
  OES_standard_derivatives: { FRAGMENT_SHADER_DERIVATIVE_HINT_OES: 0x8b8b },
  EXT_blend_minmax: { MIN_EXT: 0x8007, MAX_EXT: 0x8008 },
  WEBGL_draw_buffers: Object.fromEntries([
    ...Array.from({ length: 16 }, (_, i) => [`COLOR_ATTACHMENT${i}_WEBGL`, 0x8ce0 + i]),
    ...Array.from({ length: 16 }, (_, i) => [`DRAW_BUFFER${i}_WEBGL`, 0x8825 + i]),
    ['MAX_COLOR_ATTACHMENTS_WEBGL', 0x8cdf],
    ['MAX_DRAW_BUFFERS_WEBGL', 0x8824],
  ]),
};

/**
 * The methods of WebGL 1 extensions that expose WebGL 2 calls under their own names: the
 * same conversions and answers, on the context the extension came from.
 */
const METHODS = {
  OES_vertex_array_object: {
    createVertexArrayOES: 'createVertexArray',
    deleteVertexArrayOES: 'deleteVertexArray',
    isVertexArrayOES: 'isVertexArray',
    bindVertexArrayOES: 'bindVertexArray',
  },
  ANGLE_instanced_arrays: {
    drawArraysInstancedANGLE: 'drawArraysInstanced',
    drawElementsInstancedANGLE: 'drawElementsInstanced',
    vertexAttribDivisorANGLE: 'vertexAttribDivisor',
  },
  WEBGL_draw_buffers: { drawBuffersWEBGL: 'drawBuffers' },
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
  const ext = new (classOf(enabled))();
  if (enabled === 'WEBGL_compressed_texture_astc') {
    // essl-gl decodes ASTC's LDR profile.
    Object.defineProperty(ext, 'getSupportedProfiles', { value: () => ['ldr'], enumerable: true });
  }
  if (enabled === 'EXT_clip_control') {
    method(ctx, ext, 'clipControlEXT', 'u32 u32', (n, a) => n.clipControlExt(...a));
  }
  if (enabled === 'WEBGL_debug_shaders') {
    Object.defineProperty(ext, 'getTranslatedShaderSource', {
      value(shader) {
        const id = oid(ctx, shader, WebGLShader, false, 'getTranslatedShaderSource', 1);
        const n = ctx[NATIVE];
        return n === null ? null : n.getTranslatedShaderSource(id);
      },
      enumerable: true,
    });
  }
  if (enabled === 'WEBGL_multi_draw') multiDrawMethods(ctx, ext);
  if (enabled === 'OES_draw_buffers_indexed') drawBuffersIndexedMethods(ctx, ext);
  if (enabled === 'EXT_polygon_offset_clamp') {
    method(ctx, ext, 'polygonOffsetClampEXT', 'num num num', (n, a) => n.polygonOffsetClampExt(...a));
  }
  if (enabled === 'WEBGL_polygon_mode') {
    method(ctx, ext, 'polygonModeWEBGL', 'u32 u32', (n, a) => n.polygonModeWebgl(...a));
  }
  for (const [own, core] of Object.entries(METHODS[enabled] ?? {})) {
    const f = METHODS_2[core];
    // A draw ends the frame as the core call does.
    const draws = FRAME_CALLS.includes(core);
    const value = {
      [own](...args) {
        const r = f.apply(ctx, args);
        if (draws) frameChanged(ctx);
        return r;
      },
    }[own];
    Object.defineProperty(ext, own, { value, enumerable: true });
  }
  return ext;
}

/**
 * `WEBGL_multi_draw`'s four calls. Each argument is converted as its IDL type says — a list is
 * an `Int32Array` (shared memory too) or a sequence of `GLint`, an offset a `GLuint` — and the
 * native side checks the offsets and `drawcount`.
 */
function multiDrawMethods(ctx, ext) {
  const calls = {
    multiDrawArraysWEBGL: ['multiDrawArrays', 'u32 list u32 list u32 i32'],
    multiDrawArraysInstancedWEBGL: ['multiDrawArraysInstanced', 'u32 list u32 list u32 list u32 i32'],
    multiDrawElementsWEBGL: ['multiDrawElements', 'u32 list u32 u32 list u32 i32'],
    multiDrawElementsInstancedWEBGL: [
      'multiDrawElementsInstanced',
      'u32 list u32 u32 list u32 list u32 i32',
    ],
  };
  for (const [name, [native, signature]] of Object.entries(calls)) {
    method(ctx, ext, name, signature, (n, a) => n[native](...a), true);
  }
}

/**
 * `OES_draw_buffers_indexed`'s calls: each draw buffer's blending and colour mask. The
 * one-equation and one-function forms are the separate ones with the same value twice.
 */
function drawBuffersIndexedMethods(ctx, ext) {
  const calls = {
    enableiOES: ['u32 u32', (n, [t, i]) => n.enableIndexed(t, i, true)],
    disableiOES: ['u32 u32', (n, [t, i]) => n.enableIndexed(t, i, false)],
    blendEquationiOES: ['u32 u32', (n, [i, m]) => n.blendEquationSeparateIndexed(i, m, m)],
    blendEquationSeparateiOES: [
      'u32 u32 u32', (n, [i, rgb, a]) => n.blendEquationSeparateIndexed(i, rgb, a),
    ],
    blendFunciOES: ['u32 u32 u32', (n, [i, s, d]) => n.blendFuncSeparateIndexed(i, s, d, s, d)],
    blendFuncSeparateiOES: [
      'u32 u32 u32 u32 u32', (n, [i, ...f]) => n.blendFuncSeparateIndexed(i, ...f),
    ],
    colorMaskiOES: ['u32 bool bool bool bool', (n, [i, ...m]) => n.colorMaskIndexed(i, ...m)],
  };
  for (const [name, [signature, call]] of Object.entries(calls)) method(ctx, ext, name, signature, call);
}

/**
 * Defines extension method `name` on `ext`: its arguments converted as `signature` lists their
 * IDL types (`u32`, `i32`, `num`, `bool`, `list`: an `Int32Array` or a sequence of `GLint`),
 * then `call(native, converted)`; a draw (`draws`) ends the frame as a core draw does. A named
 * function, so that `f.name` reads as in a browser.
 */
function method(ctx, ext, name, signature, call, draws = false) {
  const kinds = signature.split(' ');
  const convert = {
    u32,
    i32,
    num,
    bool: (v) => !!v,
    list: (v, i) => i32list(v, name, i + 1),
  };
  const f = {
    [name](...args) {
      if (args.length < kinds.length) throw argc(name, kinds.length, args.length);
      const converted = kinds.map((k, i) => convert[k](args[i], i));
      const n = ctx[NATIVE];
      if (n !== null) call(n, converted);
      if (draws) frameChanged(ctx);
    },
  }[name];
  Object.defineProperty(ext, name, { value: f, enumerable: true });
}

function canonical(name) {
  return name.toUpperCase() === 'EXT_COLOR_BUFFER_FLOAT' ? 'EXT_color_buffer_float' : name;
}

