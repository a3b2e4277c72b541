// Benchmark (not a test): the page's main thread when a plan starts and when its result comes
// back — cdpr7-box "over-box" planned by the lattice planner in a worker, after the x–z lattice
// of the box preset (pose fig310, 7 values per axis) was built and drawn in the 3-D view with its
// infeasible pieces (as tests/browser/e2e-lattice.mjs leaves the page). For each page given,
// alternately (so the machine's load falls on all alike), ROUNDS fresh pages each plan once; the
// page's animation frames are recorded, and Chromium's long-animation-frame entries (frames over
// 50 ms: their script and rendering time) and the 3-D view's redraws are counted. Prints a
// Markdown section for docs/benchmarks.md.
//   node tests/browser/bench-plan-frames.mjs PAGE_DIR [OTHER_PAGE_DIR …]   (ROUNDS=5 by default)
// DEBUG=1 prints each round's figures (with the long frames' scripts) to stderr; PROFILE=FILE writes
// the main thread's CPU profile of the last round's plan to FILE (.cpuprofile, for DevTools).

import { cpus, loadavg } from 'node:os';
import { resolve, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { launchChromium, recordFrames, requirePage, serve, stopFrames } from './harness.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const dirs = (process.argv.length > 2 ? process.argv.slice(2) : ['target/page']).map((d) => resolve(here, '..', '..', d));
const ROUNDS = Number(process.env.ROUNDS ?? 5);
dirs.forEach(requirePage);
const servers = await Promise.all(dirs.map((d) => serve(d)));
const browser = await launchChromium();
const TIMEOUT = 120_000;

/** Opens results tab `id` if the page has tabs (older pages show every panel). */
async function tab(page, id) {
  if (await page.$('.tablist')) await page.click(`.tablist [role="tab"][data-tab="${id}"]`);
}

/** One plan on a fresh page: frames and long animation frames at Plan and at the result. */
async function round(base) {
  const context = await browser.newContext({ viewport: { width: 1366, height: 900 } });
  const page = await context.newPage();
  await page.goto(`${base}/#preset=cdpr7-box`, { waitUntil: 'load' });
  await page.waitForSelector('section[data-testid="result"][data-origin="cdpr7-box"] svg[data-testid="strip"]', { timeout: TIMEOUT });
  await tab(page, 'lattice');
  await page.selectOption('select[data-testid="lattice-pose"]', 'fig310');
  for (const [k, axis, [lo, hi]] of [[0, 'x', [0.2, 3.8]], [1, 'z', [0.3, 3.7]]]) {
    await page.selectOption(`select[data-testid="lattice-axis-${k}"]`, axis);
    for (const [end, v] of [['from', lo], ['to', hi]]) {
      await page.fill(`input[data-testid="lattice-${end}-${k}"]`, String(v));
      await page.dispatchEvent(`input[data-testid="lattice-${end}-${k}"]`, 'change');
    }
  }
  await page.click('[data-testid="lattice-build"]');
  await page.waitForSelector('[data-testid="chart-lattice"] line[data-testid="lattice-ray"]', { state: 'attached', timeout: TIMEOUT });
  await page.check('input[data-testid="lattice-infeasible-in-view"]');
  await tab(page, 'planning');
  await page.selectOption('select[data-testid="planner"]', 'ray-lattice');
  await page.selectOption('select[data-testid="plan-query"]', 'over-box');
  await page.waitForTimeout(500);
  await page.evaluate(() => {
    window.__loaf = [];
    new PerformanceObserver((list) => {
      for (const e of list.getEntries()) {
        const script = e.scripts.reduce((s, x) => s + x.duration, 0);
        window.__loaf.push({ start: e.startTime, duration: e.duration, script, render: e.renderStart ? e.startTime + e.duration - e.renderStart : 0, who: e.scripts.map((x) => `${x.invoker}:${x.duration.toFixed(0)}`).join(' ') });
      }
    }).observe({ type: 'long-animation-frame' });
  });
  // each frame's run state and the 3-D view's redraw count so far
  await recordFrames(page, `document.querySelector('[data-testid="plan-status"]').dataset.state + ' ' + document.querySelector('canvas[data-testid="view3d"]').dataset.draws`);
  const cdp = process.env.PROFILE ? await context.newCDPSession(page) : null;
  if (cdp) { await cdp.send('Profiler.enable'); await cdp.send('Profiler.setSamplingInterval', { interval: 100 }); await cdp.send('Profiler.start'); }
  const clicked = await page.evaluate(() => performance.now());
  await page.click('[data-testid="plan-run"]');
  await page.waitForFunction(() => document.querySelector('[data-testid="plan-status"]').dataset.state === 'running', null, { timeout: TIMEOUT, polling: 'raf' });
  const ended = await page.waitForFunction(() => {
    const s = document.querySelector('[data-testid="plan-status"]').dataset.state;
    return s !== 'running' && s !== 'idle' ? [s, performance.now()] : false;
  }, null, { timeout: TIMEOUT, polling: 'raf' }).then((h) => h.jsonValue());
  if (ended[0] !== 'found') throw new Error(`planning ended ${ended[0]}`);
  await page.waitForTimeout(800);
  if (cdp) { const { profile } = await cdp.send('Profiler.stop'); (await import('node:fs')).writeFileSync(process.env.PROFILE, JSON.stringify(profile)); }
  const recorded = await stopFrames(page);
  const frames = recorded.frames;
  const states = recorded.states.map((s) => s.split(' ')[0]);
  const draws = recorded.states.map((s) => Number(s.split(' ')[1]));
  const loaf = await page.evaluate(() => window.__loaf);
  await context.close();
  const start = states.indexOf('running');
  const end = states.findIndex((s, i) => i > start && s === 'found');
  // redraws from the frame before Plan to the last running frame, and from there to the end
  const [d0, d1, d2] = [draws[Math.max(0, start - 1)], draws[end - 1], draws[draws.length - 1]];
  const worst = (xs) => Math.max(0, ...xs);
  // frame i is the gap since frame i − 1; the run's state is read at frame i's callback
  const atPlan = worst(frames.slice(Math.max(0, start - 1), start + 3));
  const atResult = worst(frames.slice(Math.max(0, end - 1), end + 10));
  const loafAt = (t0, t1) => loaf.filter((e) => e.start + e.duration >= t0 && e.start <= t1);
  const planLoaf = loafAt(clicked, clicked + 300);
  const resultLoaf = loafAt(ended[1] - 100, ended[1] + 800);
  if (process.env.DEBUG) console.error(JSON.stringify({ atPlan, atResult, planLoaf, resultLoaf }));
  return { atPlan, atResult, planLoaf, resultLoaf, drawsAtPlan: d1 - d0, drawsAfter: d2 - d1 };
}

const results = dirs.map(() => []);
for (let r = 0; r < ROUNDS; r++) {
  for (const [k, server] of servers.entries()) results[k].push(await round(`http://127.0.0.1:${server.address().port}`));
}
await browser.close();
servers.forEach((s) => s.close());

const median = (xs) => { const s = [...xs].sort((a, b) => a - b); return s.length ? s[Math.floor(s.length / 2)] : NaN; };
const f = (x) => (Number.isFinite(x) ? x.toFixed(0) : '—');
const sum = (es, key) => es.reduce((s, e) => s + e[key], 0);
const load = loadavg()[0].toFixed(1);
console.log(`
## Planning in the page: the main thread at Plan and at the result

\`node tests/browser/bench-plan-frames.mjs ${process.argv.slice(2).join(' ')}\` (ROUNDS=${ROUNDS}): cdpr7-box "over-box" planned by
the lattice planner in a worker, on a fresh page each round, after the box preset's x–z lattice
was built and drawn in the 3-D view (infeasible pieces included); the pages alternate round by
round. "Frame" is the longest animation frame around the click on Plan (its first 3 frames) and
around the result (its first 10 frames); "long frames" are Chromium's long-animation-frame
entries (over 50 ms) there, with the script and the rendering (style, layout, paint and the
compositor commit, which reads back the software-rendered WebGL canvas) in them, summed over the
rounds. Machine: ${cpus().length} × ${cpus()[0]?.model.trim()}, load average ${load} when the run ended; headless Chromium
with SwiftShader (software WebGL): a redrawn 3-D view costs tens of milliseconds here that a GPU
does not.

| page | frame at Plan (median, worst) | frame at the result (median, worst) | long frames at Plan: count, script, rendering | long frames at the result: count, script, rendering | 3-D redraws at Plan / at the result (median) |
|---|---|---|---|---|---|`);
for (const [k, rs] of results.entries()) {
  const pl = rs.flatMap((r) => r.planLoaf);
  const rl = rs.flatMap((r) => r.resultLoaf);
  console.log(`| ${process.argv[2 + k] ?? 'target/page'} | ${f(median(rs.map((r) => r.atPlan)))} ms, ${f(Math.max(...rs.map((r) => r.atPlan)))} ms | ${f(median(rs.map((r) => r.atResult)))} ms, ${f(Math.max(...rs.map((r) => r.atResult)))} ms | ${pl.length}, ${f(sum(pl, 'script'))} ms, ${f(sum(pl, 'render'))} ms | ${rl.length}, ${f(sum(rl, 'script'))} ms, ${f(sum(rl, 'render'))} ms | ${median(rs.map((r) => r.drawsAtPlan))} / ${median(rs.map((r) => r.drawsAfter))} |`);
}
