// The page's first load on a throttled network, in Debian's headless Chromium.
//   node tests/browser/first-load.mjs [PAGE_DIR]      (default: target/page)
// Serves PAGE_DIR gzip-compressed (as a static host does), opens it in a fresh browser context
// (empty cache) under Lighthouse's "slow 4G" profile (1.6 Mbit/s down, 750 kbit/s up, 150 ms round
// trip), and waits for the first preset's feasibility strip. Checks that the wasm and its JS glue
// cross the wire in at most 1.0 MB (the page weight target, docs/benchmarks.md) and prints the
// time to the strip and the bytes by kind. Ends with "N passed, M failed"; exits 1 on failure.

import { dirname, extname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { launchChromium, requirePage, runner, serve, watchProblems } from './harness.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const root = resolve(here, '..', '..');
const pageDir = resolve(root, process.argv[2] ?? process.env.PAGE_DIR ?? 'target/page');

/** Lighthouse's simulated mobile network ("slow 4G"), in the units CDP takes (bytes/s, ms). */
const PROFILE = {
  name: 'slow 4G (1.6 Mbit/s down, 750 kbit/s up, 150 ms round trip)',
  latency: 150,
  downloadThroughput: 1.6e6 / 8,
  uploadThroughput: 750e3 / 8,
};
/** The page weight target: the wasm and its JS glue, compressed, in bytes. */
const WEIGHT_LIMIT = 1_000_000;
const TIMEOUT = 120_000;

requirePage(pageDir);
const { test, finish } = runner(5);
const server = await serve(pageDir);
const base = `http://127.0.0.1:${server.address().port}`;
const browser = await launchChromium();

await test(`first load on ${PROFILE.name}`, async () => {
  const context = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const problems = watchProblems(context);
  const page = await context.newPage();
  const cdp = await context.newCDPSession(page);
  await cdp.send('Network.enable');
  await cdp.send('Network.emulateNetworkConditions', {
    offline: false,
    latency: PROFILE.latency,
    downloadThroughput: PROFILE.downloadThroughput,
    uploadThroughput: PROFILE.uploadThroughput,
  });
  const responses = [];
  page.on('response', (r) => responses.push(r));

  await page.goto(`${base}/`, { waitUntil: 'commit' });
  await page.waitForSelector('section[data-testid="result"] svg[data-testid="strip"]', { timeout: TIMEOUT });
  const stripMs = await page.evaluate(() => performance.now());
  problems.assertNone();

  const wire = { wasm: 0, js: 0, other: 0 };
  let wasmEncoding = null;
  for (const r of responses) {
    const { responseBodySize } = await r.request().sizes();
    const ext = extname(new URL(r.url()).pathname);
    const kind = ext === '.wasm' ? 'wasm' : ext === '.js' ? 'js' : 'other';
    wire[kind] += responseBodySize;
    if (kind === 'wasm') wasmEncoding = (await r.allHeaders())['content-encoding'] ?? 'none';
  }
  await context.close();
  if (wasmEncoding !== 'gzip') throw new Error(`the wasm was sent with content-encoding ${wasmEncoding}, not gzip`);
  const weight = wire.wasm + wire.js;
  if (weight > WEIGHT_LIMIT) throw new Error(`wasm + js crossed the wire in ${weight} B, over the ${WEIGHT_LIMIT} B target`);
  return `strip drawn at ${(stripMs / 1000).toFixed(2)} s after navigation; over the wire: wasm ${wire.wasm} B, js ${wire.js} B, `
    + `other ${wire.other} B (wasm + js ${weight} B ≤ ${WEIGHT_LIMIT} B)`;
});

await browser.close();
server.close();
finish();
