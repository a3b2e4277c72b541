// Browser smoke test of the built page (scripts/build-page.sh output), in Debian's headless
// Chromium driven by playwright-core.
//   node tests/browser/smoke.mjs [PAGE_DIR]      (default: target/page)
// Serves PAGE_DIR on 127.0.0.1 (a free port), opens it, and checks that the strip is drawn and
// covers [0, 1] for every preset and trajectory, that a bad scenario shows an error as text, and
// that the page also works inside an iframe; fails on any console error or page error.
// Screenshots go to tests/browser/artifacts/. Ends with "N passed, M failed"; exits 1 on failure.

import { mkdirSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { launchChromium, readSections, requirePage, runner, serve, watchProblems } from './harness.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const root = resolve(here, '..', '..');
const pageDir = resolve(root, process.argv[2] ?? process.env.PAGE_DIR ?? 'target/page');
const artifacts = join(here, 'artifacts');
const EPS = 1e-9;
const TIMEOUT = 60_000;

// A second page that embeds the app in an iframe.
const FRAME_HTML = `<!doctype html><html><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>cablenav in a frame</title></head>
<body style="margin:0;background:#eee"><p style="margin:8px">embedding page</p>
<iframe id="app" src="/index.html" style="width:1100px;height:760px;border:1px solid #999"></iframe></body></html>`;

// ---------- checks ----------
/** Throws unless `sections` is non-empty, well-formed and covers [0, 1] without gaps. */
function assertCover(sections, what) {
  if (sections.length === 0) throw new Error(`${what}: no section drawn`);
  for (const s of sections) {
    if (!['feasible', 'infeasible', 'uncertain'].includes(s.kind))
      throw new Error(`${what}: bad data-kind ${JSON.stringify(s.kind)}`);
    if (!Number.isFinite(s.t0) || !Number.isFinite(s.t1) || s.t0 > s.t1 + EPS)
      throw new Error(`${what}: bad section [${s.t0}, ${s.t1}]`);
  }
  const sorted = [...sections].sort((a, b) => a.t0 - b.t0);
  let reached = 0;
  for (const s of sorted) {
    if (s.t0 > reached + EPS) throw new Error(`${what}: gap in t between ${reached} and ${s.t0}`);
    reached = Math.max(reached, s.t1);
  }
  if (Math.abs(sorted[0].t0) > EPS) throw new Error(`${what}: starts at t = ${sorted[0].t0}, not 0`);
  if (reached < 1 - EPS) throw new Error(`${what}: ends at t = ${reached}, not 1`);
}

/** Waits until the result shows preset `origin` and trajectory `index`, then checks it. */
async function checkResult(scope, origin, index, what) {
  const sel = `section[data-testid="result"][data-origin="${origin}"][data-trajectory-index="${index}"] svg[data-testid="strip"]`;
  await scope.waitForSelector(sel, { timeout: TIMEOUT });
  const sections = await readSections(scope);
  assertCover(sections, what);
  // every boundary tick carries a tooltip naming t and the constraint
  // (an SVG <title>, in the SVG namespace, is what browsers show as a tooltip)
  const SVG_NS = 'http://www.w3.org/2000/svg';
  const ticks = await scope.$$eval('svg[data-testid="strip"] [data-testid="boundary"]', (gs, ns) =>
    gs.map((g) => {
      const t = g.querySelector('title');
      return t && t.namespaceURI === ns ? t.textContent : `<no SVG title: ${t ? t.namespaceURI : 'none'}>`;
    }), SVG_NS,
  );
  for (const title of ticks) {
    if (!/^t = \S+ \(τ = \S+\): .+ — enters (feasible|infeasible)$/.test(title))
      throw new Error(`${what}: bad boundary tooltip ${JSON.stringify(title)}`);
  }
  const rows = await scope.$$eval('table[data-testid="intervals"] tbody tr', (trs) => trs.length);
  if (rows !== sections.length) throw new Error(`${what}: ${rows} table rows for ${sections.length} sections`);
  return { sections: sections.length, ticks: ticks.length };
}

async function optionValues(scope, testid) {
  return scope.$$eval(`select[data-testid="${testid}"] option`, (os) => os.map((o) => [o.value, o.textContent.trim()]));
}

// ---------- run ----------
mkdirSync(artifacts, { recursive: true });
requirePage(pageDir);
const { test, finish } = runner(10);
const server = await serve(pageDir, { '/__frame.html': FRAME_HTML });
const base = `http://127.0.0.1:${server.address().port}`;
const browser = await launchChromium();
const context = await browser.newContext({ viewport: { width: 1200, height: 900 } });
const problems = watchProblems(context); // console errors and page errors, from any page or frame
/** Throws if console or page errors were seen since the last call. */
function assertNoProblems() {
  problems.assertNone();
}

const page = await context.newPage();

await test('page loads and draws the first preset', async () => {
  await page.goto(`${base}/`, { waitUntil: 'load' });
  // 'load' fires once the HTML and its scripts are in; the app mounts after the wasm has
  // compiled, so wait for the preset list it renders before reading it
  await page.waitForSelector('select[data-testid="preset"] option', { state: 'attached', timeout: TIMEOUT });
  const presets = await optionValues(page, 'preset');
  if (presets.length < 3) throw new Error(`only ${presets.length} presets: ${presets}`);
  const r = await checkResult(page, presets[0][0], 0, `${presets[0][0]} #0`);
  await page.screenshot({ path: join(artifacts, 'page.png'), fullPage: true });
  assertNoProblems();
  return `${r.sections} sections, ${r.ticks} boundaries`;
});

await test('every preset and trajectory covers [0, 1]', async () => {
  const presets = await optionValues(page, 'preset');
  const done = [];
  for (const [id] of presets) {
    await page.selectOption('select[data-testid="preset"]', id);
    await checkResult(page, id, 0, `${id} #0`);
    const trajectories = await optionValues(page, 'trajectory');
    for (const [index, name] of trajectories) {
      await page.selectOption('select[data-testid="trajectory"]', index);
      await checkResult(page, id, index, `${id} / ${name}`);
      done.push(`${id}/${name}`);
    }
    await page.screenshot({ path: join(artifacts, `preset-${id}.png`), fullPage: true });
  }
  assertNoProblems();
  return `${done.length} trajectories`;
});

await test('a bad scenario shows its error as text', async () => {
  await page.selectOption('select[data-testid="preset"]', (await optionValues(page, 'preset'))[0][0]);
  await page.click('details.editor summary');
  await page.fill('textarea[data-testid="source"]', '{ "format": "cablenav-scenario/1", "name": ');
  await page.click('button[data-testid="apply"]');
  const error = await page.waitForSelector('[data-testid="error"]', { timeout: TIMEOUT });
  const text = (await error.textContent()).trim();
  if (!text) throw new Error('empty error text');
  if (await page.$('svg[data-testid="strip"]')) throw new Error('strip still drawn for a bad scenario');
  await page.screenshot({ path: join(artifacts, 'error.png'), fullPage: true });
  // and it recovers
  const first = (await optionValues(page, 'preset'))[1][0];
  await page.selectOption('select[data-testid="preset"]', first);
  await checkResult(page, first, 0, `${first} after an error`);
  assertNoProblems();
  return JSON.stringify(text.slice(0, 100));
});

await test('the page works inside an iframe', async () => {
  const host = await context.newPage();
  await host.goto(`${base}/__frame.html`, { waitUntil: 'load' });
  const frame = await (await host.waitForSelector('iframe#app')).contentFrame();
  const presets = await optionValues(frame, 'preset');
  const r = await checkResult(frame, presets[0][0], 0, 'in an iframe');
  await host.screenshot({ path: join(artifacts, 'iframe.png') });
  await host.close();
  assertNoProblems();
  return `${r.sections} sections`;
});

await browser.close();
server.close();
finish(`screenshots in ${artifacts}`);
