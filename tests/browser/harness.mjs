// Shared pieces of the browser tests: a tiny static file server, the headless Chromium launch, a
// console/page-error watcher, a minimal test runner that ends with "N passed, M failed", the
// common start of an end-to-end test (`begin`), frame recording, and the CLI as a reference.

import { execFileSync } from 'node:child_process';
import { mkdirSync, mkdtempSync } from 'node:fs';
import { createServer } from 'node:http';
import { readFileSync, statSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { tmpdir } from 'node:os';
import { dirname, extname, join, normalize, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
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

// What a static host compresses: the page's text and its wasm (PNG is compressed already).
const GZIP = new Set(['.html', '.js', '.mjs', '.wasm', '.css', '.json', '.svg']);

/**
 * Serves `dir` on 127.0.0.1 (a free port); `extra` maps paths to HTML served as is. Files are sent
 * gzip-compressed (level 9, as scripts/build-page.sh measures them) to a client that accepts it,
 * and cacheable for ten minutes, as a static host would.
 */
export function serve(dir, extra = {}) {
  const gzipped = new Map(); // file@mtime -> its gzip
  const server = createServer((req, res) => {
    const path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    if (extra[path] !== undefined) {
      res.writeHead(200, { 'content-type': TYPES['.html'] });
      return res.end(extra[path]);
    }
    let file = normalize(join(dir, path));
    if (file !== dir && !file.startsWith(dir + sep)) {
      res.writeHead(403);
      return res.end();
    }
    try {
      let stat = statSync(file);
      if (stat.isDirectory()) {
        file = join(file, 'index.html');
        stat = statSync(file);
      }
      const headers = {
        'content-type': TYPES[extname(file)] ?? 'application/octet-stream',
        'cache-control': 'max-age=600', // as GitHub Pages sends: the worker's import of the glue hits the cache
        'last-modified': stat.mtime.toUTCString(),
      };
      if (GZIP.has(extname(file)) && /\bgzip\b/.test(req.headers['accept-encoding'] ?? '')) {
        // compressed once per file and version
        const key = `${file}@${stat.mtimeMs}`;
        if (!gzipped.has(key)) gzipped.set(key, gzipSync(readFileSync(file), { level: 9 }));
        headers['content-encoding'] = 'gzip';
        res.writeHead(200, headers);
        return res.end(gzipped.get(key));
      }
      res.writeHead(200, headers);
      res.end(readFileSync(file));
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

/** Debian's Chromium, headless, with software WebGL; exits with a failure line if it cannot start. */
export function launchChromium() {
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

/** Collects console errors, page errors and failed requests of every page of `context`. */
export function watchProblems(context) {
  const problems = [];
  const watch = (page) => {
    page.on('console', (m) => {
      if (m.type() === 'error') problems.push(`console error: ${m.text()}`);
    });
    page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    page.on('response', (r) => {
      if (r.status() >= 400) problems.push(`HTTP ${r.status()} for ${r.url()}`);
    });
    page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()} ${r.failure()?.errorText ?? ''}`));
  };
  context.on('page', watch);
  return {
    /** Throws if problems were seen since the last call. */
    assertNone() {
      if (problems.length) throw new Error(problems.splice(0).join('\n'));
    },
  };
}

/** A minimal runner: `test(name, fn)` runs and reports; `finish()` prints the summary and exits. */
export function runner(watchdogMinutes = 10) {
  const results = [];
  setTimeout(() => {
    console.log(`FAIL watchdog: the tests took more than ${watchdogMinutes} minutes`);
    console.log(`${results.filter((r) => r.ok).length} passed, ${results.filter((r) => !r.ok).length + 1} failed`);
    process.exit(1);
  }, watchdogMinutes * 60_000).unref();
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
    finish(note) {
      const passed = results.filter((r) => r.ok).length;
      const failed = results.length - passed;
      if (note) console.log(note);
      console.log(`${passed} passed, ${failed} failed`);
      process.exit(failed ? 1 : 0);
    },
  };
}

/** Exits with a failure line unless PAGE_DIR holds a built page. */
export function requirePage(pageDir) {
  try {
    statSync(join(pageDir, 'index.html'));
  } catch {
    console.log(`FAIL no built page at ${pageDir} (run scripts/build-page.sh)`);
    console.log('0 passed, 1 failed');
    process.exit(1);
  }
}

/** The drawn sections of the strip in `scope` (a Page or a Frame). */
export async function readSections(scope) {
  return scope.$$eval('svg[data-testid="strip"] rect[data-testid="section"]', (rects) =>
    rects.map((r) => ({
      kind: r.dataset.kind,
      t0: Number(r.dataset.t0),
      t1: Number(r.dataset.t1),
      title: r.querySelector('title')?.textContent ?? '',
    })),
  );
}

/** What `cablenav verify FILE --trajectory NAME --json` prints, parsed (the CLI under `root`,
 * brought up to date first: [`cliBinary`]). */
export function cliVerify(root, file, trajectory) {
  return cliJson(root, ['verify', file, '--trajectory', trajectory]);
}

/** A CLI report's sections as sorted `{kind, t0, t1}`. */
export function cliSections(report) {
  const out = [];
  for (const kind of ['feasible', 'infeasible', 'uncertain']) for (const [t0, t1] of report[kind]) out.push({ kind, t0, t1 });
  return out.sort((a, b) => a.t0 - b.t0 || a.t1 - b.t1);
}

/** The common start of an end-to-end test file at `moduleUrl` (its `import.meta.url`): the
 * repository root, the built page (argv[2], $PAGE_DIR or target/page; exits unless built), the
 * artifacts directory (created), a scratch directory, the runner, the page served and Chromium.
 * `close()` ends the browser and the server. */
export async function begin(moduleUrl, { watchdogMinutes = 10, scratch = 'cablenav-e2e-' } = {}) {
  const here = dirname(fileURLToPath(moduleUrl));
  const root = resolve(here, '..', '..');
  const pageDir = resolve(root, process.argv[2] ?? process.env.PAGE_DIR ?? 'target/page');
  const artifacts = join(here, 'artifacts');
  mkdirSync(artifacts, { recursive: true });
  requirePage(pageDir);
  const { test, finish } = runner(watchdogMinutes);
  const server = await serve(pageDir);
  const browser = await launchChromium();
  return {
    root, pageDir, artifacts, test, finish, server, browser,
    scratch: mkdtempSync(join(tmpdir(), scratch)),
    base: `http://127.0.0.1:${server.address().port}`,
    async close() {
      await browser.close();
      server.close();
    },
  };
}

/** The strip's sections in `scope` as sorted `{kind, t0, t1}` (comparable with cliSections). */
export async function stripSections(scope) {
  return (await readSections(scope)).map(({ kind, t0, t1 }) => ({ kind, t0, t1 })).sort((a, b) => a.t0 - b.t0 || a.t1 - b.t1);
}

/** Opens the results tab `id` (`planning`, `lattice`, … : web/src/state.rs `Tab::id`) by clicking
 * it, and waits until its panel shows (the other panels are hidden). */
export async function openTab(page, id) {
  await page.click(`.tablist [role="tab"][data-tab="${id}"]`);
  await page.waitForSelector(`[role="tabpanel"][data-testid="panel-${id}"]:not([hidden])`, { timeout: 60_000 });
}

/** Starts recording animation-frame lengths (ms) in window.__frames, and with each the value of
 * `stateOf()` (evaluated in the page, e.g. a data-state) in window.__states. */
export async function recordFrames(page, stateOf = '""') {
  await page.evaluate((stateOf) => {
    const state = new Function(`return (${stateOf});`);
    window.__frames = [];
    window.__states = [];
    window.__recording = true;
    let last = performance.now();
    const tick = (now) => {
      window.__frames.push(now - last);
      window.__states.push(state());
      last = now;
      if (window.__recording) requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  }, stateOf);
}

/** Stops recording; the frame lengths after the first (ms) and their states. */
export async function stopFrames(page) {
  return page.evaluate(() => {
    window.__recording = false;
    return { frames: window.__frames.slice(1), states: window.__states.slice(1) };
  });
}

/** Count, median and worst of `xs`, and how many exceed 25 ms (a frame dropped at 60 Hz: more
 * than one and a half refresh intervals). */
export function frameStats(xs) {
  const s = [...xs].sort((a, b) => a - b);
  return { n: s.length, median: s[Math.floor(s.length / 2)] ?? NaN, worst: s[s.length - 1] ?? NaN, dropped: s.filter((x) => x > 25).length };
}

/** Whether this process has brought the CLI up to date. */
let cliFresh = false;

/** The CLI under `root`, brought up to date once per process (a binary left from an older commit
 * would compare the page with another core): the dev profile's (`opt-level = 2`), which
 * `cargo test --workspace` (scripts/test.sh step 1) has built already, so that the browser tests
 * do not build the core and its dependencies once more in release. */
export function cliBinary(root) {
  if (!cliFresh) {
    execFileSync('cargo', ['build', '-q', '--bin', 'cablenav'], { cwd: root, stdio: 'inherit' });
    cliFresh = true;
  }
  return join(root, 'target', 'debug', 'cablenav');
}

/** What `cablenav ARGS…` prints with --json, parsed ([`cliBinary`]). */
export function cliJson(root, args) {
  return JSON.parse(execFileSync(cliBinary(root), [...args, '--json'], { cwd: root, encoding: 'utf8' }));
}
