// Loads the addon: the local build (`essl-gl.<platform>.node` beside package.json), else the
// per-platform package (`essl-gl-<platform>`), as napi-rs packages do.
import { createRequire } from 'node:module';
import { existsSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const require = createRequire(import.meta.url);
const root = join(dirname(fileURLToPath(import.meta.url)), '..');

/** `linux-x64-gnu`, `linux-x64-musl`, `darwin-arm64`, … as napi-rs names platforms. */
export function platformTriple() {
  const { platform, arch } = process;
  if (platform === 'linux') return `linux-${arch}-${isMusl() ? 'musl' : 'gnu'}`;
  if (platform === 'win32') return `win32-${arch}-msvc`;
  return `${platform}-${arch}`;
}

function isMusl() {
  try {
    return readFileSync('/usr/bin/ldd', 'utf8').includes('musl');
  } catch {
    return !process.report?.getReport?.().header?.glibcVersionRuntime;
  }
}

function load() {
  const triple = platformTriple();
  const override = process.env.ESSL_GL_NODE_BINARY;
  const candidates = [
    override,
    join(root, `essl-gl.${triple}.node`),
    `essl-gl-${triple}`,
  ].filter(Boolean);
  const errors = [];
  for (const c of candidates) {
    if (c.endsWith('.node') && !existsSync(c)) {
      errors.push(`${c}: not built`);
      continue;
    }
    try {
      return require(c);
    } catch (e) {
      errors.push(`${c}: ${e.message}`);
    }
  }
  throw new Error(
    `essl-gl: no native addon for ${triple}. Install the package essl-gl-${triple}, or build it ` +
      `from the repository (npm run build in crates/essl-gl-node).\n  ${errors.join('\n  ')}`,
  );
}

/** The addon's exports (`NativeContext`). */
export const native = load();
