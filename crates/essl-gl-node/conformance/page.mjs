#!/usr/bin/env node
// Runs one page of the WebGL conformance suite in Node: jsdom parses the page and runs its
// scripts (the suite's own js-test-pre.js and webgl-test-utils.js among them), its canvases
// answer getContext with an essl-gl context, and the suite's harness hooks
// (`webglTestHarness.reportResults` / `notifyFinished`) count each assertion.
//
//   node conformance/page.mjs SDK_TESTS_DIR PAGE VERSION [TIMEOUT_S] [--impl essl-gl|gl]
//
// Prints one JSON line: { page, version, passed, failed, finished, failures: [msg…], error }.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { JSDOM, VirtualConsole } from 'jsdom';

const [sdk, page, versionArg, timeoutArg] = process.argv.slice(2);
const implArg = process.argv.indexOf('--impl');
const impl = implArg > 0 ? process.argv[implArg + 1] : 'essl-gl';
const version = Number(versionArg ?? 2);
const timeout = Number(timeoutArg ?? 120) * 1000;

const result = { page, version, passed: 0, failed: 0, finished: false, failures: [], error: null };
let printed = false;
function report() {
  if (printed) return;
  printed = true;
  process.stdout.write(`${JSON.stringify(result)}\n`);
}

/** The implementation's hook into a jsdom window. */
async function installer() {
  if (impl === 'gl') {
    const { installHeadlessGl } = await import('./headless-gl.mjs');
    return installHeadlessGl;
  }
  const { installInWindow } = await import('../index.js');
  return installInWindow;
}

async function main() {
  const install = await installer();
  const file = join(sdk, page);
  const url = `${pathToFileURL(file).href}?webglVersion=${version}`;
  const html = readFileSync(file, 'utf8');
  const virtualConsole = new VirtualConsole();
  virtualConsole.on('jsdomError', (e) => {
    // An uncaught exception of a page script: the page counts it as nothing, the browser
    // prints it; kept for the report.
    if (result.failures.length < 50) result.failures.push(`uncaught: ${e.message}`);
  });
  let done;
  const finished = new Promise((resolve) => {
    done = resolve;
  });
  const dom = new JSDOM(html, {
    url,
    runScripts: 'dangerously',
    resources: 'usable',
    pretendToBeVisual: true,
    virtualConsole,
    beforeParse(window) {
      install(window);
      // jsdom has no OffscreenCanvas. Pages that draw into one with a 2D context and upload it
      // as a texture (extensions/oes-texture-*-with-canvas.html) get a detached <canvas> of
      // that size, which the `canvas` package draws as it draws the page's other 2D canvases;
      // the pages that need OffscreenCanvas itself (transfer, workers) are left out.
      if (!window.OffscreenCanvas) {
        window.OffscreenCanvas = function OffscreenCanvas(width, height) {
          const c = window.document.createElement('canvas');
          c.width = width;
          c.height = height;
          return c;
        };
      }
      // jsdom lays nothing out, so an element's client size is 0; an unstyled canvas's is
      // its width and height, as a browser lays it out.
      for (const dim of ['Width', 'Height']) {
        Object.defineProperty(window.HTMLCanvasElement.prototype, `client${dim}`, {
          configurable: true,
          get() {
            return this.style[dim.toLowerCase()] ? 0 : this[dim.toLowerCase()];
          },
        });
      }
      // jsdom has no fetch, and Node's does not read file: URLs: the suite's resources are
      // read from the folder the page is in, as a browser serving the suite reads them.
      window.fetch = async (input) => {
        const u = new URL(String(input?.url ?? input), window.location.href);
        if (u.protocol !== 'file:') return fetch(u);
        const body = readFileSync(fileURLToPath(u));
        return new Response(body, { status: 200 });
      };
      // jsdom's postMessage sends a message whose `source` is null; a browser's names the
      // window that posted it, which the suite's setZeroTimeout (webgl-test-utils.js) checks.
      window.postMessage = (data) => {
        setTimeout(() => {
          const e = new window.MessageEvent('message', { data, origin: window.location.origin, source: window });
          window.dispatchEvent(e);
        }, 0);
      };
      window.webglTestHarness = {
        reportResults(_path, success, msg, skipped) {
          if (skipped) return;
          if (success) result.passed++;
          else {
            result.failed++;
            if (result.failures.length < 50) result.failures.push(String(msg));
          }
        },
        notifyFinished() {
          result.finished = true;
          done();
        },
      };
    },
  });
  const timer = setTimeout(() => {
    result.error = 'timeout';
    done();
  }, timeout);
  await finished;
  clearTimeout(timer);
  try {
    dom.window.close();
  } catch {
    // The page's own teardown failing does not change its counts.
  }
}

process.on('uncaughtException', (e) => {
  result.error = `uncaught: ${e?.stack ?? e}`.slice(0, 2000);
  report();
  process.exit(0);
});

main()
  .then(() => {
    report();
    process.exit(0);
  })
  .catch((e) => {
    result.error = String(e?.stack ?? e).slice(0, 2000);
    report();
    process.exit(0);
  });
