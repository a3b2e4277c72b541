// Shared by the browser tests: a static file server for the built page, Debian's headless
// Chromium through playwright-core, and a tiny test runner printing "ok"/"FAIL" lines and a final
// "N passed, M failed" (exit 1 on failure).

import { readFileSync, statSync } from 'node:fs';
import { extname, join, normalize, sep } from 'node:path';
import { createServer } from 'node:http';
import { chromium } from 'playwright-core';

const TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.wasm': 'application/wasm',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.png': 'image/png',
  '.svg': 'image/svg+xml',
};

/** Serves `dir` on 127.0.0.1 (a free port); `pages` maps extra paths to HTML text. */
export function serve(dir, pages = {}) {
  const server = createServer((req, res) => {
    const path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    if (path in pages) {
      res.writeHead(200, { 'content-type': TYPES['.html'] });
      return res.end(pages[path]);
    }
    let file = normalize(join(dir, path));
    if (file !== dir && !file.startsWith(dir + sep)) {
      res.writeHead(403);
      return res.end();
    }
    try {
      if (statSync(file).isDirectory()) file = join(file, 'index.html');
      const body = readFileSync(file);
      res.writeHead(200, { 'content-type': TYPES[extname(file)] ?? 'application/octet-stream' });
      res.end(body);
    } catch {
      res.writeHead(404, { 'content-type': 'text/plain' });
      res.end('not found');
    }
  });
  return new Promise((ok, fail) => {
    server.once('error', fail);
    server.listen(0, '127.0.0.1', () => ok(server));
  });
}

/** Headless Chromium; exits the process with a FAIL line if it cannot start. WebGL runs on
 * SwiftShader; `--disable-gpu` keeps the page's compositing in software too, which in headless
 * Chromium is far faster than compositing through SwiftShader GL (a frame that only moves a
 * progress bar takes ~17 ms instead of 33–150 ms), so frame times measure the page, not the
 * emulated GPU. */
export function launch() {
  return chromium
    .launch({
      executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
      headless: true,
      args: [
        '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
        '--disable-background-networking', '--disable-component-update', '--disable-sync',
        '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
      ],
    })
    .catch((e) => {
      console.log(`FAIL launching Chromium: ${e.message}`);
      console.log('0 passed, 1 failed');
      process.exit(1);
    });
}

/** A test runner: `test(name, fn)` runs and reports one test; `finish()` prints the totals and
 * exits; a watchdog fails the run after `limitMs`. Exits at once if `pageDir` has no built page. */
export function runner(what, pageDir, limitMs) {
  const results = [];
  try {
    statSync(join(pageDir, 'index.html'));
  } catch {
    console.log(`FAIL no built page at ${pageDir} (run scripts/build-page.sh)`);
    console.log('0 passed, 1 failed');
    process.exit(1);
  }
  setTimeout(() => {
    console.log(`FAIL watchdog: ${what} took more than ${limitMs / 60000} minutes`);
    console.log(`${results.filter((r) => r.ok).length} passed, ${results.filter((r) => !r.ok).length + 1} failed`);
    process.exit(1);
  }, limitMs).unref();
  return {
    async test(name, fn) {
      const started = Date.now();
      try {
        const detail = await fn();
        results.push({ name, ok: true });
        console.log(`ok   ${name}${detail ? ` — ${detail}` : ''} (${Date.now() - started} ms)`);
      } catch (e) {
        results.push({ name, ok: false });
        console.log(`FAIL ${name}: ${e && e.stack ? e.stack : e}`);
      }
    },
    finish(artifacts) {
      const passed = results.filter((r) => r.ok).length;
      const failed = results.length - passed;
      console.log(`screenshots in ${artifacts}`);
      console.log(`${passed} passed, ${failed} failed`);
      process.exit(failed ? 1 : 0);
    },
  };
}
