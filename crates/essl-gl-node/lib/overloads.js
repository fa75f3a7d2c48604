// The operations WebIDL resolves by their arguments (bufferData, texImage2D, readPixels,
// uniform*v, …), written out: which overload an argument list selects, as WebIDL's overload
// resolution picks it for WebGL 1's and WebGL 2's IDL, then the native call.
import {
  NATIVE, VERSION, argc, u32, i32, i64, f32, bool, offset32, f32list, i32list, u32list, oid,
  WebGLUniformLocation,
} from './objects.js';
import { imageSource, isImageSource } from './sources.js';
import { types } from 'node:util';

const INVALID_VALUE = 0x501;

/** Whether `v` is an `ArrayBufferView` (a typed array or a DataView). */
function isView(v) {
  return ArrayBuffer.isView(v);
}

/** Whether `v` is an `ArrayBuffer` or `SharedArrayBuffer` (of any realm). */
function isBuffer(v) {
  return types.isAnyArrayBuffer(v);
}

function typeError(name, what) {
  return new TypeError(`Failed to execute '${name}': ${what}`);
}

function arity(name, valid, given) {
  return typeError(name, `Valid arities are: [${valid.join(', ')}], but ${given} arguments provided.`);
}

/** An `AllowSharedBufferSource` as a view over the same bytes (no copy). */
function bytesOf(v) {
  return isBuffer(v) ? new Uint8Array(v) : v;
}

export const OVERLOADS = {
  bufferData(target, data, usage, srcOffset, length) {
    const n0 = arguments.length;
    if (n0 < 3) throw argc('bufferData', 3, n0);
    const webgl2 = this[VERSION] === 2;
    if (webgl2 && n0 >= 4) {
      if (!isView(data)) throw typeError('bufferData', "parameter 2 is not of type 'ArrayBufferView'.");
      const t = u32(target), u = u32(usage), o = offset32(srcOffset), l = n0 > 4 ? u32(length) : 0;
      const n = this[NATIVE];
      if (n !== null) n.bufferData(t, data, u, o, l);
      return;
    }
    const t = u32(target);
    if (data === null || data === undefined) {
      const u = u32(usage);
      const n = this[NATIVE];
      if (n !== null) n.synthesizeError(INVALID_VALUE, 'bufferData', 'no data');
      return void u;
    }
    if (isView(data) || isBuffer(data)) {
      const u = u32(usage);
      const n = this[NATIVE];
      if (n !== null) n.bufferData(t, bytesOf(data), u, 0, 0);
      return;
    }
    const size = i64(data), u = u32(usage);
    const n = this[NATIVE];
    if (n !== null) n.bufferDataSize(t, size, u);
  },

  bufferSubData(target, offset, data, srcOffset, length) {
    const n0 = arguments.length;
    if (n0 < 3) throw argc('bufferSubData', 3, n0);
    const t = u32(target), o = i64(offset);
    if (this[VERSION] === 2 && n0 >= 4) {
      if (!isView(data)) throw typeError('bufferSubData', "parameter 3 is not of type 'ArrayBufferView'.");
      const so = offset32(srcOffset), l = n0 > 4 ? u32(length) : 0;
      const n = this[NATIVE];
      if (n !== null) n.bufferSubData(t, o, data, so, l);
      return;
    }
    if (!isView(data) && !isBuffer(data)) {
      throw typeError('bufferSubData', "parameter 3 is not of type '(ArrayBuffer or ArrayBufferView)'.");
    }
    const n = this[NATIVE];
    if (n !== null) n.bufferSubData(t, o, bytesOf(data), 0, 0);
  },

  getBufferSubData(target, srcByteOffset, dstBuffer, dstOffset, length) {
    const n0 = arguments.length;
    if (n0 < 3) throw argc('getBufferSubData', 3, n0);
    const t = u32(target), o = i64(srcByteOffset);
    if (!isView(dstBuffer)) throw typeError('getBufferSubData', "parameter 3 is not of type 'ArrayBufferView'.");
    const d = offset32(dstOffset ?? 0), l = u32(length ?? 0);
    const n = this[NATIVE];
    if (n !== null) n.getBufferSubData(t, o, dstBuffer, d, l);
  },

  texImage2D(...args) {
    return texImage.call(this, 'texImage2D', false, false, args);
  },
  texImage3D(...args) {
    return texImage.call(this, 'texImage3D', false, true, args);
  },
  texSubImage2D(...args) {
    return texImage.call(this, 'texSubImage2D', true, false, args);
  },
  texSubImage3D(...args) {
    return texImage.call(this, 'texSubImage3D', true, true, args);
  },

  compressedTexImage2D(...args) {
    return compressed.call(this, 'compressedTexImage2D', 4, args);
  },
  compressedTexImage3D(...args) {
    return compressed.call(this, 'compressedTexImage3D', 5, args);
  },
  compressedTexSubImage2D(...args) {
    return compressed.call(this, 'compressedTexSubImage2D', 5, args);
  },
  compressedTexSubImage3D(...args) {
    return compressed.call(this, 'compressedTexSubImage3D', 7, args);
  },

  readPixels(x, y, width, height, format, type, dst, dstOffset) {
    const n0 = arguments.length;
    if (n0 < 7) throw argc('readPixels', 7, n0);
    const a = [i32(x), i32(y), i32(width), i32(height), u32(format), u32(type)];
    const webgl2 = this[VERSION] === 2;
    if (webgl2 && n0 >= 8) {
      if (!isView(dst)) throw typeError('readPixels', "parameter 7 is not of type 'ArrayBufferView'.");
      const o = offset32(dstOffset);
      const n = this[NATIVE];
      if (n !== null) n.readPixels(...a, dst, o);
      return;
    }
    if (dst === null || dst === undefined) {
      const n = this[NATIVE];
      if (n !== null) n.synthesizeError(INVALID_VALUE, 'readPixels', 'no destination ArrayBufferView');
      return;
    }
    if (isView(dst)) {
      const n = this[NATIVE];
      if (n !== null) n.readPixels(...a, dst, 0);
      return;
    }
    if (!webgl2) throw typeError('readPixels', "parameter 7 is not of type 'ArrayBufferView'.");
    const o = i64(dst);
    const n = this[NATIVE];
    if (n !== null) n.readPixelsToBuffer(...a, o);
  },

  vertexAttrib1f(index, x) {
    if (arguments.length < 2) throw argc('vertexAttrib1f', 2, arguments.length);
    const i = u32(index), a = f32(x);
    const n = this[NATIVE];
    if (n !== null) n.vertexAttrib4f(i, a, 0, 0, 1);
  },
  vertexAttrib2f(index, x, y) {
    if (arguments.length < 3) throw argc('vertexAttrib2f', 3, arguments.length);
    const i = u32(index), a = f32(x), b = f32(y);
    const n = this[NATIVE];
    if (n !== null) n.vertexAttrib4f(i, a, b, 0, 1);
  },
  vertexAttrib3f(index, x, y, z) {
    if (arguments.length < 4) throw argc('vertexAttrib3f', 4, arguments.length);
    const i = u32(index), a = f32(x), b = f32(y), c = f32(z);
    const n = this[NATIVE];
    if (n !== null) n.vertexAttrib4f(i, a, b, c, 1);
  },

  clearBufferfv(buffer, drawbuffer, values, srcOffset) {
    if (arguments.length < 3) throw argc('clearBufferfv', 3, arguments.length);
    const b = u32(buffer), d = i32(drawbuffer), v = f32list(values, 'clearBufferfv', 3);
    const o = offset32(srcOffset ?? 0);
    const n = this[NATIVE];
    if (n !== null) n.clearBufferfv(b, d, v, o);
  },
  clearBufferiv(buffer, drawbuffer, values, srcOffset) {
    if (arguments.length < 3) throw argc('clearBufferiv', 3, arguments.length);
    const b = u32(buffer), d = i32(drawbuffer), v = i32list(values, 'clearBufferiv', 3);
    const o = offset32(srcOffset ?? 0);
    const n = this[NATIVE];
    if (n !== null) n.clearBufferiv(b, d, v, o);
  },
  clearBufferuiv(buffer, drawbuffer, values, srcOffset) {
    if (arguments.length < 3) throw argc('clearBufferuiv', 3, arguments.length);
    const b = u32(buffer), d = i32(drawbuffer), v = u32list(values, 'clearBufferuiv', 3);
    const o = offset32(srcOffset ?? 0);
    const n = this[NATIVE];
    if (n !== null) n.clearBufferuiv(b, d, v, o);
  },
};

// vertexAttrib[1234]fv.
for (const k of [1, 2, 3, 4]) {
  const name = `vertexAttrib${k}fv`;
  OVERLOADS[name] = {
    [name](index, values) {
      if (arguments.length < 2) throw argc(name, 2, arguments.length);
      const i = u32(index), v = f32list(values, name, 2);
      const n = this[NATIVE];
      if (n !== null) n.vertexAttribFv(k, i, v);
    },
  }[name];
}

// uniform[1234]{f,i,ui}v.
for (const [suffix, list, native] of [
  ['fv', f32list, 'uniformFv'],
  ['iv', i32list, 'uniformIv'],
  ['uiv', u32list, 'uniformUiv'],
]) {
  for (const k of [1, 2, 3, 4]) {
    const name = `uniform${k}${suffix}`;
    OVERLOADS[name] = {
      [name](location, data, srcOffset, srcLength) {
        if (arguments.length < 2) throw argc(name, 2, arguments.length);
        const l = oid(this, location, WebGLUniformLocation, true, name, 1);
        const v = list(data, name, 2);
        const webgl2 = this[VERSION] === 2;
        const o = webgl2 && srcOffset !== undefined ? offset32(srcOffset) : 0;
        const len = webgl2 && srcLength !== undefined ? u32(srcLength) : 0;
        const n = this[NATIVE];
        if (n !== null) n[native](k, l, v, o, len);
      },
    }[name];
  }
}

// uniformMatrix{C}x{R}fv.
for (const [shape, code] of [
  ['2', 22], ['3', 33], ['4', 44], ['2x3', 23], ['2x4', 24], ['3x2', 32], ['3x4', 34],
  ['4x2', 42], ['4x3', 43],
]) {
  const name = `uniformMatrix${shape}fv`;
  OVERLOADS[name] = {
    [name](location, transpose, data, srcOffset, srcLength) {
      if (arguments.length < 3) throw argc(name, 3, arguments.length);
      const l = oid(this, location, WebGLUniformLocation, true, name, 1);
      const t = bool(transpose);
      const v = f32list(data, name, 3);
      const webgl2 = this[VERSION] === 2;
      const o = webgl2 && srcOffset !== undefined ? offset32(srcOffset) : 0;
      const len = webgl2 && srcLength !== undefined ? u32(srcLength) : 0;
      const n = this[NATIVE];
      if (n !== null) n.uniformMatrixFv(code, l, t, v, o, len);
    },
  }[name];
}

/** How many integers stand between `level` and `format` in each upload call. */
const MIDDLE = {
  texImage2D: ['internalformat', 'width', 'height', 'border'],
  texImage3D: ['internalformat', 'width', 'height', 'depth', 'border'],
  texSubImage2D: ['x', 'y', 'width', 'height'],
  texSubImage3D: ['x', 'y', 'z', 'width', 'height', 'depth'],
};

/**
 * texImage2D/3D and texSubImage2D/3D: by argument count and the type of the data argument,
 * a typed array (or `null`), an offset into the bound `PIXEL_UNPACK_BUFFER`, or an image
 * source (`ImageData`, a canvas of the `canvas` or `@napi-rs/canvas` packages).
 */
function texImage(name, sub, threeD, args) {
  const webgl2 = this[VERSION] === 2;
  const fields = MIDDLE[name];
  const full = 2 + fields.length + 2; // before the data argument
  const n0 = args.length;
  // WebGL 1's and WebGL 2's 2D "source" overloads without a size.
  const shortLen = sub ? 7 : 6;
  if (!threeD && n0 === shortLen) {
    return sourceShort.call(this, name, sub, args);
  }
  const valid = threeD ? [full + 1, full + 2] : webgl2 ? [shortLen, full + 1, full + 2] : [shortLen, full + 1];
  if (n0 < full + 1) {
    if (n0 < shortLen) throw argc(name, shortLen, n0);
    throw arity(name, valid, n0);
  }
  const r = region(args, fields, sub);
  const data = args[full];
  const n = this[NATIVE];
  if (webgl2 && n0 >= full + 2) {
    if (!isView(data)) throw typeError(name, `parameter ${full + 1} is not of type 'ArrayBufferView'.`);
    const o = offset32(args[full + 1]);
    if (n !== null) n.texImageView(sub, threeD, r, data, o);
    return;
  }
  if (data === null || data === undefined) {
    // The IDL's pixels are nullable: a sub-image of no data is a GL error, as in Chromium.
    if (sub) {
      if (n !== null) n.synthesizeError(0x0501, name, 'no image data');
      return;
    }
    if (n !== null) n.texImageView(sub, threeD, r, null, 0);
    return;
  }
  if (isView(data)) {
    if (n !== null) n.texImageView(sub, threeD, r, data, 0);
    return;
  }
  if (isImageSource(data)) {
    if (!webgl2) throw typeError(name, `parameter ${full + 1} is not of type 'ArrayBufferView'.`);
    const src = imageSource(data, name);
    if (n !== null) n.texImageSource(sub, threeD, r, src.data, src.width, src.height, src.bitmap === true);
    return;
  }
  if (!webgl2) throw typeError(name, `parameter ${full + 1} is not of type 'ArrayBufferView'.`);
  if (typeof data === 'object' && !types.isNumberObject(data)) {
    throw typeError(name, `parameter ${full + 1} is not of type 'ArrayBufferView'.`);
  }
  const o = i64(data);
  if (n !== null) n.texImageBuffer(sub, threeD, r, o);
}

/** The `Region` the native upload calls take, from the numbers of an argument list. */
function region(args, fields, sub) {
  const r = {
    target: u32(args[0]),
    level: i32(args[1]),
    internalformat: 0,
    x: 0,
    y: 0,
    z: 0,
    width: 0,
    height: 0,
    depth: 1,
    border: 0,
  };
  fields.forEach((f, i) => {
    r[f] = i32(args[2 + i]);
  });
  r.format = u32(args[2 + fields.length]);
  r.ty = u32(args[3 + fields.length]);
  void sub;
  return r;
}

/** texImage2D(target, level, internalformat, format, type, source) and the texSub form. */
function sourceShort(name, sub, args) {
  const fields = sub ? ['x', 'y'] : ['internalformat'];
  const r = region(args, fields, sub);
  const source = args[args.length - 1];
  if (!isImageSource(source)) {
    throw typeError(
      name,
      `parameter ${args.length} is not of type '(ImageBitmap or ImageData or HTMLImageElement or HTMLCanvasElement or HTMLVideoElement or OffscreenCanvas or VideoFrame)'.`,
    );
  }
  const src = imageSource(source, name);
  r.width = src.width;
  r.height = src.height;
  const n = this[NATIVE];
  if (n !== null) n.texImageSource(sub, false, r, src.data, src.width, src.height, src.bitmap === true);
}

/** The compressed-texture calls: `count` integers between `level` and the data. */
function compressed(name, count, args) {
  const n0 = args.length;
  const required = 2 + count + 1;
  if (n0 < required) throw argc(name, required, n0);
  const target = u32(args[0]), level = i32(args[1]);
  const numbers = [];
  for (let i = 0; i < count; i++) numbers.push(i64(args[2 + i]));
  const data = args[2 + count];
  const n = this[NATIVE];
  if (isView(data)) {
    // WebGL 2: (…, srcData, srcOffset, srcLengthOverride), both in elements of srcData.
    let view = data;
    if (this[VERSION] === 2 && args.length > 3 + count) {
      const elem = data.BYTES_PER_ELEMENT ?? 1;
      const length = data.byteLength / elem;
      const off = u32(args[3 + count]);
      const over = args.length > 4 + count ? u32(args[4 + count]) : 0;
      const len = over === 0 ? length - off : over;
      if (off > length || off + len > length) {
        if (n !== null) n.synthesizeError(INVALID_VALUE, name, 'srcOffset + srcLengthOverride past the end of srcData');
        return;
      }
      view = new Uint8Array(data.buffer, data.byteOffset + off * elem, len * elem);
    }
    if (n !== null) n.compressedTexImage(name, target, level, numbers, view);
    return;
  }
  if (this[VERSION] !== 2) {
    throw typeError(name, `parameter ${3 + count} is not of type 'ArrayBufferView'.`);
  }
  // (…, imageSize, offset): from the bound PIXEL_UNPACK_BUFFER.
  if (args.length < 4 + count) throw argc(name, 4 + count, args.length);
  numbers.push(i64(data), i64(args[3 + count]));
  if (n !== null) n.compressedTexImage(name, target, level, numbers, null);
}
