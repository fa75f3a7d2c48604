// The Vite and Rollup plugin (`essl/vite`, `essl/rollup`): checks every shader file and every
// script that holds shaders as it is transformed; an error fails the build (and shows in
// Vite's overlay in `vite dev`, until the file is saved fixed), a warning prints. A shader
// file imported without another loader (`import fs from './light.frag'`) becomes a module
// whose default export is the text WebGL is given, its `#include`s in place; with `minify:
// true`, that text (and a `?raw` import's) minified.
import {readFileSync} from 'node:fs';
import {CheckCache, cacheDir} from './cache.js';
import {MAYBE_WANTED, SHADER, buildError, checkModule, file, optionsError, wanted} from './core.js';

export default function essl(options = {}) {
  if (options === null || typeof options !== 'object' || Array.isArray(options)) {
    throw new TypeError('essl(): options must be an object');
  }
  const bad = optionsError('essl()', options);
  if (bad) throw bad;
  const load = options.load !== false;
  // Files whose errors the page shows (`vite dev`): saving one reloads the page, so that the
  // overlay goes as soon as the shader is fixed (a module whose transform failed is not in
  // Vite's module graph, and its change would not reach the page).
  const failed = new Set();
  // In a one-shot build (not `vite dev`, not watch mode), a module whose code the plugin does
  // not replace (a script, a `?raw` import) is not waited for: its check runs on Node's thread
  // pool while the bundler goes on, and the first failing module (in the order the modules
  // were transformed) fails the build when the bundle is written; its warnings print then.
  let serving = false;
  let pending = [];
  // Checks kept between builds (`cache`, default on): Vite's root, else the working folder.
  let cache = null;
  const useCache = root => {
    const dir = cacheDir(options.cache, root);
    cache = dir ? new CheckCache(dir) : null;
  };
  useCache(process.cwd());
  return {
    name: 'essl',
    enforce: 'pre',
    configResolved(config) {
      serving = config.command === 'serve';
      if (config.root) useCache(config.root);
    },
    buildStart() {
      pending = [];
      cache?.forgetDisk();
    },
    buildEnd() {
      // A one-shot build keeps its checks at `generateBundle`, after those still running.
      if (serving || this.meta?.watchMode) cache?.save();
    },
    async generateBundle() {
      const all = await Promise.all(pending);
      pending = [];
      cache?.save();
      for (const r of all) if (r.thrown) throw r.thrown;
      for (const r of all) for (const w of r.checked?.warnings ?? []) this.warn(w.rendered);
      const failing = all.find(r => r.checked?.errors.length);
      if (failing) this.error(buildError(failing.checked.errors));
    },
    configureServer(server) {
      const reload = () => {
        failed.clear();
        server.ws.send({type: 'full-reload'});
      };
      server.watcher.on('change', changed => {
        if (failed.has(changed)) reload();
      });
      // A shader file created while the page shows an error may be the `#include` it missed.
      server.watcher.on('add', added => {
        if (failed.size && SHADER.test(added)) reload();
      });
    },
    // Each hook's `filter` (Rollup 4.38, Vite 6.3) spares the bundler calling it for modules it
    // would return at once (in Vite, two wrappers a call: about 2 ms a build of 200 shaders);
    // older bundlers ignore it and the hook tests the module itself.
    load: {
      filter: {id: SHADER},
      handler(id) {
        // `?raw` and other queries are Vite's; a bare shader import is this plugin's.
        if (!load || id.includes('?') || id.startsWith('\0') || !SHADER.test(id) || !wanted(id, options)) return null;
        return `export default ${JSON.stringify(readFileSync(id, 'utf8'))};`;
      },
    },
    transform: {
      filter: {id: MAYBE_WANTED},
      handler: transform,
    },
  };

  async function transform(code, id) {
    if (!wanted(id, options)) return null;
    // Under `minify` (which a `preset` turns off), a `?raw` import's code is replaced too:
    // its text minified.
    const raw = options.minify === true && !options.preset && /\?raw$/.test(id) && SHADER.test(file(id));
    const replaces = (load && !id.includes('?') && SHADER.test(id)) || raw;
    if (!replaces && !serving && !this.meta?.watchMode) {
      pending.push(checkModule(id, code, options, false, cache).then(checked => ({checked}), thrown => ({thrown})));
      return null;
    }
    // `vite dev` has one build start for the server's life: an included file may have
    // changed since the last check.
    if (serving) cache?.forgetDisk();
    const checked = await checkModule(id, code, options, false, cache);
    if (!checked) return null;
    for (const f of checked.files) if (f !== file(id)) this.addWatchFile(f);
    for (const w of checked.warnings) this.warn(w.rendered);
    if (checked.errors.length) {
      failed.add(file(id));
      for (const f of checked.files) failed.add(f);
      for (const e of checked.errors) if (e.file) failed.add(e.file);
      this.error(buildError(checked.errors));
    }
    // The module's text: a bare import's, or under `minify` a `?raw` import's too.
    if (replaces && checked.text !== null) {
      return {code: `export default ${JSON.stringify(checked.text)};`, map: null};
    }
    return null;
  }
}
