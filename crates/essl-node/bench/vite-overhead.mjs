// What the essl plugin adds to a `vite build`: a generated project importing 200 shaders
// (`?raw`, the webgl2fundamentals lessons' shaders from ../shared/corpora or $ESSL_CORPORA),
// built with and without the plugin, after one untimed build of each, alternating, ROUNDS times
// each (default 7); prints the median wall-clock and CPU time of each and the change in per
// cent: the plugin with the lints and with `lints: false`, both without its cache (every module
// checked), and with the lints and a cache the untimed build filled (every module unchanged
// since), and the median of each round's change against that round's build without the plugin.
// Two projects: the shaders alone, and an app that also bundles three.js (the copy
// scripts/fetch-js-libs.sh installs in tests/js) and makes a RawShaderMaterial of each shader.
//
//   node --expose-gc bench/vite-overhead.mjs   (from crates/essl-node, after `npm run build`)
//
// The projects are written under /dev/shm where there is one (a disk's write-back otherwise
// moves the builds' times), and the heap is collected before each build where `--expose-gc`
// allows (one variant's garbage otherwise lands in the next one's build).
import {mkdtempSync, mkdirSync, readFileSync, rmSync, writeFileSync, existsSync, symlinkSync} from 'node:fs';
import {tmpdir, cpus} from 'node:os';
import {dirname, join} from 'node:path';
import {fileURLToPath} from 'node:url';
import {execFileSync} from 'node:child_process';
import {build} from 'vite';
import essl from '../lib/vite.js';

const here = dirname(fileURLToPath(import.meta.url));
const corpora = process.env.ESSL_CORPORA || join(here, '..', '..', '..', '..', 'shared', 'corpora');
const file = join(corpora, 'webgl2fundamentals_shaders.jsonl');
if (!existsSync(file)) {
  console.error(`vite-overhead: no ${file} (set ESSL_CORPORA)`);
  process.exit(process.env.ESSL_REQUIRE_CORPORA === '1' ? 1 : 0);
}
const ROUNDS = Number(process.env.ROUNDS || 7);
const shaders = readFileSync(file, 'utf8')
  .trim()
  .split('\n')
  .map(l => JSON.parse(l))
  .filter(s => !s.templated && s.stage && s.expect_compile)
  .slice(0, 200);

const three = join(here, '..', '..', '..', 'tests', 'js', 'node_modules', 'three');

function project(withThree) {
  const dir = mkdtempSync(join(existsSync('/dev/shm') ? '/dev/shm' : tmpdir(), 'essl-vite-bench-'));
  mkdirSync(join(dir, 'src', 'shaders'), {recursive: true});
  const imports = [];
  shaders.forEach((s, i) => {
    const name = `s${String(i).padStart(3, '0')}.${s.stage === 'vertex' ? 'vert' : 'frag'}`;
    writeFileSync(join(dir, 'src', 'shaders', name), s.source);
    imports.push(`import s${i} from './shaders/${name}?raw';`);
  });
  let main = `${imports.join('\n')}\nexport const all = [${shaders.map((_, i) => `s${i}`).join(', ')}];\n`;
  if (withThree) {
    mkdirSync(join(dir, 'node_modules'));
    symlinkSync(three, join(dir, 'node_modules', 'three'));
    main =
      "import * as THREE from 'three';\n" +
      main +
      'const renderer = new THREE.WebGLRenderer();\n' +
      'const scene = new THREE.Scene();\n' +
      'for (const s of all) scene.add(new THREE.Mesh(new THREE.BoxGeometry(), new THREE.RawShaderMaterial({vertexShader: s, fragmentShader: s})));\n' +
      'renderer.render(scene, new THREE.PerspectiveCamera());\n';
  } else {
    main += 'document.body.textContent = all.join("\\n").length;\n';
  }
  writeFileSync(join(dir, 'src', 'main.js'), main);
  writeFileSync(join(dir, 'index.html'), '<!doctype html><script type="module" src="/src/main.js"></script>\n');
  return dir;
}

// One build: its wall-clock time and the process's CPU time (every thread: Vite's, esbuild's
// service aside, and the checks on Node's thread pool), in ms. The CPU time says what the
// checks cost the process however they were scheduled (on a VM whose two threads slow each
// other, it moves between runs about as much as the wall-clock time).
async function once(dir, plugin) {
  globalThis.gc?.();
  const cpu = process.cpuUsage();
  const start = process.hrtime.bigint();
  await build({
    root: dir,
    configFile: false,
    logLevel: 'silent',
    plugins: plugin ? [plugin] : [],
    build: {outDir: join(dir, 'dist'), emptyOutDir: true},
  });
  const used = process.cpuUsage(cpu);
  return {wall: Number(process.hrtime.bigint() - start) / 1e6, cpu: (used.user + used.system) / 1e3};
}

const median = a => [...a].sort((x, y) => x - y)[a.length >> 1];
const commit = execFileSync('git', ['rev-parse', '--short', 'HEAD'], {encoding: 'utf8'}).trim();
console.log(`vite build, ${shaders.length} shaders, commit ${commit}, ${cpus().length} × ${cpus()[0].model}, ${ROUNDS} rounds`);
for (const withThree of [false, ...(existsSync(three) ? [true] : [])]) {
  const dir = project(withThree);
  const variants = {
    without: null,
    essl: essl({cache: false}),
    'essl, lints off': essl({cache: false, lints: false}),
    'essl, cached': essl({cache: join(dir, 'essl-cache')}),
  };
  const times = Object.fromEntries(Object.keys(variants).map(k => [k, []]));
  for (const p of Object.values(variants)) await once(dir, p);
  for (let r = 0; r < ROUNDS; r++) {
    const order = Object.keys(variants);
    for (let k = 0; k < r % order.length; k++) order.push(order.shift());
    for (const name of order) times[name].push(await once(dir, variants[name]));
  }
  rmSync(dir, {recursive: true, force: true});
  for (const what of ['wall', 'cpu']) {
    const base = median(times.without.map(t => t[what]));
    const parts = Object.entries(times).map(([name, t]) => {
      const m = median(t.map(x => x[what]));
      const change = ((m - base) / base) * 100;
      return name === 'without' ? `without essl ${m.toFixed(0)} ms` : `${name} ${m.toFixed(0)} ms (${change >= 0 ? '+' : ''}${change.toFixed(1)} %)`;
    });
    const label = what === 'wall' ? 'wall-clock' : 'CPU (all threads)';
    console.log(`${withThree ? 'with three.js' : 'shaders alone'}, ${label}: ${parts.join(', ')}`);
    // Each round's builds ran one after another: the median of each round's change against
    // that round's build without the plugin follows the machine's drift between rounds,
    // which the medians above mix into the change.
    const paired = Object.entries(times)
      .filter(([name]) => name !== 'without')
      .map(([name, t]) => {
        const m = median(t.map((x, i) => x[what] / times.without[i][what] - 1));
        return `${name} ${m >= 0 ? '+' : ''}${(m * 100).toFixed(1)} %`;
      });
    console.log(`${withThree ? 'with three.js' : 'shaders alone'}, ${label}, per round: ${paired.join(', ')}`);
  }
}
