#!/usr/bin/env node
// Writes lib/generated.js from the WebGL IDL (the Khronos `webgl.idl` and `webgl2.idl`):
// every constant, and one method per operation that is not overloaded, converting its
// arguments as WebIDL does and calling the native context. The overloaded operations and the
// few that need more than a conversion (`getExtension`, `isContextLost`, …) are written by
// hand in lib/overloads.js; this script checks that every operation of the IDL is one or the
// other.
//
//   node scripts/generate.mjs [IDL_DIR]     (default: the shared/specs folder beside the repository)
import { readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const idlDir = process.argv[2] ?? join(here, '../../../../shared/specs');
const out = join(here, '../lib/generated.js');
const outTypes = join(here, '../lib/generated.d.ts');

/** The operations written by hand in lib/overloads.js. */
export const HANDWRITTEN = new Set([
  'bufferData', 'bufferSubData', 'getBufferSubData',
  'texImage2D', 'texSubImage2D', 'texImage3D', 'texSubImage3D',
  'compressedTexImage2D', 'compressedTexSubImage2D', 'compressedTexImage3D', 'compressedTexSubImage3D',
  'readPixels',
  'uniform1fv', 'uniform2fv', 'uniform3fv', 'uniform4fv',
  'uniform1iv', 'uniform2iv', 'uniform3iv', 'uniform4iv',
  'uniform1uiv', 'uniform2uiv', 'uniform3uiv', 'uniform4uiv',
  'uniformMatrix2fv', 'uniformMatrix3fv', 'uniformMatrix4fv',
  'uniformMatrix2x3fv', 'uniformMatrix2x4fv', 'uniformMatrix3x2fv',
  'uniformMatrix3x4fv', 'uniformMatrix4x2fv', 'uniformMatrix4x3fv',
  'vertexAttrib1f', 'vertexAttrib2f', 'vertexAttrib3f',
  'vertexAttrib1fv', 'vertexAttrib2fv', 'vertexAttrib3fv', 'vertexAttrib4fv',
  'clearBufferfv', 'clearBufferiv', 'clearBufferuiv',
  'getExtension', 'getSupportedExtensions', 'getContextAttributes', 'isContextLost',
  'getError', 'makeXRCompatible',
]);

/** Operations and constants of an IDL interface mixin, in order. */
function parseMixin(text, name) {
  const start = text.indexOf(`interface mixin ${name}`);
  if (start < 0) throw new Error(`no mixin ${name}`);
  const open = text.indexOf('{', start);
  const close = text.indexOf('\n};', open);
  const body = text
    .slice(open + 1, close)
    .replace(/\/\*[\s\S]*?\*\//g, '')
    .replace(/\/\/[^\n]*/g, '');
  const constants = [];
  const operations = [];
  const attributes = [];
  for (let stmt of body.split(';')) {
    stmt = stmt.replace(/\s+/g, ' ').trim();
    if (!stmt) continue;
    let m = /^const [\w ]+ (\w+) = (0x[0-9A-Fa-f]+|-?\d+)$/.exec(stmt);
    if (m) {
      constants.push([m[1], Number(m[2])]);
      continue;
    }
    if (/\battribute\b/.test(stmt)) {
      attributes.push(stmt);
      continue;
    }
    let ext = '';
    m = /^\[([^\]]*)\] (.*)$/.exec(stmt);
    if (m && !stmt.startsWith('[AllowShared]')) {
      ext = m[1];
      stmt = m[2];
    }
    m = /^(.+?) (\w+)\((.*)\)$/.exec(stmt);
    if (!m) throw new Error(`cannot read: ${stmt}`);
    const params = splitParams(m[3]).map(parseParam);
    operations.push({ ret: m[1], name: m[2], params, handlesLoss: ext.includes('WebGLHandlesContextLoss') });
  }
  return { constants, operations, attributes };
}

/** Splits a parameter list at the commas outside `<>` and `()`. */
function splitParams(s) {
  const parts = [];
  let depth = 0;
  let cur = '';
  for (const c of s) {
    if (c === '<' || c === '(') depth++;
    if (c === '>' || c === ')') depth--;
    if (c === ',' && depth === 0) {
      parts.push(cur);
      cur = '';
    } else cur += c;
  }
  if (cur.trim()) parts.push(cur);
  return parts.map((p) => p.trim());
}

function parseParam(p) {
  let optional = false;
  p = p.replace(/\[AllowShared\] /g, '');
  if (p.startsWith('optional ')) {
    optional = true;
    p = p.slice(9);
  }
  let dflt;
  const eq = p.indexOf(' = ');
  if (eq >= 0) {
    dflt = p.slice(eq + 3);
    p = p.slice(0, eq);
  }
  const sp = p.lastIndexOf(' ');
  let type = p.slice(0, sp);
  const name = p.slice(sp + 1);
  let nullable = false;
  if (type.endsWith('?')) {
    nullable = true;
    type = type.slice(0, -1);
  }
  return { type, name, optional, dflt, nullable };
}

const INTERFACES = new Set([
  'WebGLBuffer', 'WebGLFramebuffer', 'WebGLProgram', 'WebGLRenderbuffer', 'WebGLShader',
  'WebGLTexture', 'WebGLUniformLocation', 'WebGLQuery', 'WebGLSampler', 'WebGLSync',
  'WebGLTransformFeedback', 'WebGLVertexArrayObject',
]);

/** The JavaScript expression converting parameter `p` (a local of its name). */
function convert(op, p, i) {
  const v = safe(p.name);
  switch (p.type) {
    case 'GLenum':
    case 'GLuint':
    case 'GLbitfield':
    case 'unsigned long':
      return `u32(${v})`;
    case 'GLint':
    case 'GLsizei':
      return `i32(${v})`;
    case 'GLintptr':
    case 'GLsizeiptr':
    case 'GLint64':
      return `i64(${v})`;
    case 'GLuint64':
    case 'unsigned long long':
      return `u64(${v})`;
    case 'GLfloat':
    case 'GLclampf':
      return `f32(${v})`;
    case 'GLboolean':
      return `bool(${v})`;
    case 'DOMString':
      return `str(${v})`;
    case 'sequence<DOMString>':
      return `strings(${v}, '${op.name}', ${i + 1})`;
    case 'sequence<GLenum>':
    case 'sequence<GLuint>':
      return `u32seq(${v}, '${op.name}', ${i + 1})`;
    case 'Int32List':
      return `i32list(${v}, '${op.name}', ${i + 1})`;
    case 'Uint32List':
      return `u32list(${v}, '${op.name}', ${i + 1})`;
    case 'Float32List':
      return `f32list(${v}, '${op.name}', ${i + 1})`;
    default:
      if (INTERFACES.has(p.type)) {
        return `oid(this, ${v}, ${p.type}, ${p.nullable}, '${op.name}', ${i + 1})`;
      }
      throw new Error(`${op.name}: no conversion for ${p.type}`);
  }
}

/** A parameter name that is not a reserved word. */
function safe(name) {
  return ['function', 'var', 'default'].includes(name) ? `${name}_` : name;
}

/** What a call answers when the context is lost (WebGL 1.0 § 5.15.2 and the IDL). */
function lostValue(op) {
  const special = {
    checkFramebufferStatus: 'FRAMEBUFFER_UNSUPPORTED',
    getAttribLocation: '-1',
    getFragDataLocation: '-1',
    getUniformBlockIndex: '0xFFFFFFFF',
    clientWaitSync: '0x911D',
  };
  if (op.name in special) {
    return special[op.name] === 'FRAMEBUFFER_UNSUPPORTED' ? '0x8CDD' : special[op.name];
  }
  switch (op.ret) {
    case 'undefined':
      return 'undefined';
    case 'GLboolean':
      return 'false';
    case 'GLenum':
    case 'GLint':
    case 'GLuint':
    case 'GLintptr':
      return '0';
    default:
      return 'null';
  }
}

/** The JavaScript expression turning the native answer `r` into the IDL's return type. */
function answer(op, call) {
  const t = op.ret.replace(/\?$/, '');
  if (INTERFACES.has(t)) {
    if (t === 'WebGLUniformLocation' || op.name.startsWith('create') || op.name === 'fenceSync') {
      return `wrapNew(this, ${t}, ${call})`;
    }
    return `answer(this, ${call})`;
  }
  if (t === 'any' || t === 'sequence<WebGLShader>') return `answer(this, ${call})`;
  if (t === 'WebGLActiveInfo') return `activeInfo(${call})`;
  if (t === 'WebGLShaderPrecisionFormat') return `precisionFormat(${call})`;
  return call;
}

function method(op) {
  const params = op.params.map((p) => safe(p.name));
  const required = op.params.filter((p) => !p.optional).length;
  const lines = [];
  lines.push(`  ${op.name}(${params.join(', ')}) {`);
  if (required > 0) {
    lines.push(`    if (arguments.length < ${required}) throw argc('${op.name}', ${required}, arguments.length);`);
  }
  const args = op.params.map((p, i) => convert(op, p, i));
  const n = op.params.length;
  const locals = args.map((a, i) => `a${i}`);
  if (n > 0) lines.push(`    const ${args.map((a, i) => `${locals[i]} = ${a}`).join(', ')};`);
  lines.push(`    const n = this[NATIVE];`);
  lines.push(`    if (n === null) return ${lostValue(op)};`);
  const call = `n.${op.name}(${locals.join(', ')})`;
  if (op.ret === 'undefined') {
    lines.push(`    ${call};`);
  } else {
    lines.push(`    return ${answer(op, call)};`);
  }
  lines.push('  },');
  return lines.join('\n');
}

function emit() {
  const idl1 = readFileSync(join(idlDir, 'webgl1.idl'), 'utf8');
  const idl2 = readFileSync(join(idlDir, 'webgl2.idl'), 'utf8');
  const base1 = parseMixin(idl1, 'WebGLRenderingContextBase');
  const over1 = parseMixin(idl1, 'WebGLRenderingContextOverloads');
  const base2 = parseMixin(idl2, 'WebGL2RenderingContextBase');
  const over2 = parseMixin(idl2, 'WebGL2RenderingContextOverloads');
  const seen = new Set();
  const missing = [];
  const section = (title, ops) => {
    const body = [];
    for (const op of ops) {
      if (HANDWRITTEN.has(op.name) || seen.has(op.name)) continue;
      seen.add(op.name);
      body.push(method(op));
    }
    return `export const ${title} = {\n${body.join('\n')}\n};\n`;
  };
  for (const op of [...over1.operations, ...over2.operations]) {
    if (!HANDWRITTEN.has(op.name)) missing.push(op.name);
  }
  if (missing.length) throw new Error(`overloads not written by hand: ${missing.join(', ')}`);
  const hex = (v) => (v < 0 ? String(v) : `0x${v.toString(16).toUpperCase()}`);
  const consts = (list) => `{\n${list.map(([k, v]) => `  ${k}: ${hex(v)},`).join('\n')}\n}`;
  const names = (ops) => JSON.stringify([...new Set(ops.map((o) => o.name))]);
  const text = `// Generated by scripts/generate.mjs from the WebGL IDL (webgl.idl, webgl2.idl): do not edit.
// One method per operation that is not overloaded: WebIDL's argument conversions, then the
// native call; a lost context answers what WebGL answers for each return type.
/* eslint-disable */
import {
  NATIVE, argc, u32, i32, i64, u64, f32, bool, str, strings, u32seq, i32list, u32list, f32list,
  oid, answer, wrapNew, activeInfo, precisionFormat,
  WebGLBuffer, WebGLFramebuffer, WebGLProgram, WebGLRenderbuffer, WebGLShader, WebGLTexture,
  WebGLUniformLocation, WebGLQuery, WebGLSampler, WebGLSync, WebGLTransformFeedback,
  WebGLVertexArrayObject,
} from './objects.js';

/** The constants of WebGLRenderingContextBase. */
export const CONSTANTS_1 = ${consts(base1.constants)};

/** The constants WebGL2RenderingContextBase adds. */
export const CONSTANTS_2 = ${consts(base2.constants)};

/** Every operation of WebGL 1's context, by name. */
export const OPERATIONS_1 = ${names([...base1.operations, ...over1.operations])};

/** Every operation of WebGL 2's context, by name. */
export const OPERATIONS_2 = ${names([...base1.operations, ...base2.operations, ...over2.operations])};

${section('METHODS_1', base1.operations)}
${section('METHODS_2', base2.operations)}`;
  writeFileSync(out, text);
  console.log(`wrote ${out}: ${seen.size} generated methods`);
  writeFileSync(outTypes, declarations(base1, over1, base2, over2));
  console.log(`wrote ${outTypes}`);
}

/** A TypeScript type for an IDL type; `param` for an argument (sequences as iterables). */
function tsType(t, param) {
  const nullable = t.endsWith('?');
  if (nullable) t = t.slice(0, -1);
  let r;
  const seq = /^sequence<(.+)>$/.exec(t);
  if (seq) {
    const inner = tsType(seq[1], param);
    r = param ? `Iterable<${inner}>` : `${inner}[]`;
  } else if (INTERFACES.has(t) || ['WebGLActiveInfo', 'WebGLShaderPrecisionFormat'].includes(t)) {
    r = t;
  } else {
    r = {
      undefined: 'void',
      any: 'any',
      GLboolean: 'boolean',
      boolean: 'boolean',
      object: 'object',
      'WebGLContextAttributes?': 'WebGLContextAttributes',
      DOMString: 'string',
      Float32List: 'Float32Array | Iterable<number>',
      Int32List: 'Int32Array | Iterable<number>',
      Uint32List: 'Uint32Array | Iterable<number>',
      ArrayBufferView: 'ArrayBufferView',
      AllowSharedBufferSource: 'ArrayBufferView | ArrayBuffer | SharedArrayBuffer',
      TexImageSource: 'TexImageSource',
      WebGLContextAttributes: 'WebGLContextAttributes',
      'Promise<undefined>': 'Promise<void>',
    }[t] ?? (/^(GL\w+|unsigned long( long)?|long)$/.test(t) ? 'number' : null);
    if (r === null) throw new Error(`no TypeScript type for ${t}`);
  }
  return nullable ? `${r} | null` : r;
}

function signature(op) {
  const params = op.params.map((p) => {
    const t = tsType(p.nullable ? `${p.type}?` : p.type, true);
    return `${safe(p.name)}${p.optional ? '?' : ''}: ${t}`;
  });
  return `  ${op.name}(${params.join(', ')}): ${tsType(op.ret, false)};`;
}

function declarations(base1, over1, base2, over2) {
  const block = (name, mixins) => {
    const lines = [];
    for (const m of mixins) {
      for (const [k] of m.constants) lines.push(`  readonly ${k}: number;`);
      for (const op of m.operations) lines.push(signature(op));
    }
    return `export interface ${name} {\n${lines.join('\n')}\n}\n`;
  };
  return `// Generated by scripts/generate.mjs from the WebGL IDL: do not edit.
import type {
  WebGLBuffer, WebGLFramebuffer, WebGLProgram, WebGLRenderbuffer, WebGLShader, WebGLTexture,
  WebGLUniformLocation, WebGLQuery, WebGLSampler, WebGLSync, WebGLTransformFeedback,
  WebGLVertexArrayObject, WebGLActiveInfo, WebGLShaderPrecisionFormat, TexImageSource,
  WebGLContextAttributes,
} from '../index.js';

${block('WebGLRenderingContextBase', [base1])}
${block('WebGLRenderingContextOverloads', [over1])}
${block('WebGL2RenderingContextBase', [base2])}
${block('WebGL2RenderingContextOverloads', [over2])}`;
}

emit();
