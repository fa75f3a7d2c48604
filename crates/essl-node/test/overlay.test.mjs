// `vite dev` in a real browser (Debian's Chromium through playwright-core): an error planted
// in an imported shader shows in Vite's error overlay with essl's message at the author's
// line, and goes away when the file is saved fixed. The overlay's screenshot is written to
// $ESSL_ARTIFACTS (or the temporary folder) and checked to cover the page.
import {test} from 'node:test';
import assert from 'node:assert/strict';
import {cpSync, existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync} from 'node:fs';
import {tmpdir} from 'node:os';
import {dirname, join} from 'node:path';
import {fileURLToPath} from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';

async function tools() {
  try {
    return {vite: await import('vite'), playwright: await import('playwright-core')};
  } catch {
    return null;
  }
}
const t = await tools();
const skip = !t
  ? 'vite and playwright-core are not installed (npm ci in crates/essl-node)'
  : !existsSync(CHROMIUM)
    ? `no Chromium at ${CHROMIUM} (apt-get install chromium, or set CHROMIUM)`
    : false;
if (skip && process.env.ESSL_REQUIRE_CORPORA === '1') throw new Error(skip);

test('vite dev: the error in the overlay, gone on save', {skip, timeout: 120_000}, async () => {
  const {default: essl} = await import('../lib/vite.js');
  const dir = mkdtempSync(join(tmpdir(), 'essl-overlay-'));
  cpSync(join(here, 'project'), dir, {recursive: true});
  const frag = join(dir, 'src', 'shaders', 'light.frag');
  const good = readFileSync(frag, 'utf8');
  writeFileSync(frag, good.replace('u_color.rgb * lambert', 'u_colour.rgb * lambert'));
  const server = await t.vite.createServer({
    root: dir,
    configFile: false,
    logLevel: 'silent',
    plugins: [essl()],
    server: {port: 0, host: '127.0.0.1'},
  });
  await server.listen();
  const browser = await t.playwright.chromium.launch({executablePath: CHROMIUM, args: ['--no-sandbox']});
  try {
    const page = await browser.newPage({viewport: {width: 1000, height: 700}});
    await page.goto(server.resolvedUrls.local[0]);
    const overlay = page.locator('vite-error-overlay');
    await overlay.waitFor({timeout: 30_000});
    const text = await page.evaluate(() => document.querySelector('vite-error-overlay').shadowRoot.textContent);
    assert.match(text, /error\[undeclared-identifier\]: `u_colour` is not declared/);
    assert.match(text, /light\.frag:9:19/);
    const out = join(process.env.ESSL_ARTIFACTS || dir, 'vite-overlay.png');
    const png = await page.screenshot({path: out});
    assert.ok(png.length > 10_000, 'a screenshot with content');
    const box = await page.evaluate(() => {
      const r = document.querySelector('vite-error-overlay').shadowRoot.querySelector('.window').getBoundingClientRect();
      return {w: r.width, h: r.height, top: document.elementFromPoint(500, 200)?.tagName};
    });
    assert.equal(box.top, 'VITE-ERROR-OVERLAY', 'the overlay is what the page shows');
    assert.ok(box.w > 500 && box.h > 100, JSON.stringify(box));
    writeFileSync(frag, good);
    await overlay.waitFor({state: 'detached', timeout: 30_000});
    await page.waitForFunction(() => document.getElementById('out')?.textContent.includes('lambert'), null, {timeout: 30_000});
  } finally {
    await browser.close();
    await server.close();
    rmSync(dir, {recursive: true, force: true});
  }
});
