// What the Vite/Rollup plugin and the webpack loader share: which modules to check, checking
// one through essl (the addon's one pipeline), and the error a bundler shows.
import {readFileSync} from 'node:fs';
import {checkAsync, format, minifyAsync} from '../index.js';

const SHADER_EXT = 'glsl|vert|frag|vs|fs|vsh|fsh';
const SCRIPT_EXT = 'm?[jt]sx?|c[jt]s';
export const SHADER = new RegExp(`\\.(${SHADER_EXT})$`);
const SCRIPT = new RegExp(`\\.(${SCRIPT_EXT})$`);
/** A module id that may name a shader or a script (its query aside): a bundler's hook filter. */
export const MAYBE_WANTED = new RegExp(`\\.(${SHADER_EXT}|${SCRIPT_EXT})(\\?.*)?$`);
// A script is read only when it may hold a shader: a `glsl` tag or comment (in any case), or
// `#version`; under a preset, every script (three.js's ShaderMaterial shaders carry neither).
const MAY_HOLD = /glsl|#version/i;
const CHECK_KEYS = ['target', 'defines', 'includeDirs', 'preset', 'config', 'rules', 'lints', 'denyWarnings', 'variants'];

const PLUGIN_KEYS = new Set([...CHECK_KEYS, 'include', 'exclude', 'failOnWarnings', 'minify', 'load', 'cache']);

/**
 * The TypeError for the options of a plugin or the loader (`fn` names it), or null: `minify`
 * not a boolean, or an option essl does not know (a typo would pass silently).
 */
export function optionsError(fn, options) {
  if (options.minify !== undefined && typeof options.minify !== 'boolean') {
    return new TypeError(`${fn}: options.minify must be a boolean`);
  }
  if (options.cache !== undefined && typeof options.cache !== 'boolean' && typeof options.cache !== 'string') {
    return new TypeError(`${fn}: options.cache must be a boolean or a folder's path`);
  }
  const unknown = Object.keys(options).filter(k => !PLUGIN_KEYS.has(k));
  if (!unknown.length) return null;
  return new TypeError(`${fn}: unknown option${unknown.length > 1 ? 's' : ''} ${unknown.join(', ')} (known: ${[...PLUGIN_KEYS].join(', ')})`);
}

/** The file a module id names: without `?query` or Vite's `\0` prefix (a `#` is the path's). */
export function file(id) {
  return id.replace(/^\0/, '').replace(/\?.*$/, '');
}

/** A module id's query (`raw` for `light.frag?raw`), `''` without one. */
function query(id) {
  const at = id.indexOf('?');
  return at < 0 ? '' : id.slice(at + 1);
}

/** Whether a module is one essl checks, under the plugin's options. */
export function wanted(id, options = {}) {
  if (id.startsWith('\0')) return false;
  const f = file(id);
  if (!SHADER.test(f) && !SCRIPT.test(f)) return false;
  if (options.exclude ? matches(options.exclude, f) : /[\\/]node_modules[\\/]/.test(f)) return false;
  return options.include ? matches(options.include, f) : true;
}

function matches(patterns, f) {
  return [patterns].flat().some(p => {
    if (!(p instanceof RegExp)) return f.includes(p);
    p.lastIndex = 0; // a `g` or `y` RegExp keeps its place between tests
    return p.test(f);
  });
}

/**
 * Checks a module: a shader file as its author wrote it (`shaderText`, or `code` itself when
 * `given`: a webpack loader's source, as the loaders before it left it; its `#include`s followed
 * from disk), a script from `code`. Returns the result, its errors and warnings (warnings count
 * as errors under `failOnWarnings`), and for a shader file the text WebGL is given (includes in
 * place) and the files it read.
 */
export async function checkModule(id, code, options = {}, given = false, cache = null) {
  const f = file(id);
  const isShader = SHADER.test(f);
  if (!isShader && !options.preset && !MAY_HOLD.test(code)) return null;
  const source = !isShader || given ? code : shaderText(f, code, query(id));
  const o = {filename: f};
  for (const k of CHECK_KEYS) if (options[k] !== undefined) o[k] = options[k];
  // `minify: true`: a shader file's text is minified (a script's shaders are left as they are,
  // and so are shaders a preset's library assembles at run time).
  const minify = isShader && options.minify === true && !options.preset;
  // A preset's checks read the library the project has installed: those are not kept.
  const key = cache && !options.preset ? cache.key(f, source, [o, minify, !!options.failOnWarnings]) : null;
  if (key) {
    const kept = cache.get(key, f, source);
    if (kept) return kept;
  }
  const checked = await checkSource(source, o, f, isShader, minify, options);
  if (key && checked) {
    // An `essl.toml` the options name is read too (the nearest one the cache finds itself).
    const files = read(checked.result);
    if (o.config) files.push(o.config);
    cache.set(key, f, checked, files, source);
  }
  return checked;
}

/** Every file a check read: each shader's file and the files its `#include`s named. */
function read(result) {
  return result.shaders.flatMap(s => [s.file, ...(s.files ?? [])]);
}

async function checkSource(source, o, f, isShader, minify, options) {
  let result;
  const notes = [];
  try {
    result = minify ? await minifyOrCheck(source, o, f, notes) : await checkAsync(source, o);
  } catch (e) {
    // A `.glsl` file nothing gives a stage to is a chunk for other shaders to include (as
    // vite-plugin-glsl's users write them): it is checked where it is included.
    if (/\.glsl$/.test(f) && /cannot tell the stage/.test(e.message)) return null;
    throw e;
  }
  const fails = d => d.severity === 'error' || (options.failOnWarnings && d.severity === 'warning');
  const errors = result.diagnostics.filter(fails);
  const warnings = result.diagnostics.filter(d => d.severity === 'warning' && !fails(d));
  for (const n of notes) warnings.push({severity: 'warning', rendered: n});
  const shader = isShader ? result.shaders[0] : null;
  const text = minify && typeof result.text === 'string' ? result.text : shader?.text ?? null;
  return {result, errors, warnings, text, files: shader?.files ?? []};
}

/**
 * A shader file's text as its author wrote it: taken back from the module Vite made of a `?raw`
 * import or this plugin's `load` (`export default "…"`, the text as a JSON string), else read
 * from the file. The read is synchronous: an asynchronous one costs four trips through Node's
 * thread pool, which the bundler's own reads wait behind (200 shaders: 20 ms on a build of 80).
 */
function shaderText(f, code, q) {
  // Another query's module (`?url`, `?inline`, `?worker`) is not the text: the file is.
  const prefix = 'export default "';
  const body = code.trimEnd().replace(/;$/, '');
  if ((q === '' || q === 'raw') && body.startsWith(prefix) && body.endsWith('"')) {
    try {
      const text = JSON.parse(body.slice(prefix.length - 1));
      if (typeof text === 'string') return text;
    } catch {
      // Not one JSON string after all: the file says what the author wrote.
    }
  }
  return readFileSync(f, 'utf8');
}

/**
 * A shader file checked and minified. Should the minifier refuse its own output (it compiles
 * the text again and compares the interface), the file is checked as it is, its text goes
 * out unminified, and a warning says why.
 */
async function minifyOrCheck(source, o, f, notes) {
  try {
    return await minifyAsync(source, o);
  } catch (e) {
    if (e instanceof TypeError || /cannot tell the stage/.test(e.message)) throw e;
    notes.push(`essl: ${f} is not minified: ${e.message}`);
    return await checkAsync(source, o);
  }
}

/** The error a bundler reports: essl's text for every error, located at the first one. */
export function buildError(errors) {
  const first = errors[0];
  const err = new Error(`essl: ${errors.length} error${errors.length === 1 ? '' : 's'} in shaders\n${format(errors)}`);
  err.name = 'EsslError';
  err.plugin = 'essl';
  if (first.range) {
    err.id = first.file;
    err.loc = {file: first.file, line: first.range.start.line, column: first.range.start.column - 1};
  }
  err.diagnostics = errors;
  return err;
}
