// Builds the addon from source with cargo and puts it where index.js loads it
// (essl.linux-x64-gnu.node). `--release` for an optimised build; `--no-build` copies what the
// workspace's last build left (scripts/test.sh builds it with the tests).
import {execFileSync} from 'node:child_process';
import {copyFileSync} from 'node:fs';
import {dirname, join} from 'node:path';
import {fileURLToPath} from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const root = join(here, '..', '..', '..');
const release = process.argv.includes('--release');
if (!process.argv.includes('--no-build')) {
  execFileSync('cargo', ['build', '-p', 'essl-node', ...(release ? ['--release'] : [])], {
    cwd: root,
    stdio: 'inherit',
  });
}
const target = process.env.CARGO_TARGET_DIR || join(root, 'target');
const built = join(target, release ? 'release' : 'debug', 'libessl_node.so');
copyFileSync(built, join(here, '..', 'essl.linux-x64-gnu.node'));
