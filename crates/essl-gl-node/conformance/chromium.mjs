// Runs pages of the WebGL conformance suite in headless Chromium (Debian's `chromium`, its
// WebGL on ANGLE/SwiftShader), counting each page's assertions through the same harness hooks
// as the Node runner (`webglTestHarness.reportResults` / `notifyFinished`), over a local
// HTTP server of the suite's folder.
import { createServer } from 'node:http';
import { readFile } from 'node:fs/promises';
import { extname, join, normalize } from 'node:path';
import { chromium } from 'playwright-core';

const TYPES = {
  '.html': 'text/html',
  '.js': 'text/javascript',
  '.css': 'text/css',
  '.png': 'image/png',
  '.jpg': 'image/jpeg',
  '.gif': 'image/gif',
  '.svg': 'image/svg+xml',
  '.webm': 'video/webm',
  '.mp4': 'video/mp4',
  '.ogv': 'video/ogg',
  '.txt': 'text/plain',
  '.wasm': 'application/wasm',
  '.json': 'application/json',
};

/** Serves `root` on 127.0.0.1; resolves to `{ url, close }`. */
export function serve(root) {
  const server = createServer(async (req, res) => {
    const path = normalize(decodeURIComponent(new URL(req.url, 'http://x').pathname));
    try {
      const body = await readFile(join(root, path));
      res.writeHead(200, { 'content-type': TYPES[extname(path)] ?? 'application/octet-stream' });
      res.end(body);
    } catch {
      res.writeHead(404);
      res.end();
    }
  });
  return new Promise((resolve) => {
    server.listen(0, '127.0.0.1', () => {
      const { port } = server.address();
      resolve({ url: `http://127.0.0.1:${port}`, close: () => server.close() });
    });
  });
}

export const FLAGS = [
  '--no-sandbox',
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--ignore-gpu-blocklist',
  '--disable-quic',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--disable-dev-shm-usage',
  '--autoplay-policy=no-user-gesture-required',
];

/** Launches Debian's Chromium headless. */
export function launch() {
  return chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    headless: true,
    args: FLAGS,
  });
}

const HOOKS = `
  window.__results = { passed: 0, failed: 0, failures: [], finished: false };
  window.webglTestHarness = {
    reportResults(path, success, msg, skipped) {
      if (skipped) return;
      if (success) window.__results.passed++;
      else {
        window.__results.failed++;
        if (window.__results.failures.length < 50) window.__results.failures.push(String(msg));
      }
    },
    notifyFinished() { window.__results.finished = true; },
  };
`;

/** Runs `page` (relative to the served root) in WebGL `version`; its counts. */
export async function runPage(browser, base, page, version, timeoutMs) {
  const result = { page, version, passed: 0, failed: 0, finished: false, failures: [], error: null };
  const context = await browser.newContext({ viewport: { width: 800, height: 600 } });
  const tab = await context.newPage();
  await tab.addInitScript(HOOKS);
  tab.on('pageerror', (e) => {
    if (result.failures.length < 50) result.failures.push(`uncaught: ${e.message}`);
  });
  try {
    await tab.goto(`${base}/${page}?webglVersion=${version}`, { timeout: timeoutMs });
    await tab.waitForFunction(() => window.__results.finished, null, { timeout: timeoutMs, polling: 200 });
  } catch (e) {
    result.error = /Timeout/.test(String(e)) ? 'timeout' : String(e).slice(0, 500);
  }
  try {
    const r = await tab.evaluate(() => window.__results);
    Object.assign(result, { passed: r.passed, failed: r.failed, finished: r.finished });
    result.failures.push(...r.failures);
  } catch (e) {
    result.error ??= String(e).slice(0, 500);
  }
  await context.close().catch(() => {});
  return result;
}
