// A fixed sample of the Khronos WebGL conformance pages, run in Node against essl-gl as the
// full run does (conformance/run.mjs): no page may kill its process or fail to finish, and
// each passes at least the assertions the committed full run passed
// (conformance/results/essl-gl-*.json). Skips without the suite's sdk/tests
// (ESSL_WEBGL_SDK, or test-data/webgl/sdk/tests from scripts/gl-node-conformance.sh).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const sdk = process.env.ESSL_WEBGL_SDK ?? join(here, '../../../test-data/webgl/sdk/tests');
const have = existsSync(join(sdk, 'js/js-test-pre.js'));
const sample = readFileSync(join(here, '../conformance/sample.txt'), 'utf8')
  .split('\n')
  .map((l) => l.trim())
  .filter((l) => l && !l.startsWith('#'));

function expected(context) {
  const f = join(here, `../conformance/results/essl-gl-${context}.json`);
  return existsSync(f) ? JSON.parse(readFileSync(f, 'utf8')) : {};
}

// The pages draw with 2D canvases as well, which jsdom takes from the `canvas` package.
let canvas = true;
try {
  await import('canvas');
} catch {
  canvas = false;
}
const required = process.env.ESSL_REQUIRE_CORPORA === '1';
const why = !have
  ? `no WebGL conformance suite at ${sdk} (scripts/gl-node-conformance.sh fetches it)`
  : !canvas
    ? 'the canvas package is not installed or did not build (jsdom has no 2D canvas without it)'
    : null;
// The suite is not among the shared corpora and is fetched from GitHub: where it is absent the
// sample skips even under ESSL_REQUIRE_CORPORA=1; with the suite present, a missing canvas
// package fails there.
const skip = why === null || (required && have) ? false : why;

for (const context of ['webgl2', 'webgl1']) {
  const want = expected(context);
  test(`conformance sample, ${context}`, { skip }, async (t) => {
    assert.equal(why, null, `${why} (ESSL_REQUIRE_CORPORA=1)`);
    for (const line of sample) {
      const [ctx, page] = line.split(/\s+/);
      if (ctx !== context) continue;
      await t.test(page, () => {
        const out = execFileSync(process.execPath, [join(here, '../conformance/page.mjs'), sdk, page, context === 'webgl1' ? '1' : '2', '60'], { encoding: 'utf8', timeout: 120000 });
        const r = JSON.parse(out.trim().split('\n').pop());
        assert.equal(r.error, null, `error: ${r.error}`);
        assert.ok(r.finished, 'the page finished');
        const w = want[page];
        if (w) assert.ok(r.passed >= w.passed, `${r.passed} passed, the committed run passed ${w.passed}; failures: ${r.failures.slice(0, 3).join(' | ')}`);
      });
    }
  });
}
