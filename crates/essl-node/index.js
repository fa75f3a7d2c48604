// essl for JavaScript: check WebGL shaders as a browser compiles them, link them, translate
// them, and run the `essl` command. The work is done by the native addon (crates/essl-node,
// the same checking pipeline as `essl lint`); this file checks arguments and shapes results.
import * as os from 'node:os';
import {native} from './lib/native.js';

const STAGES = new Set(['vertex', 'fragment']);

function kind(value) {
  if (value === null) return 'null';
  if (Array.isArray(value)) return 'an array';
  const t = typeof value;
  return t === 'object' ? 'an object' : /^[aeiou]/.test(t) ? `an ${t}` : `a ${t}`;
}

function text(fn, name, value) {
  if (typeof value !== 'string') {
    throw new TypeError(`essl.${fn}: ${name} must be a string, not ${kind(value)}`);
  }
  return value;
}

function opts(fn, value) {
  if (value === undefined || value === null) return {};
  if (typeof value !== 'object' || Array.isArray(value)) {
    throw new TypeError(`essl.${fn}: options must be an object, not ${kind(value)}`);
  }
  value = {...value};
  if (value.stage !== undefined && !STAGES.has(value.stage)) {
    throw new TypeError(`essl.${fn}: options.stage must be 'vertex' or 'fragment', not ${JSON.stringify(value.stage)}`);
  }
  // A define's value as JSON carries it: a string, a finite number or a boolean.
  if (value.defines !== null && typeof value.defines === 'object' && !Array.isArray(value.defines)) {
    for (const [name, v] of Object.entries(value.defines)) {
      const ok = typeof v === 'string' || typeof v === 'boolean' || (typeof v === 'number' && Number.isFinite(v));
      if (!ok) {
        throw new TypeError(
          `essl.${fn}: options.defines.${name} must be a string, a finite number or a boolean, not ${typeof v === 'number' ? String(v) : kind(v)}`,
        );
      }
    }
  }
  return value;
}

// `link` and `translate` take two texts: a `filename` or `stage` would name both.
function pairOptions(fn, options) {
  const o = opts(fn, options);
  for (const key of ['filename', 'stage']) {
    if (o[key] !== undefined) {
      const instead = fn === 'link' ? 'use options.vertexFilename and options.fragmentFilename' : 'the first text is the vertex shader, the second the fragment shader';
      throw new TypeError(`essl.${fn}: options.${key} would name both shaders; ${instead}`);
    }
  }
  return o;
}

// A diagnostic's `rendered` (its rustc-style text) is written when it is first read: the
// addon answers its index among the answer's diagnostics, and the getter asks for the text.
// The key keeps its place among the diagnostic's keys.
function lazyRendered(diagnostics, rendering) {
  for (const d of diagnostics) {
    const index = d.rendered;
    if (typeof index !== 'number') continue;
    Object.defineProperty(d, 'rendered', {
      enumerable: true,
      configurable: true,
      get() {
        const value = native.render(rendering, index);
        Object.defineProperty(this, 'rendered', {value, enumerable: true, configurable: true, writable: true});
        return value;
      },
      set(value) {
        Object.defineProperty(this, 'rendered', {value, enumerable: true, configurable: true, writable: true});
      },
    });
  }
}

// The result of an answer: its JSON parsed, each diagnostic's `rendered` a getter.
function answered(answer) {
  if (typeof answer === 'string') return JSON.parse(answer);
  const r = JSON.parse(answer.json);
  const shaders = r.shaders ?? [r.vertex, r.fragment];
  const programs = r.programs ?? [r.program];
  for (const x of [...shaders, ...programs]) lazyRendered(x.diagnostics, answer.rendering);
  return r;
}

// Calls the addon, rethrowing its argument errors as TypeErrors with the function's name.
function call(fn, f) {
  try {
    return answered(f());
  } catch (e) {
    if (e instanceof SyntaxError) throw new Error(`essl.${fn}: the addon answered what is not JSON`);
    // The pipeline's messages name the command line's flags; here they are options.
    const said = String(e.message)
      .replace(/^essl: /, '')
      .replace('pass `--stage vertex` or `--stage fragment`', "pass options.stage ('vertex' or 'fragment')");
    const message = `essl.${fn}: ${said}`;
    throw e.code === 'InvalidArg' ? new TypeError(message) : new Error(message);
  }
}

/** Every diagnostic of a result (shaders first, then programs). */
function all(result) {
  return [
    ...result.shaders.flatMap(s => s.diagnostics),
    ...result.programs.flatMap(p => p.diagnostics),
  ];
}

function checkOptions(fn, source, options) {
  text(fn, 'source', source);
  const o = opts(fn, options);
  if (o.filename === undefined && o.stage) o.filename = o.stage === 'vertex' ? 'shader.vert' : 'shader.frag';
  return JSON.stringify(o);
}

// The addon answers `text: 1` for a shader whose text is the source as passed (no
// `#include` expanded), rather than sending the same string back.
function given(shader, source) {
  if (shader.text === 1) shader.text = source;
  return shader;
}

function checked(result, source) {
  if (result.shaders.length) given(result.shaders[0], source);
  result.diagnostics = all(result);
  result.ok = result.errors === 0;
  return result;
}

export function check(source, options) {
  const o = checkOptions('check', source, options);
  return checked(call('check', () => native.checkJson(source, o)), source);
}

// `checkAsync`'s queue. The checks asked for while others run go to the addon together, a
// batch at a time on each of LANES threads of Node's pool: one trip through the pool per batch
// rather than per check, and the pool's other threads (and a core) left to the program's own
// work — a bundler's reads and writes, which wait behind whatever the pool holds. A bundler
// transforms its modules a few at a time, and each batch takes those that arrived while the
// last one ran (docs/performance.md, "What the Vite plugin adds to a build").
const LANES = Math.max(1, Math.min(4, (os.availableParallelism?.() ?? os.cpus().length) - 1));
const waiting = [];
let running = 0;
let pumping = false;

function queued(source, o) {
  return new Promise((resolve, reject) => {
    waiting.push({source, o, resolve, reject});
    // The calls of one turn of the event loop (a `Promise.all` of many) go in one batch.
    if (!pumping) {
      pumping = true;
      queueMicrotask(pump);
    }
  });
}

function pump() {
  pumping = false;
  while (running < LANES && waiting.length) {
    const batch = waiting.splice(0, Math.ceil(waiting.length / (LANES - running)));
    running++;
    let answers;
    try {
      answers = native.checkJsonBatchAsync(
        batch.map(b => b.source),
        batch.map(b => b.o),
      );
    } catch (e) {
      answers = Promise.reject(e);
    }
    answers
      .then(
        all => all.forEach((answer, i) => settle(batch[i], answer)),
        e => batch.forEach(b => settle(b, {invalidArg: e?.code === 'InvalidArg', message: String(e?.message ?? e)})),
      )
      .finally(() => {
        running--;
        pump();
      });
  }
}

// A batch's answer for one check: its result, or the error `checkAsync` throws.
function settle({source, resolve, reject}, answer) {
  const failed = answer !== null && typeof answer === 'object' && 'invalidArg' in answer;
  try {
    resolve(
      checked(
        call('checkAsync', () => {
          if (!failed) return answer;
          const e = new Error(answer.message);
          if (answer.invalidArg) e.code = 'InvalidArg';
          throw e;
        }),
        source,
      ),
    );
  } catch (e) {
    reject(e);
  }
}

export async function checkAsync(source, options) {
  return queued(source, checkOptions('checkAsync', source, options));
}

function minifyOptions(fn, source, options) {
  text(fn, 'source', source);
  const {rename = true, ...o} = opts(fn, options);
  if (typeof rename !== 'boolean') throw new TypeError(`essl.${fn}: options.rename must be a boolean, not ${kind(rename)}`);
  if (o.filename === undefined && o.stage) o.filename = o.stage === 'vertex' ? 'shader.vert' : 'shader.frag';
  return [JSON.stringify(o), rename];
}

export function minify(source, options) {
  const [o, rename] = minifyOptions('minify', source, options);
  return checked(call('minify', () => native.minifyJson(source, o, rename)), source);
}

export async function minifyAsync(source, options) {
  const [o, rename] = minifyOptions('minifyAsync', source, options);
  let json;
  try {
    json = await native.minifyJsonAsync(source, o, rename);
  } catch (e) {
    return call('minifyAsync', () => {
      throw e;
    });
  }
  return checked(call('minifyAsync', () => json), source);
}

export function link(vertex, fragment, options) {
  text('link', 'vertex', vertex);
  text('link', 'fragment', fragment);
  const o = pairOptions('link', options);
  const {vertexFilename, fragmentFilename, ...rest} = o;
  const v = {...rest, ...(vertexFilename ? {filename: vertexFilename} : {})};
  const f = {...rest, ...(fragmentFilename ? {filename: fragmentFilename} : {})};
  const r = call('link', () => native.linkJson(vertex, fragment, JSON.stringify(v), JSON.stringify(f)));
  return {
    ...r.program,
    vertex: given(r.vertex, vertex),
    fragment: given(r.fragment, fragment),
    diagnostics: [...r.vertex.diagnostics, ...r.fragment.diagnostics, ...r.program.diagnostics],
  };
}

export function translate(vertex, fragment, options) {
  text('translate', 'vertex', vertex);
  text('translate', 'fragment', fragment);
  const {to = 'wgsl', ...rest} = pairOptions('translate', options);
  if (typeof to !== 'string') throw new TypeError(`essl.translate: options.to must be a string, not ${kind(to)}`);
  const r = call('translate', () => native.translateJson(vertex, fragment, to, JSON.stringify(rest)));
  if (to === 'spirv') {
    r.vertex = Uint32Array.from(r.vertex);
    r.fragment = Uint32Array.from(r.fragment);
  }
  return r;
}

export function format(diagnostics) {
  const list = Array.isArray(diagnostics)
    ? diagnostics
    : diagnostics && Array.isArray(diagnostics.diagnostics)
      ? diagnostics.diagnostics
      : null;
  if (!list || list.some(d => d === null || typeof d !== 'object' || typeof d.rendered !== 'string')) {
    throw new TypeError(`essl.format: expected diagnostics or a result, not ${kind(diagnostics)}`);
  }
  return list.map(d => d.rendered).join('\n');
}

export function runCli(args) {
  if (!Array.isArray(args) || args.some(a => typeof a !== 'string')) {
    throw new TypeError('essl.runCli: args must be an array of strings');
  }
  return native.runCli(args);
}
