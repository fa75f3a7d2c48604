// `npm pack` gives a tarball that installs into a fresh project with no compiler and no
// network (the addon is inside it), where `import {check} from 'essl'` and `npx essl` work.
import {test} from 'node:test';
import assert from 'node:assert/strict';
import {execFileSync} from 'node:child_process';
import {mkdtempSync, rmSync, writeFileSync, readdirSync} from 'node:fs';
import {tmpdir} from 'node:os';
import {dirname, join} from 'node:path';
import {fileURLToPath} from 'node:url';

const pkg = join(dirname(fileURLToPath(import.meta.url)), '..');

test('npm pack, then npm i of the tarball in a fresh folder, offline', () => {
  const dir = mkdtempSync(join(tmpdir(), 'essl-pack-'));
  try {
    execFileSync('npm', ['pack', '--pack-destination', dir, '--loglevel=error'], {cwd: pkg, stdio: 'pipe'});
    const [tarball] = readdirSync(dir).filter(f => f.endsWith('.tgz'));
    const listed = execFileSync('tar', ['tzf', join(dir, tarball)], {encoding: 'utf8'});
    assert.match(listed, /package\/essl\.linux-x64-gnu\.node/);
    assert.doesNotMatch(listed, /\.rs\n|Cargo\.toml|test\//);
    const app = join(dir, 'app');
    execFileSync('mkdir', [app]);
    writeFileSync(join(app, 'package.json'), '{"name":"app","private":true,"type":"module"}');
    execFileSync('npm', ['i', '--offline', '--no-audit', '--no-fund', '--loglevel=error', join(dir, tarball)], {
      cwd: app,
      stdio: 'pipe',
      env: {...process.env, PATH: `${dirname(process.execPath)}:/usr/bin:/bin`, CC: 'false', CXX: 'false'},
    });
    writeFileSync(join(app, 'main.js'), [
      "import {check, format} from 'essl';",
      "const r = check('#version 300 es\\nprecision mediump float;\\nout vec4 o;\\nvoid main() { o = vec4(flot(1)); }\\n', {stage: 'fragment'});",
      'console.log(r.errors, r.diagnostics[0].code);',
    ].join('\n'));
    assert.equal(execFileSync(process.execPath, ['main.js'], {cwd: app, encoding: 'utf8'}).trim(), '1 undeclared-function');
    const version = execFileSync(join(app, 'node_modules', '.bin', 'essl'), ['--version'], {cwd: app, encoding: 'utf8'});
    assert.match(version, /^essl \d/);
  } finally {
    rmSync(dir, {recursive: true, force: true});
  }
});
