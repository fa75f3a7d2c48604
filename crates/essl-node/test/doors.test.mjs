// One pipeline behind every front door: on the same project, `npx essl lint --format json`
// (the CLI) and `check()` of each file (what the plugins call) give the same diagnostics —
// shader files with includes, a linked pair, shaders in a JS module — at the same places.
import {test} from 'node:test';
import assert from 'node:assert/strict';
import {execFileSync} from 'node:child_process';
import {cpSync, mkdtempSync, readFileSync, rmSync, writeFileSync} from 'node:fs';
import {tmpdir} from 'node:os';
import {dirname, join} from 'node:path';
import {fileURLToPath} from 'node:url';
import {check} from '../index.js';

const here = dirname(fileURLToPath(import.meta.url));
const bin = join(here, '..', 'bin', 'essl.js');

function plant(dir, file, from, to) {
  const path = join(dir, file);
  writeFileSync(path, readFileSync(path, 'utf8').replaceAll(from, to));
}

const key = d => `${d.file}:${d.line}:${d.column} ${d.code}`;

test('the CLI and check() agree on a project', () => {
  const dir = mkdtempSync(join(tmpdir(), 'essl-doors-'));
  try {
    cpSync(join(here, 'project'), dir, {recursive: true});
    plant(dir, 'src/shaders/light.vert', 'v_normal', 'v_norm');
    plant(dir, 'src/shaders/light.frag', 'u_color.a);', 'u_color.a / (u_color.g - u_color.b));');
    plant(dir, 'src/materials.js', 'u_outline * ${SCALE}', 'u_outline * ${SCALE} * u_missing');
    let out;
    try {
      out = execFileSync(process.execPath, [bin, 'lint', '--format', 'json', '-I', 'src/shaders', 'src'], {cwd: dir, encoding: 'utf8'});
    } catch (e) {
      out = e.stdout;
    }
    const objects = out.trim().split('\n').map(l => JSON.parse(l));
    const cli = objects
      .filter(o => o.kind === 'shader' || o.kind === 'program')
      .flatMap(o => o.diagnostics.map(d => key({...d, file: join(dir, d.file ?? o.file)})));
    const files = [...new Set(objects.filter(o => o.kind === 'shader').map(o => o.file))];
    const api = files.flatMap(f => {
      const filename = join(dir, f);
      const r = check(readFileSync(filename, 'utf8'), {filename, includeDirs: [join(dir, 'src', 'shaders')]});
      return r.diagnostics.map(d => key({...d, line: d.range?.start.line, column: d.range?.start.column}));
    });
    assert.ok(cli.length >= 3, cli.join('\n'));
    // A pair's link diagnostics are reported with each of its two files by check().
    assert.deepEqual([...new Set(api)].sort(), [...new Set(cli)].sort());
  } finally {
    rmSync(dir, {recursive: true, force: true});
  }
});
