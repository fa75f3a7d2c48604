// The binding as a JavaScript program sees it: WebIDL's conversions and TypeErrors, object
// identity, GL errors, extensions, a lost and a destroyed context, typed arrays.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  createContext, Canvas, WebGL2RenderingContext, WebGLRenderingContext, WebGLBuffer,
  WebGLTexture, WebGLUniformLocation, WebGLActiveInfo, installInWindow,
} from '../index.js';

const gl = createContext(16, 16);

function program(ctx, vs, fs) {
  const p = ctx.createProgram();
  for (const [type, src] of [[ctx.VERTEX_SHADER, vs], [ctx.FRAGMENT_SHADER, fs]]) {
    const s = ctx.createShader(type);
    ctx.shaderSource(s, src);
    ctx.compileShader(s);
    assert.ok(ctx.getShaderParameter(s, ctx.COMPILE_STATUS), ctx.getShaderInfoLog(s));
    ctx.attachShader(p, s);
  }
  ctx.linkProgram(p);
  assert.ok(ctx.getProgramParameter(p, ctx.LINK_STATUS), ctx.getProgramInfoLog(p));
  return p;
}

test('the context is a WebGL2RenderingContext with the IDL constants and attributes', () => {
  assert.ok(gl instanceof WebGL2RenderingContext);
  assert.equal(Object.prototype.toString.call(gl), '[object WebGL2RenderingContext]');
  assert.equal(gl.ARRAY_BUFFER, 0x8892);
  assert.equal(WebGL2RenderingContext.RGBA32F, 0x8814);
  assert.equal(gl.drawingBufferWidth, 16);
  assert.equal(gl.drawingBufferHeight, 16);
  assert.ok(gl.canvas instanceof Canvas);
  assert.equal(gl.canvas.getContext('webgl2'), gl);
  assert.equal(gl.canvas.getContext('webgl'), null);
  assert.equal(gl.canvas.getContext('2d'), null);
  assert.match(gl.getParameter(gl.VERSION), /^WebGL 2\.0/);
  assert.throws(() => new WebGL2RenderingContext(), TypeError);
  assert.throws(() => new WebGLBuffer(), TypeError);
});

test('objects keep their identity through getParameter', () => {
  const b = gl.createBuffer();
  const t = gl.createTexture();
  assert.ok(b instanceof WebGLBuffer);
  gl.bindBuffer(gl.ARRAY_BUFFER, b);
  gl.bindTexture(gl.TEXTURE_2D, t);
  assert.equal(gl.getParameter(gl.ARRAY_BUFFER_BINDING), b);
  assert.equal(gl.getParameter(gl.TEXTURE_BINDING_2D), t);
  assert.ok(gl.getParameter(gl.TEXTURE_BINDING_2D) instanceof WebGLTexture);
  gl.bindBuffer(gl.ARRAY_BUFFER, null);
  assert.equal(gl.getParameter(gl.ARRAY_BUFFER_BINDING), null);
  b.label = 'vertices';
  assert.equal(b.label, 'vertices');
  gl.deleteBuffer(b);
  assert.equal(gl.isBuffer(b), false);
  assert.equal(gl.getError(), gl.NO_ERROR);
});

test('WebIDL conversions: numbers modulo, too few arguments and wrong types are TypeErrors', () => {
  assert.throws(() => gl.bindBuffer(gl.ARRAY_BUFFER), TypeError);
  assert.throws(() => gl.bindBuffer(gl.ARRAY_BUFFER, {}), TypeError);
  assert.throws(() => gl.bindBuffer(gl.ARRAY_BUFFER, gl.createTexture()), TypeError);
  assert.throws(() => gl.attachShader(null, null), TypeError);
  assert.throws(() => gl.uniform4fv(null, 7), TypeError);
  assert.throws(() => gl.enable(Symbol('x')), TypeError);
  assert.throws(() => gl.bufferSubData(gl.ARRAY_BUFFER, 0, 'abc'), TypeError);
  // "3042" converts to BLEND; 2^32 + BLEND wraps to BLEND.
  gl.enable('3042');
  assert.equal(gl.isEnabled(gl.BLEND), true);
  gl.disable(2 ** 32 + gl.BLEND);
  assert.equal(gl.isEnabled(gl.BLEND), false);
  // undefined for a nullable object is null.
  gl.bindBuffer(gl.ARRAY_BUFFER, undefined);
  assert.equal(gl.getError(), gl.NO_ERROR);
  // An unsigned long long srcOffset of -1 is 2^64 - 1: past the view, INVALID_OPERATION.
  const t = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, t);
  for (const o of [-1, 5]) {
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 1, 1, 0, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4), o);
    assert.equal(gl.getError(), gl.INVALID_OPERATION, `srcOffset ${o}`);
  }
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 1, 1, 0, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(8), 4);
  assert.equal(gl.getError(), gl.NO_ERROR);
  gl.deleteTexture(t);
});

test('a bad value is a GL error, never an exception', () => {
  gl.enable(0x1234);
  assert.equal(gl.getError(), gl.INVALID_ENUM);
  gl.bufferData(gl.ARRAY_BUFFER, null, gl.STATIC_DRAW);
  assert.equal(gl.getError(), gl.INVALID_VALUE);
  gl.drawArrays(gl.TRIANGLES, 0, 3);
  assert.equal(gl.getError(), gl.INVALID_OPERATION);
  assert.equal(gl.getError(), gl.NO_ERROR);
  // The pixels of texSubImage2D are nullable: no data is a GL error, as in Chromium.
  gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, 0, 0, gl.RGBA, gl.UNSIGNED_BYTE, null);
  assert.equal(gl.getError(), gl.INVALID_VALUE);
});

test('an object of another context is INVALID_OPERATION', () => {
  const other = createContext(4, 4);
  const b = other.createBuffer();
  gl.bindBuffer(gl.ARRAY_BUFFER, b);
  assert.equal(gl.getError(), gl.INVALID_OPERATION);
  other.destroy();
});

test('typed arrays in and out: bufferData without a copy, getBufferSubData and readPixels into the caller', () => {
  const b = gl.createBuffer();
  gl.bindBuffer(gl.COPY_READ_BUFFER, b);
  const src = new Float32Array([1, 2, 3, 4]);
  gl.bufferData(gl.COPY_READ_BUFFER, src.buffer, gl.STATIC_READ);
  const dst = new Float32Array(4);
  gl.getBufferSubData(gl.COPY_READ_BUFFER, 4, dst, 1, 3);
  assert.deepEqual([...dst], [0, 2, 3, 4]);
  gl.bufferSubData(gl.COPY_READ_BUFFER, 0, new Float32Array([9, 8]), 1, 1);
  gl.getBufferSubData(gl.COPY_READ_BUFFER, 0, dst);
  assert.deepEqual([...dst], [8, 2, 3, 4]);
  // srcOffset past the end of the array: INVALID_VALUE.
  gl.bufferSubData(gl.COPY_READ_BUFFER, 0, src, 5);
  assert.equal(gl.getError(), gl.INVALID_VALUE);
  gl.clearColor(0, 1, 0, 1);
  gl.clear(gl.COLOR_BUFFER_BIT);
  const px = new Uint8Array(8);
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px, 4);
  assert.deepEqual([...px], [0, 0, 0, 0, 0, 255, 0, 255]);
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Float32Array(4));
  assert.equal(gl.getError(), gl.INVALID_OPERATION);
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, null);
  assert.equal(gl.getError(), gl.INVALID_VALUE);
});

test('a triangle, uniforms, active info, getUniform and a PNG', () => {
  const p = program(
    gl,
    '#version 300 es\nin vec2 a_pos; void main() { gl_Position = vec4(a_pos, 0.0, 1.0); }',
    '#version 300 es\nprecision mediump float; uniform vec4 u_color; out vec4 o; void main() { o = u_color; }',
  );
  gl.useProgram(p);
  assert.equal(gl.getParameter(gl.CURRENT_PROGRAM), p);
  const loc = gl.getUniformLocation(p, 'u_color');
  assert.ok(loc instanceof WebGLUniformLocation);
  gl.uniform4fv(loc, [1, 0, 0.5, 1]);
  assert.deepEqual([...gl.getUniform(p, loc)], [1, 0, 0.5, 1]);
  const info = gl.getActiveUniform(p, 0);
  assert.ok(info instanceof WebGLActiveInfo);
  assert.equal(info.name, 'u_color');
  assert.equal(info.type, gl.FLOAT_VEC4);
  const vb = gl.createBuffer();
  gl.bindBuffer(gl.ARRAY_BUFFER, vb);
  gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 3, -1, -1, 3]), gl.STATIC_DRAW);
  const at = gl.getAttribLocation(p, 'a_pos');
  gl.enableVertexAttribArray(at);
  gl.vertexAttribPointer(at, 2, gl.FLOAT, false, 0, 0);
  gl.drawArrays(gl.TRIANGLES, 0, 3);
  const px = new Uint8Array(4);
  gl.readPixels(8, 8, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
  assert.deepEqual([...px], [255, 0, 128, 255]);
  const png = gl.toPNG();
  assert.deepEqual([...png.subarray(0, 8)], [137, 80, 78, 71, 13, 10, 26, 10]);
  assert.equal(gl.getError(), gl.NO_ERROR);
});

test('texImage2D from an ImageData-shaped object', () => {
  const t = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, t);
  const data = new Uint8ClampedArray([255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255]);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA, gl.RGBA, gl.UNSIGNED_BYTE, { width: 2, height: 2, data });
  assert.equal(gl.getError(), gl.NO_ERROR);
  const fb = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, t, 0);
  const px = new Uint8Array(16);
  gl.readPixels(0, 0, 2, 2, gl.RGBA, gl.UNSIGNED_BYTE, px);
  // The source's first row is the texture's row 0.
  assert.deepEqual([...px], [...data]);
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  assert.throws(() => gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA, gl.RGBA, gl.UNSIGNED_BYTE, 5), TypeError);
});

test('extensions: the same object each time, null for unknown names', () => {
  const ext = gl.getExtension('EXT_color_buffer_float');
  assert.ok(ext);
  assert.equal(gl.getExtension('ext_color_buffer_float'), ext);
  assert.equal(gl.getExtension('WEBGL_no_such_thing'), null);
  assert.ok(gl.getSupportedExtensions().includes('WEBGL_lose_context'));
});

test('compressed textures: extension objects, the srcOffset and PIXEL_UNPACK_BUFFER forms, sampling', () => {
  const ctx = createContext(2, 2);
  const tex = ctx.createTexture();
  ctx.bindTexture(ctx.TEXTURE_2D, tex);
  // A DXT1 block of red, 4 bytes into the data.
  const red = [0x00, 0xf8, 0x1f, 0x00, 0, 0, 0, 0];
  const data = new Uint8Array([9, 9, 9, 9, ...red]);
  ctx.compressedTexImage2D(ctx.TEXTURE_2D, 0, 0x83f0, 4, 4, 0, data, 4);
  assert.equal(ctx.getError(), ctx.INVALID_ENUM, 'before the extension');
  const s3tc = ctx.getExtension('WEBGL_compressed_texture_s3tc');
  assert.equal(s3tc.COMPRESSED_RGB_S3TC_DXT1_EXT, 0x83f0);
  assert.deepEqual([...ctx.getParameter(ctx.COMPRESSED_TEXTURE_FORMATS)], [0x83f0, 0x83f1, 0x83f2, 0x83f3]);
  assert.deepEqual(ctx.getExtension('WEBGL_compressed_texture_astc').getSupportedProfiles(), ['ldr']);
  ctx.compressedTexImage2D(ctx.TEXTURE_2D, 0, s3tc.COMPRESSED_RGB_S3TC_DXT1_EXT, 4, 4, 0, data, 13);
  assert.equal(ctx.getError(), ctx.INVALID_VALUE, 'srcOffset past the end');
  ctx.compressedTexImage2D(ctx.TEXTURE_2D, 0, s3tc.COMPRESSED_RGB_S3TC_DXT1_EXT, 4, 4, 0, data, 4);
  assert.equal(ctx.getError(), ctx.NO_ERROR);
  // The same block from a PIXEL_UNPACK_BUFFER: (imageSize, offset).
  const pbo = ctx.createBuffer();
  ctx.bindBuffer(ctx.PIXEL_UNPACK_BUFFER, pbo);
  ctx.bufferData(ctx.PIXEL_UNPACK_BUFFER, data, ctx.STATIC_DRAW);
  ctx.compressedTexSubImage2D(ctx.TEXTURE_2D, 0, 0, 0, 4, 4, s3tc.COMPRESSED_RGB_S3TC_DXT1_EXT, 8, 4);
  assert.equal(ctx.getError(), ctx.NO_ERROR);
  ctx.compressedTexSubImage2D(ctx.TEXTURE_2D, 0, 0, 0, 4, 4, s3tc.COMPRESSED_RGB_S3TC_DXT1_EXT, 8, 5);
  assert.equal(ctx.getError(), ctx.INVALID_OPERATION, 'past the buffer');
  ctx.bindBuffer(ctx.PIXEL_UNPACK_BUFFER, null);
  ctx.texParameteri(ctx.TEXTURE_2D, ctx.TEXTURE_MIN_FILTER, ctx.NEAREST);
  const p = program(
    ctx,
    '#version 300 es\nin vec2 a; void main() { gl_Position = vec4(a, 0.0, 1.0); }',
    '#version 300 es\nprecision mediump float; uniform sampler2D t; out vec4 c; void main() { c = texture(t, vec2(0.5)); }',
  );
  ctx.useProgram(p);
  const b = ctx.createBuffer();
  ctx.bindBuffer(ctx.ARRAY_BUFFER, b);
  ctx.bufferData(ctx.ARRAY_BUFFER, new Float32Array([-1, -1, 3, -1, -1, 3]), ctx.STATIC_DRAW);
  ctx.enableVertexAttribArray(0);
  ctx.vertexAttribPointer(0, 2, ctx.FLOAT, false, 0, 0);
  ctx.drawArrays(ctx.TRIANGLES, 0, 3);
  const px = new Uint8Array(4);
  ctx.readPixels(0, 0, 1, 1, ctx.RGBA, ctx.UNSIGNED_BYTE, px);
  assert.deepEqual([...px], [255, 0, 0, 255]);
  ctx.destroy();
});

test('WEBGL_debug_shaders and WEBGL_clip_cull_distance: methods, constants, switches', () => {
  const ctx = createContext(4, 4);
  const dbg = ctx.getExtension('WEBGL_debug_shaders');
  const s = ctx.createShader(ctx.FRAGMENT_SHADER);
  assert.equal(dbg.getTranslatedShaderSource(s), '');
  ctx.shaderSource(s, 'precision mediump float; void main() { gl_FragColor = gl_FragCoord; }');
  assert.equal(dbg.getTranslatedShaderSource(s), '', 'not compiled yet');
  ctx.compileShader(s);
  const text = dbg.getTranslatedShaderSource(s);
  assert.match(text, /@fragment/);
  assert.match(text, /gl_FragCoord/);
  assert.throws(() => dbg.getTranslatedShaderSource(null), TypeError);
  assert.throws(() => dbg.getTranslatedShaderSource({}), TypeError);
  const clip = ctx.getExtension('WEBGL_clip_cull_distance');
  if (clip !== null) {
    assert.equal(clip.CLIP_DISTANCE3_WEBGL, 0x3003);
    assert.equal(ctx.getParameter(clip.MAX_CLIP_DISTANCES_WEBGL), 8);
    assert.equal(ctx.getParameter(clip.MAX_CULL_DISTANCES_WEBGL), 0);
    ctx.enable(clip.CLIP_DISTANCE3_WEBGL);
    assert.equal(ctx.isEnabled(clip.CLIP_DISTANCE3_WEBGL), true);
    assert.equal(ctx.getError(), ctx.NO_ERROR);
  }
  ctx.destroy();
});

test('WEBGL_multi_draw: lists as arrays or shared Int32Arrays, gl_DrawID per draw, TypeErrors and GL errors', () => {
  for (const version of [1, 2]) {
    const ctx = createContext(8, 2, {}, { version });
    const ext = ctx.getExtension('WEBGL_multi_draw');
    assert.equal(ext.multiDrawArraysWEBGL.name, 'multiDrawArraysWEBGL');
    const p = program(ctx, `#extension GL_ANGLE_multi_draw : require
attribute vec2 p;
varying float v;
void main() { v = float(gl_DrawID) / 3.0; gl_Position = vec4(p, 0.0, 1.0); }`,
    'precision mediump float; varying float v; void main() { gl_FragColor = vec4(v, 0.0, 0.0, 1.0); }');
    ctx.useProgram(p);
    // Four strips across the canvas, 6 vertices each.
    const strips = [];
    for (let i = 0; i < 4; i++) {
      const [a, b] = [-1 + 0.5 * i, -0.5 + 0.5 * i];
      strips.push(a, -1, b, -1, b, 1, a, -1, b, 1, a, 1);
    }
    ctx.bindBuffer(ctx.ARRAY_BUFFER, ctx.createBuffer());
    ctx.bufferData(ctx.ARRAY_BUFFER, new Float32Array(strips), ctx.STATIC_DRAW);
    ctx.enableVertexAttribArray(0);
    ctx.vertexAttribPointer(0, 2, ctx.FLOAT, false, 0, 0);
    // Strips 3, 2, 1, 0 as draws 0..3; the firsts from shared memory at offset 1.
    const firsts = new Int32Array(new SharedArrayBuffer(20));
    firsts.set([-1, 18, 12, 6, 0]);
    ext.multiDrawArraysWEBGL(ctx.TRIANGLES, firsts, 1, [6, 6, 6, 6], 0, 4);
    assert.equal(ctx.getError(), ctx.NO_ERROR);
    const px = new Uint8Array(8 * 2 * 4);
    ctx.readPixels(0, 0, 8, 2, ctx.RGBA, ctx.UNSIGNED_BYTE, px);
    assert.deepEqual([0, 2, 4, 6].map((x) => px[x * 4]), [255, 170, 85, 0], `WebGL ${version}`);
    assert.throws(() => ext.multiDrawArraysWEBGL(ctx.TRIANGLES, 5, 0, [6], 0, 1), TypeError);
    assert.throws(() => ext.multiDrawArraysWEBGL(ctx.TRIANGLES, [0], 0, [6], 0), TypeError);
    ext.multiDrawArraysWEBGL(ctx.TRIANGLES, [0], 0, [6], 0, -1);
    assert.equal(ctx.getError(), ctx.INVALID_VALUE);
    ext.multiDrawElementsWEBGL(ctx.TRIANGLES, [3], 1, ctx.UNSIGNED_SHORT, [0], 0, 1);
    assert.equal(ctx.getError(), ctx.INVALID_OPERATION);
    ctx.destroy();
  }
});

test('WEBGL_lose_context: calls do nothing, getError says CONTEXT_LOST_WEBGL once, events, restore', async () => {
  const ctx = createContext(8, 8);
  const canvas = ctx.canvas;
  const b = ctx.createBuffer();
  const p = ctx.createProgram();
  const ext = ctx.getExtension('WEBGL_lose_context');
  const events = [];
  canvas.addEventListener('webglcontextlost', (e) => {
    events.push(e.type);
    e.preventDefault();
  });
  const restored = new Promise((resolve) => canvas.addEventListener('webglcontextrestored', resolve));
  ext.loseContext();
  assert.equal(ctx.isContextLost(), true);
  assert.equal(ctx.getError(), ctx.CONTEXT_LOST_WEBGL);
  assert.equal(ctx.getError(), ctx.NO_ERROR);
  assert.equal(ctx.createBuffer(), null);
  assert.equal(ctx.isBuffer(b), false);
  assert.equal(ctx.getParameter(ctx.VIEWPORT), null);
  assert.equal(ctx.checkFramebufferStatus(ctx.FRAMEBUFFER), ctx.FRAMEBUFFER_UNSUPPORTED);
  assert.equal(ctx.getAttribLocation(p, 'x'), -1);
  assert.throws(() => ctx.bindBuffer(ctx.ARRAY_BUFFER, {}), TypeError);
  await new Promise((r) => setTimeout(r, 10));
  assert.deepEqual(events, ['webglcontextlost']);
  ext.restoreContext();
  await restored;
  assert.equal(ctx.isContextLost(), false);
  assert.equal(ctx.isBuffer(b), false);
  ctx.bindBuffer(ctx.ARRAY_BUFFER, b);
  assert.equal(ctx.getError(), ctx.INVALID_OPERATION);
  const b2 = ctx.createBuffer();
  assert.ok(b2 instanceof WebGLBuffer);
  ctx.destroy();
});

test('destroy frees the context at once and leaves it lost for good', () => {
  const ctx = createContext(8, 8);
  ctx.destroy();
  assert.equal(ctx.destroyed, true);
  assert.equal(ctx.isContextLost(), true);
  assert.equal(ctx.drawingBufferWidth, 0);
  assert.equal(ctx.createTexture(), null);
  assert.equal(ctx.toPNG(), null);
  ctx.clear(ctx.COLOR_BUFFER_BIT);
});

test('resize and a canvas size change give the drawing buffer a new size', () => {
  const ctx = createContext(8, 8);
  ctx.canvas.width = 32;
  assert.equal(ctx.drawingBufferWidth, 32);
  ctx.resize(10, 20);
  assert.equal(ctx.drawingBufferWidth, 10);
  assert.equal(ctx.drawingBufferHeight, 20);
  assert.equal(ctx.canvas.height, 20);
  ctx.destroy();
});

test('a WebGL 1 context has WebGL 1 methods only and compiles GLSL ES 1.00 only', () => {
  const ctx = createContext(8, 8, {}, { version: 1 });
  assert.ok(ctx instanceof WebGLRenderingContext);
  assert.equal(ctx.createVertexArray, undefined);
  assert.equal(ctx.TEXTURE_3D, undefined);
  assert.match(ctx.getParameter(ctx.VERSION), /^WebGL 1\.0/);
  const s = ctx.createShader(ctx.FRAGMENT_SHADER);
  ctx.shaderSource(s, '#version 300 es\nprecision mediump float; out vec4 o; void main() { o = vec4(1); }');
  ctx.compileShader(s);
  assert.equal(ctx.getShaderParameter(s, ctx.COMPILE_STATUS), false);
  ctx.destroy();
});

test('a WebGL 1 context takes HALF_FLOAT_OES from a Uint16Array once OES_texture_half_float is on', () => {
  const ctx = createContext(8, 8, {}, { version: 1 });
  const t = ctx.createTexture();
  ctx.bindTexture(ctx.TEXTURE_2D, t);
  const half = new Uint16Array(4).fill(0x3c00);
  ctx.texImage2D(ctx.TEXTURE_2D, 0, ctx.RGBA, 1, 1, 0, ctx.RGBA, 0x8d61, half);
  assert.equal(ctx.getError(), ctx.INVALID_ENUM);
  const ext = ctx.getExtension('OES_texture_half_float');
  assert.equal(ext.HALF_FLOAT_OES, 0x8d61);
  ctx.texImage2D(ctx.TEXTURE_2D, 0, ctx.RGBA, 1, 1, 0, ctx.RGBA, ext.HALF_FLOAT_OES, half);
  assert.equal(ctx.getError(), ctx.NO_ERROR);
  ctx.texImage2D(ctx.TEXTURE_2D, 0, ctx.RGBA, 1, 1, 0, ctx.RGBA, ext.HALF_FLOAT_OES, null);
  assert.equal(ctx.getError(), ctx.NO_ERROR);
  assert.equal(ctx.getExtension('WEBGL_color_buffer_float').RGBA32F_EXT, 0x8814);
  ctx.destroy();
});

test('a canvas in a document is cleared when the task that drew returns, unless preserveDrawingBuffer; an offscreen one is not', async () => {
  const { JSDOM } = await import('jsdom');
  const dom = new JSDOM('<!doctype html><body></body>', { runScripts: 'outside-only' });
  installInWindow(dom.window);
  const doc = dom.window.document;
  const make = (attached, preserve) => {
    const canvas = doc.createElement('canvas');
    canvas.width = canvas.height = 4;
    if (attached) doc.body.appendChild(canvas);
    const ctx = canvas.getContext('webgl2', { preserveDrawingBuffer: preserve });
    ctx.clearColor(1, 1, 1, 1);
    ctx.clear(ctx.COLOR_BUFFER_BIT);
    return ctx;
  };
  const shown = make(true, false);
  const kept = make(true, true);
  const offscreen = make(false, false);
  assert.ok(shown instanceof dom.window.WebGL2RenderingContext);
  await new Promise((r) => setTimeout(r, 5));
  const read = (ctx) => {
    const px = new Uint8Array(4);
    ctx.readPixels(0, 0, 1, 1, ctx.RGBA, ctx.UNSIGNED_BYTE, px);
    return [...px];
  };
  assert.deepEqual(read(shown), [0, 0, 0, 0]);
  assert.deepEqual(read(kept), [255, 255, 255, 255]);
  assert.deepEqual(read(offscreen), [255, 255, 255, 255]);
  // Values cross into the page's realm: its Int32Array and TypeError.
  assert.ok(shown.getParameter(shown.VIEWPORT) instanceof dom.window.Int32Array);
  assert.throws(() => shown.bindBuffer(shown.ARRAY_BUFFER, {}), dom.window.TypeError);
  for (const c of [shown, kept, offscreen]) c.destroy();
  dom.window.close();
});

// jsdom's 2D canvas comes from the `canvas` package, whose addon is fetched prebuilt or compiled
// (scripts/test-gl-node.sh removes it where neither works): without it, the test below leaves
// out its 2D part and says so.
let canvas2d = true;
try {
  await import('canvas');
} catch {
  canvas2d = false;
}

test('a WebGL canvas in a document reads back: toDataURL, toBlob, drawImage and texImage2D from it', async (t) => {
  const { JSDOM } = await import('jsdom');
  const dom = new JSDOM('<!doctype html><body></body>', { runScripts: 'outside-only' });
  installInWindow(dom.window);
  const doc = dom.window.document;
  const source = doc.createElement('canvas');
  source.width = 2;
  source.height = 2;
  const a = source.getContext('webgl2', { preserveDrawingBuffer: true });
  a.clearColor(0, 1, 0, 1);
  a.clear(a.COLOR_BUFFER_BIT);
  const url = source.toDataURL();
  assert.ok(url.startsWith('data:image/png;base64,'));
  assert.deepEqual([...Buffer.from(url.slice(22), 'base64').subarray(1, 4)], [0x50, 0x4e, 0x47]);
  const blob = await new Promise((r) => source.toBlob(r));
  assert.equal(blob.type, 'image/png');
  // A 2D context draws it, scaled too.
  if (canvas2d) {
    const flat = doc.createElement('canvas');
    flat.width = 4;
    flat.height = 4;
    const c2 = flat.getContext('2d');
    c2.drawImage(source, 0, 0, 4, 4);
    assert.deepEqual([...c2.getImageData(3, 3, 1, 1).data], [0, 255, 0, 255]);
  } else {
    t.diagnostic('drawImage into a 2D canvas not tested: the canvas package is not installed or did not build');
  }
  const b = doc.createElement('canvas').getContext('webgl2');
  const tex = b.createTexture();
  b.bindTexture(b.TEXTURE_2D, tex);
  b.texImage2D(b.TEXTURE_2D, 0, b.RGBA, b.RGBA, b.UNSIGNED_BYTE, source);
  assert.equal(b.getError(), b.NO_ERROR);
  b.bindFramebuffer(b.FRAMEBUFFER, b.createFramebuffer());
  b.framebufferTexture2D(b.FRAMEBUFFER, b.COLOR_ATTACHMENT0, b.TEXTURE_2D, tex, 0);
  const px = new Uint8Array(4);
  b.readPixels(1, 1, 1, 1, b.RGBA, b.UNSIGNED_BYTE, px);
  assert.deepEqual([...px], [0, 255, 0, 255]);
  a.destroy();
  b.destroy();
  dom.window.close();
});

const noCanvas = canvas2d ? false : 'jsdom decodes images with the canvas package, which is not installed or did not build';

test('without the canvas package, decoding an image in jsdom rejects rather than waits', { skip: canvas2d && 'the canvas package is installed' }, async () => {
  const { JSDOM } = await import('jsdom');
  const dom = new JSDOM('<!doctype html><body></body>', { runScripts: 'outside-only', resources: 'usable' });
  const w = dom.window;
  installInWindow(w);
  const source = w.document.createElement('canvas');
  source.getContext('webgl2', { preserveDrawingBuffer: true }).clear(0x4000);
  const img = new w.Image();
  img.src = source.toDataURL();
  await assert.rejects(img.decode(), { name: 'EncodingError', message: /`canvas` package/ });
  const blob = await new Promise((r) => source.toBlob(r));
  await assert.rejects(w.createImageBitmap(blob), { name: 'EncodingError', message: /`canvas` package/ });
  w.close();
});

test('createImageBitmap and image.decode in a document: blobs, images, flipY, crops, no pixel store', { skip: noCanvas }, async () => {
  const { JSDOM } = await import('jsdom');
  const dom = new JSDOM('<!doctype html><body></body>', { runScripts: 'outside-only', resources: 'usable' });
  const w = dom.window;
  installInWindow(w);
  const doc = w.document;
  // A 1 × 2 PNG: red on top, blue below, made by a WebGL canvas.
  const source = doc.createElement('canvas');
  source.width = 1;
  source.height = 2;
  const a = source.getContext('webgl2', { preserveDrawingBuffer: true });
  a.enable(a.SCISSOR_TEST);
  for (const [y, rgb] of [[1, [1, 0, 0]], [0, [0, 0, 1]]]) {
    a.scissor(0, y, 1, 1);
    a.clearColor(...rgb, 1);
    a.clear(a.COLOR_BUFFER_BIT);
  }
  const blob = await new Promise((r) => source.toBlob(r));
  const gl = doc.createElement('canvas').getContext('webgl2');
  const tex = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, tex);
  gl.bindFramebuffer(gl.FRAMEBUFFER, gl.createFramebuffer());
  /** The uploaded texture's texels, row 0 first. */
  const upload = (src) => {
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA, gl.RGBA, gl.UNSIGNED_BYTE, src);
    assert.equal(gl.getError(), gl.NO_ERROR);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, tex, 0);
    const px = new Uint8Array(src.width * src.height * 4);
    gl.readPixels(0, 0, src.width, src.height, gl.RGBA, gl.UNSIGNED_BYTE, px);
    return [...px];
  };
  const RED = [255, 0, 0, 255], BLUE = [0, 0, 255, 255];
  const bitmap = await w.createImageBitmap(blob);
  assert.ok(bitmap instanceof w.ImageBitmap);
  assert.deepEqual([bitmap.width, bitmap.height], [1, 2]);
  // The image's first row is row 0; UNPACK_FLIP_Y_WEBGL does not apply to a bitmap.
  gl.pixelStorei(gl.UNPACK_FLIP_Y_WEBGL, true);
  assert.deepEqual(upload(bitmap), [...RED, ...BLUE]);
  gl.pixelStorei(gl.UNPACK_FLIP_Y_WEBGL, false);
  assert.deepEqual(upload(await w.createImageBitmap(blob, { imageOrientation: 'flipY' })), [...BLUE, ...RED]);
  assert.deepEqual(upload(await w.createImageBitmap(bitmap, 0, 1, 1, 1)), BLUE);
  const img = new w.Image();
  img.src = `data:image/png;base64,${Buffer.from(await blob.arrayBuffer()).toString('base64')}`;
  await img.decode();
  assert.deepEqual(upload(img), [...RED, ...BLUE]);
  bitmap.close();
  assert.equal(bitmap.width, 0);
  await assert.rejects(w.createImageBitmap(bitmap), { name: 'InvalidStateError' });
  await assert.rejects(w.createImageBitmap(42), TypeError);
  const broken = new w.Image();
  broken.src = 'data:image/png;base64,AAAA';
  await assert.rejects(broken.decode(), { name: 'EncodingError' });
  a.destroy();
  gl.destroy();
  w.close();
});

test('ImageData in a document without one: both constructors, the DOM checks, uploads', async () => {
  const { JSDOM } = await import('jsdom');
  const dom = new JSDOM('<!doctype html><body></body>', { runScripts: 'outside-only' });
  const w = dom.window;
  installInWindow(w);
  assert.equal(typeof w.ImageData, 'function');
  // Pixels made in the page's realm, as a page script makes them.
  const data = w.eval('new Uint8ClampedArray([255, 0, 0, 255, 0, 0, 255, 255])');
  const image = new w.ImageData(data, 1);
  assert.deepEqual([image.width, image.height, image.colorSpace], [1, 2, 'srgb']);
  assert.equal(new w.ImageData(3, 2).data.length, 24);
  assert.throws(() => new w.ImageData(data, 3), RangeError);
  assert.throws(() => new w.ImageData(data, 1, 3), RangeError);
  assert.throws(() => new w.ImageData(0, 2), RangeError);
  assert.throws(() => new w.ImageData('pixels', 1), TypeError);
  const gl = w.document.createElement('canvas').getContext('webgl2');
  gl.bindTexture(gl.TEXTURE_2D, gl.createTexture());
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA, gl.RGBA, gl.UNSIGNED_BYTE, image);
  assert.equal(gl.getError(), gl.NO_ERROR);
  gl.bindFramebuffer(gl.FRAMEBUFFER, gl.createFramebuffer());
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, gl.getParameter(gl.TEXTURE_BINDING_2D), 0);
  const px = new Uint8Array(8);
  gl.readPixels(0, 0, 1, 2, gl.RGBA, gl.UNSIGNED_BYTE, px);
  assert.deepEqual([...px], [255, 0, 0, 255, 0, 0, 255, 255]);
  gl.destroy();
  w.close();
});

test('PNG images upload their colour as the file holds it, nearly transparent pixels too', { skip: noCanvas }, async () => {
  const { JSDOM } = await import('jsdom');
  const dom = new JSDOM('<!doctype html><body></body>', { runScripts: 'outside-only', resources: 'usable' });
  const w = dom.window;
  installInWindow(w);
  const source = w.document.createElement('canvas');
  source.width = 1;
  source.height = 1;
  const a = source.getContext('webgl2', { premultipliedAlpha: false, preserveDrawingBuffer: true });
  a.clearColor(1, 192 / 255, 128 / 255, 1 / 255);
  a.clear(a.COLOR_BUFFER_BIT);
  const img = new w.Image();
  img.src = source.toDataURL();
  await img.decode();
  const gl = w.document.createElement('canvas').getContext('webgl2');
  const tex = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, tex);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA, gl.RGBA, gl.UNSIGNED_BYTE, img);
  assert.equal(gl.getError(), gl.NO_ERROR);
  gl.bindFramebuffer(gl.FRAMEBUFFER, gl.createFramebuffer());
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, tex, 0);
  const px = new Uint8Array(4);
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
  // A 2D canvas keeps premultiplied colour and would give 255, 255, 255, 1.
  assert.deepEqual([...px], [255, 192, 128, 1]);
  a.destroy();
  gl.destroy();
  w.close();
});

test('a canvas larger than the device allows gets a drawing buffer as large as it allows', () => {
  const small = createContext(1, 1);
  const max = small.getParameter(small.MAX_TEXTURE_SIZE);
  small.destroy();
  const gl = createContext(max + 32, 8);
  assert.deepEqual([gl.drawingBufferWidth, gl.drawingBufferHeight], [max, 8]);
  gl.canvas.width = 8;
  gl.canvas.height = max + 32;
  assert.deepEqual([gl.drawingBufferWidth, gl.drawingBufferHeight], [8, max]);
  assert.equal(gl.getError(), gl.NO_ERROR);
  gl.destroy();
});
