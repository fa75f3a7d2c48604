// The plugin's cache of checks between builds (`cache` option; default
// `<root>/node_modules/.cache/essl`), as eslint-webpack-plugin and rollup-plugin-typescript2
// keep theirs: a module whose check found no error is not checked again while its text, the
// options, the essl build, every file the check read (`#include`d files, the partner of a
// `NAME.vert` + `NAME.frag` pair, the `essl.toml` the options name) and the nearest
// `essl.toml` are unchanged. Results with
// errors are never kept, so a fix is always checked; what is kept is what the plugin uses
// (the warnings' text, the shader text where it is not the module's own, the files read), one
// JSON file for the folder, read once a build: its size is most of what a build that checks
// nothing new pays.
//
// Written by hand: the caches on npm (flat-cache, file-entry-cache, find-cache-dir) key on a
// file's metadata and know nothing of what a check read besides the file itself.
import * as crypto from 'node:crypto';
import {existsSync, mkdirSync, readFileSync, renameSync, statSync, writeFileSync} from 'node:fs';
import {dirname, join} from 'node:path';
import {fileURLToPath} from 'node:url';
import {LOCAL_ADDON} from './native.js';

const FORMAT = 2;
/** An entry's `text` when it is the text checked. */
const SAME = 1;
/** Entries kept in the file (the most recently used). */
const MAX_ENTRIES = 10000;
const here = dirname(fileURLToPath(import.meta.url));

// Node's one-shot `hash` (20.12, 21.7) where it has one: half `createHash`'s time on a
// shader's text.
const sha = crypto.hash
  ? text => crypto.hash('sha256', text, 'base64url')
  : text => crypto.createHash('sha256').update(text).digest('base64url');

/** What makes results of one essl differ from another's: the package's version and, where
 * the addon was built beside it (this repository), the addon file's size and time. */
function buildId() {
  const pkg = readFileSync(join(here, '..', 'package.json'), 'utf8');
  let stamp = '';
  try {
    const s = statSync(LOCAL_ADDON);
    stamp = `${s.size}:${s.mtimeMs}`;
  } catch {
    // The per-platform package's addon: its version is the package's.
  }
  return sha(`${FORMAT}\n${pkg}\n${stamp}`);
}

/** The cache folder an option names: `true` or absent → `<root>/node_modules/.cache/essl`. */
export function cacheDir(option, root) {
  if (option === false) return null;
  if (typeof option === 'string') return option;
  return join(root, 'node_modules', '.cache', 'essl');
}

/** The checks of one plugin instance: loaded on first use, written by `save`. */
export class CheckCache {
  constructor(dir) {
    this.dir = dir;
    this.file = join(dir, 'checks.json');
    this.entries = null;
    this.changed = false;
    this.base = null;
    // Within one build: each file's hash and each folder's nearest `essl.toml`.
    this.hashes = new Map();
    this.configs = new Map();
  }

  /** Forgets what was seen of the disk: at each build, and before each check in `vite dev`,
   * where files change while the server runs. */
  forgetDisk() {
    this.hashes.clear();
    this.configs.clear();
  }

  load() {
    if (this.entries) return;
    this.base ??= buildId();
    this.entries = new Map();
    try {
      const kept = JSON.parse(readFileSync(this.file, 'utf8'));
      if (kept.format === FORMAT && kept.base === this.base && Array.isArray(kept.entries)) {
        for (const [key, entry] of kept.entries) this.entries.set(key, entry);
      }
    } catch {
      // None yet, or unreadable: start empty.
    }
  }

  /** The key of a module's check: its file, its text and the options that change the answer. */
  key(f, source, options) {
    this.load();
    return sha(`${this.base}\n${f}\n${JSON.stringify(options)}\n${source}`);
  }

  fileHash(path) {
    let h = this.hashes.get(path);
    if (h === undefined) {
      try {
        h = sha(readFileSync(path));
      } catch {
        h = null;
      }
      this.hashes.set(path, h);
    }
    return h;
  }

  /** The nearest `essl.toml` in `dir` or above, with its hash: `[path, hash]`, or `null`. */
  config(dir) {
    if (this.configs.has(dir)) return this.configs.get(dir);
    const candidate = join(dir, 'essl.toml');
    let found;
    if (existsSync(candidate)) {
      found = [candidate, this.fileHash(candidate)];
    } else {
      const up = dirname(dir);
      found = up === dir ? null : this.config(up);
    }
    this.configs.set(dir, found);
    return found;
  }

  /** The kept check for `key` when nothing it read has changed, else undefined; `source` is
   * the text the key was made of, which an entry does not repeat. */
  get(key, f, source) {
    const entry = this.entries.get(key);
    if (!entry) return undefined;
    const same =
      JSON.stringify(this.config(dirname(f))) === JSON.stringify(entry.config) &&
      entry.deps.every(([path, h]) => this.fileHash(path) === h);
    if (!same) return undefined;
    // Used again: among the most recent, written when something else changes (a build
    // that checks nothing new writes nothing).
    this.entries.delete(key);
    this.entries.set(key, entry);
    const {text, files, warnings} = entry.checked;
    return {
      errors: [],
      warnings,
      text: text === SAME ? source : text,
      files: files ?? [f],
    };
  }

  /** Keeps a check of `source` that found no error, with the files it read (besides `f`
   * itself). The text WebGL is given is kept only where it is not `source` (an `#include`
   * put in place, a minified text), and the files only where they are not `[f]`: a build
   * reads the whole file before it checks anything. */
  set(key, f, checked, read, source) {
    if (checked.errors.length) return;
    const deps = [...new Set(read)].filter(p => p && p !== f).map(p => [p, this.fileHash(p)]);
    if (deps.some(([, h]) => h === null)) return;
    const plain = {
      warnings: checked.warnings.map(w => ({severity: w.severity, rendered: w.rendered})),
      text: checked.text === source ? SAME : checked.text,
    };
    if (!(checked.files.length === 1 && checked.files[0] === f)) plain.files = checked.files;
    this.entries.delete(key);
    this.entries.set(key, {config: this.config(dirname(f)), deps, checked: plain});
    this.changed = true;
  }

  /** Writes the kept checks, the most recently used last. */
  save() {
    if (!this.entries || !this.changed) return;
    this.changed = false;
    const all = [...this.entries].slice(-MAX_ENTRIES);
    try {
      mkdirSync(this.dir, {recursive: true});
      const tmp = `${this.file}.${process.pid}.tmp`;
      writeFileSync(tmp, JSON.stringify({format: FORMAT, base: this.base, entries: all}));
      renameSync(tmp, this.file);
    } catch {
      // A cache that cannot be written leaves the next build to check again.
    }
  }
}
