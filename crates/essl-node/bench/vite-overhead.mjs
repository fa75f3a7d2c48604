// What the essl plugin adds to a `vite build`: a generated project importing 200 shaders
// (`?raw`, the webgl2fundamentals lessons' shaders from ../shared/corpora or $ESSL_CORPORA),
// built with and without the plugin, alternating, ROUNDS times each (default 7); prints the
// median of each and their ratio.
//
//   node bench/vite-overhead.mjs        (from crates/essl-node, after `npm run build`)
import {mkdtempSync, mkdirSync, readFileSync, rmSync, writeFileSync, existsSync} from 'node:fs';
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

const dir = mkdtempSync(join(tmpdir(), 'essl-vite-bench-'));
mkdirSync(join(dir, 'src', 'shaders'), {recursive: true});
const imports = [];
shaders.forEach((s, i) => {
  const name = `s${String(i).padStart(3, '0')}.${s.stage === 'vertex' ? 'vert' : 'frag'}`;
  writeFileSync(join(dir, 'src', 'shaders', name), s.source);
  imports.push(`import s${i} from './shaders/${name}?raw';`);
});
writeFileSync(
  join(dir, 'src', 'main.js'),
  `${imports.join('\n')}\nexport const all = [${shaders.map((_, i) => `s${i}`).join(', ')}];\n` +
    'document.body.textContent = all.join("\\n").length;\n',
);
writeFileSync(join(dir, 'index.html'), '<!doctype html><script type="module" src="/src/main.js"></script>\n');

async function once(withPlugin) {
  const start = process.hrtime.bigint();
  await build({
    root: dir,
    configFile: false,
    logLevel: 'silent',
    plugins: withPlugin ? [essl({lints: true})] : [],
    build: {outDir: join(dir, 'dist'), emptyOutDir: true},
  });
  return Number(process.hrtime.bigint() - start) / 1e6;
}

const times = {without: [], with: []};
await once(false);
await once(true);
for (let r = 0; r < ROUNDS; r++) {
  for (const withPlugin of r % 2 ? [true, false] : [false, true]) {
    times[withPlugin ? 'with' : 'without'].push(await once(withPlugin));
  }
}
rmSync(dir, {recursive: true, force: true});
const median = a => [...a].sort((x, y) => x - y)[a.length >> 1];
const commit = execFileSync('git', ['rev-parse', '--short', 'HEAD'], {encoding: 'utf8'}).trim();
const [w, wo] = [median(times.with), median(times.without)];
console.log(`vite build of ${shaders.length} shaders, commit ${commit}, ${cpus().length} × ${cpus()[0].model}, ${ROUNDS} rounds`);
console.log(`without essl: ${wo.toFixed(0)} ms (median), with essl: ${w.toFixed(0)} ms: ${(((w - wo) / wo) * 100).toFixed(1)} % added`);
