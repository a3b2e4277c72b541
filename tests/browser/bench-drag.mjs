// Benchmark (not a test): the cost of one drag update in the page (wasm, headless Chromium) —
// moving a via point of each cdpr7-tree trajectory, rewriting the scenario, re-verifying the
// trajectory exactly and rebuilding the 3-D scene, as the page times it (`data-update-ms` of the
// "Move" bar) — and the animation frames while dragging. Prints a Markdown section for
// docs/benchmarks.md (scripts/bench.sh appends it).
//   node tests/browser/bench-drag.mjs [PAGE_DIR] [STEPS]      (default: target/page, 60)

import { cpus, loadavg } from 'node:os';
import { resolve, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { launchChromium, requirePage, serve } from './harness.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const pageDir = resolve(here, '..', '..', process.argv[2] ?? 'target/page');
const STEPS = Number(process.argv[3] ?? 60);
const TARGET_MS = 5;
requirePage(pageDir);
const server = await serve(pageDir);
const browser = await launchChromium();
const page = await (await browser.newContext({ viewport: { width: 1366, height: 768 } })).newPage();
await page.goto(`http://127.0.0.1:${server.address().port}/#preset=cdpr7-tree`, { waitUntil: 'load' });
await page.waitForSelector('svg[data-testid="strip"]');

const q = (xs, p) => { const s = [...xs].sort((a, b) => a - b); return s[Math.min(s.length - 1, Math.floor(p * s.length))]; };
const rows = [];
const names = await page.$$eval('select[data-testid="trajectory"] option', (os) => os.map((o) => [o.value, o.textContent.trim()]));
for (const [index, name] of names) {
  await page.selectOption('select[data-testid="trajectory"]', index);
  await page.waitForSelector(`section[data-testid="result"][data-trajectory-index="${index}"]`);
  const labels = await page.$$eval('select[data-testid="handle"] option', (os) => os.map((o) => o.textContent.trim()));
  const k = labels.findIndex((l) => l.startsWith(`via point 2 of “${name}”`)) - 1;
  const canvas = page.locator('canvas[data-testid="view3d"]');
  await page.waitForFunction((k) => (document.querySelector('canvas[data-testid="view3d"]').dataset.handlePx ?? '').split(' ').length > k, k);
  const box = await canvas.boundingBox();
  const [hx, hy] = (await canvas.getAttribute('data-handle-px')).split(' ')[k].split(',').map(Number);
  await page.evaluate(() => { window.__f = []; window.__on = true; let l = performance.now(); const t = (n) => { window.__f.push(n - l); l = n; if (window.__on) requestAnimationFrame(t); }; requestAnimationFrame(t); });
  const updates = [];
  const verifies = [];
  await page.mouse.move(box.x + hx, box.y + hy);
  await page.mouse.down();
  for (let i = 1; i <= STEPS; i++) {
    await page.mouse.move(box.x + hx + 2 * i, box.y + hy + 1.5 * i);
    updates.push(Number(await page.getAttribute('[data-testid="handle-readout"]', 'data-update-ms')));
    const v = await page.getAttribute('[data-testid="handle-readout"]', 'data-verify-ms');
    if (v) verifies.push(Number(v));
  }
  // the frames while the pointer moves, then (recording on) the release: the page verifies the
  // final scenario itself and the form, link, address and autosave follow
  const frames = (await page.evaluate(() => { const f = window.__f; window.__f = []; return f; })).slice(1);
  await page.mouse.up();
  await page.waitForTimeout(500);
  const release = await page.evaluate(() => { window.__on = false; return Math.max(...window.__f); });
  rows.push({ name, updates, verifies, frames, release });
  await page.click('[data-testid="reset-preset"]');
  await page.waitForSelector('section[data-testid="result"][data-origin="cdpr7-tree"]');
}

// The same pointer moves on an empty corner of the view (an orbit: the camera moves, the scene is
// redrawn, nothing is edited, verified or rebuilt), and frames with no input at all: what the
// frames cost without the page's own work, in this browser's software WebGL.
const frameLoop = () => page.evaluate(() => { window.__f = []; window.__on = true; let l = performance.now(); const t = (n) => { window.__f.push(n - l); l = n; if (window.__on) requestAnimationFrame(t); }; requestAnimationFrame(t); });
const frameStop = async () => (await page.evaluate(() => { window.__on = false; return window.__f; })).slice(1);
const box = await page.locator('canvas[data-testid="view3d"]').boundingBox();
await frameLoop();
await page.mouse.move(box.x + 12, box.y + box.height - 12);
await page.mouse.down();
for (let i = 1; i <= STEPS; i++) {
  await page.mouse.move(box.x + 12 + 2 * i, box.y + box.height - 12 - 1.5 * i);
  await page.getAttribute('[data-testid="handle-readout"]', 'data-update-ms');
}
await page.mouse.up();
const orbit = await frameStop();
await frameLoop();
await page.waitForTimeout(2000);
const still = await frameStop();
await browser.close();
server.close();

const fmt = (x) => x.toFixed(2);
console.log(`
## Dragging in the page (wasm)

One drag update in the page, headless Chromium (\`node tests/browser/bench-drag.mjs PAGE_DIR\`): a via
point of each cdpr7-tree trajectory dragged by ${STEPS} pointer moves. Each update rewrites the
scenario and rebuilds the 3-D scene on the main thread ("update", timed by the page itself), while
a Web Worker re-verifies the trajectory exactly ("exact verification", the worker's own time; the
newest scenario is sent whenever the worker is free: \`web/src/live.rs\`); the plots, the
editor's form, the share link, the address and the autosave follow at the end of the drag
(\`Quiet\` in web/src/state.rs), when the page verifies the final scenario itself. Machine: ${cpus().length} × ${cpus()[0]?.model ?? '?'}, load average
${loadavg()[0].toFixed(1)} while measuring (frame times include software WebGL, SwiftShader).

| trajectory | update median | update p90 | update worst | exact verification in the worker: median, p90, worst | frames median | frames p90 | frames over 25 ms (dropped at 60 Hz) | longest frame at the release | target ≤ ${TARGET_MS} ms per update (median) |
|---|---|---|---|---|---|---|---|---|---|
${rows.map((r) => `| cdpr7-tree "${r.name}" | ${fmt(q(r.updates, 0.5))} ms | ${fmt(q(r.updates, 0.9))} ms | ${fmt(Math.max(...r.updates))} ms | ${r.verifies.length ? `${fmt(q(r.verifies, 0.5))}, ${fmt(q(r.verifies, 0.9))}, ${fmt(Math.max(...r.verifies))} ms` : '—'} | ${fmt(q(r.frames, 0.5))} ms | ${fmt(q(r.frames, 0.9))} ms | ${r.frames.filter((f) => f > 25).length} of ${r.frames.length} | ${fmt(r.release)} ms | ${q(r.updates, 0.5) <= TARGET_MS ? 'met' : '**missed**'} |`).join('\n')}
${[['orbiting the view (same pointer moves; redraw only)', orbit], ['no input (2 s)', still]].map(([what, f]) => `| ${what} | — | — | — | — | ${fmt(q(f, 0.5))} ms | ${fmt(q(f, 0.9))} ms | ${f.filter((x) => x > 25).length} of ${f.length} | — | — |`).join('\n')}

"Frames" are those while the pointer moves; the release (the page's own final verification, then
the deferred form, link, address and autosave) is timed apart. The last two rows are the frames
without the page's own work: where they drop as many frames as the drags, the drops are the
browser's software rendering (SwiftShader draws and reads back the canvas on the CPU, on the same
two cores as the page and its worker), not the update.`);
