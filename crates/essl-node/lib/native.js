// Loads the addon: the `.node` beside the package (as the repository's build and `npm pack`
// put it), else the per-platform package napi-rs's convention names.
import {createRequire} from 'node:module';
import {fileURLToPath} from 'node:url';

const require = createRequire(import.meta.url);
const PLATFORM = `${process.platform}-${process.arch}${process.platform === 'linux' ? '-gnu' : ''}`;
/** The addon file beside the package, where the repository's build puts it. */
export const LOCAL_ADDON = fileURLToPath(new URL(`../essl.${PLATFORM}.node`, import.meta.url));

function load() {
  const tried = [];
  for (const name of [LOCAL_ADDON, `essl-${PLATFORM}`]) {
    try {
      return require(name);
    } catch (e) {
      if (e.code !== 'MODULE_NOT_FOUND') throw e;
      tried.push(name);
    }
  }
  throw new Error(
    `essl: no native addon for ${PLATFORM} (looked for ${tried.join(', ')}); ` +
      'essl ships one for x86-64 Linux with glibc. In the repository, build it with ' +
      '`npm run build` in crates/essl-node.',
  );
}

export const native = load();
