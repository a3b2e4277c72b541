// End-to-end test of the ray lattice on the page and of lattice planning, in Debian's headless
// Chromium driven by playwright-core, against the built page (scripts/build-page.sh):
//   node tests/browser/e2e-lattice.mjs [PAGE_DIR]      (default: target/page)
// - the box preset's x–z lattice at y = 2 (pose fig310), 7 values per axis over x ∈ [0.2, 3.8],
//   z ∈ [0.3, 3.7] (thesis Fig. 3.10), its rays computed by Web Workers (as many as the machine
//   has cores, at most 8) and joined on the page: every ray's feasible pieces and
//   their components in the cross-section equal `cablenav lattice … --json` for the same request,
//   the component count too, and the 3-D view draws the lattice; Cancel stops a larger build;
// - lattice planning of cdpr7-box "over-box" in a worker: the page keeps drawing frames while it
//   runs (the frame times are recorded and reported, not asserted), the A* polyline and the
//   smoothed path are drawn, and the strip's sections of the planned trajectory equal
//   `cablenav verify` on the exported scenario with the plan; the same for Robocrane "q1-q2"
//   (with its wrench set);
// - the lattice planner's steps in the planning tab: 1 is refused with the core's error exactly as
//   `cablenav plan --planner lattice --steps 1` prints it, 9 gives the lattice and A* polyline of
//   `--steps 9`, and the steps and planner ride in the URL (a reload restores them).
// Ends with "N passed, M failed"; exits 1 on failure.

import { spawnSync } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { begin, cliBinary, cliJson, cliSections, cliVerify, frameStats, openTab, recordFrames, stopFrames, stripSections, watchProblems } from './harness.mjs';

const { root, artifacts, scratch, test, finish, base, browser, close } = await begin(import.meta.url, { watchdogMinutes: 10, scratch: 'cablenav-lattice-' });
const TIMEOUT = 60_000;
const PLAN_TIMEOUT = 240_000;

const context = await browser.newContext({ viewport: { width: 1366, height: 900 }, acceptDownloads: true });
const problems = watchProblems(context);
const page = await context.newPage();
await page.goto(`${base}/#preset=cdpr7-box`, { waitUntil: 'load' });
await page.waitForSelector('section[data-testid="result"][data-origin="cdpr7-box"] svg[data-testid="strip"]', { timeout: TIMEOUT });

/** Sets the lattice panel's request. */
async function request(pose, axes, ranges, steps) {
  await openTab(page, 'lattice');
  await page.selectOption('select[data-testid="lattice-pose"]', pose);
  for (let k = 0; k < 2; k++) {
    await page.selectOption(`select[data-testid="lattice-axis-${k}"]`, axes[k]);
    await page.fill(`input[data-testid="lattice-from-${k}"]`, String(ranges[k][0]));
    await page.dispatchEvent(`input[data-testid="lattice-from-${k}"]`, 'change');
    await page.fill(`input[data-testid="lattice-to-${k}"]`, String(ranges[k][1]));
    await page.dispatchEvent(`input[data-testid="lattice-to-${k}"]`, 'change');
  }
  await page.fill('input[data-testid="lattice-steps"]', String(steps));
  await page.dispatchEvent('input[data-testid="lattice-steps"]', 'change');
}

await test('the box preset\'s x–z lattice at y = 2 (7 steps), built in workers, equals `cablenav lattice`', async () => {
  const ranges = [[0.2, 3.8], [0.3, 3.7]];
  await request('fig310', ['x', 'z'], ranges, 7);
  await page.click('[data-testid="lattice-build"]');
  await page.waitForSelector('[data-testid="chart-lattice"] line[data-testid="lattice-ray"]', { state: 'attached', timeout: TIMEOUT });
  const lines = await page.$$eval('[data-testid="chart-lattice"] line[data-testid="lattice-ray"]', (ls) => ls.map((l) => ({
    component: l.dataset.component, from: l.dataset.from.split(',').map(Number), to: l.dataset.to.split(',').map(Number),
  })));
  const cli = cliJson(root, ['lattice', 'static/scenarios/cdpr7-box.json', '--pose', 'fig310', '--axes', 'x,z', '--range', '0.2', '3.8', '0.3', '3.7', '--steps', '7']);
  if (cli.rays.length !== 14) throw new Error(`the CLI gave ${cli.rays.length} rays`);
  const near = (a, b) => Math.abs(a - b) <= 1e-12 * Math.max(1, Math.abs(b));
  let pieces = 0;
  for (const [r, ray] of cli.rays.entries()) {
    // the page's stretches on this ray: along x at the ray's z, or along z at its x
    const along = ray.vary === 'x' ? 0 : 1;
    const at = along === 0 ? ray.fixed.z : ray.fixed.x;
    const mine = lines.filter((l) => l.from[1 - along] === l.to[1 - along] && near(l.from[1 - along], at) && l.from[along] !== l.to[along]);
    const feasible = mine.filter((l) => l.component !== 'none').map((l) => [l.from[along], l.to[along], Number(l.component)]).sort((a, b) => a[0] - b[0]);
    const want = ray.feasible.map((iv, p) => [iv[0], iv[1], cli.piece_components[r][p]]);
    const same = feasible.length === want.length && feasible.every((f, i) => near(f[0], want[i][0]) && near(f[1], want[i][1]) && f[2] === want[i][2]);
    if (!same) throw new Error(`ray ${r} (${ray.vary} at ${at}): page ${JSON.stringify(feasible)}\n  CLI ${JSON.stringify(want)}`);
    // the rest of the ray is drawn red, end to end
    const covered = mine.reduce((s, l) => s + Math.abs(l.to[along] - l.from[along]), 0);
    if (!near(covered, ranges[along][1] - ranges[along][0])) throw new Error(`ray ${r} covers ${covered} of its range`);
    pieces += mine.length;
  }
  if (pieces !== lines.length) throw new Error(`${lines.length - pieces} stretches on no CLI ray`);
  // Fig. 3.10: the x-ray at z = 0.8667 starts at x ≈ 2.002
  const fig = cli.rays.findIndex((r) => r.vary === 'x' && near(r.fixed.z, 0.3 + 3.4 / 6));
  if (!(Math.abs(cli.rays[fig].feasible[0][0] - 2.002) < 1e-3)) throw new Error(`x-ray at z = 0.8667 starts at ${cli.rays[fig].feasible[0][0]}`);
  const heading = await page.$eval('[data-testid="panel-lattice"]', (p) => p.textContent);
  const count = /(\d+) component\(s\)/.exec(heading)?.[1];
  if (Number(count) !== cli.components) throw new Error(`the panel says ${count} component(s), the CLI ${cli.components}`);
  const colours = new Set(lines.filter((l) => l.component !== 'none').map((l) => l.component));
  if (colours.size !== cli.components) throw new Error(`${colours.size} components drawn, the CLI has ${cli.components}`);
  // the 3-D view draws the feasible pieces (and, asked to, the infeasible ones too)
  const drawn = () => page.$eval('canvas[data-testid="view3d"]', (c) => Number(c.dataset.latticePieces));
  const feasibleCount = lines.filter((l) => l.component !== 'none').length;
  await page.waitForFunction((n) => Number(document.querySelector('canvas[data-testid="view3d"]').dataset.latticePieces) === n, feasibleCount, { timeout: TIMEOUT });
  await page.check('input[data-testid="lattice-infeasible-in-view"]');
  await page.waitForFunction((n) => Number(document.querySelector('canvas[data-testid="view3d"]').dataset.latticePieces) === n, lines.length, { timeout: TIMEOUT });
  await page.locator('canvas[data-testid="view3d"]').scrollIntoViewIfNeeded();
  await page.waitForTimeout(300);
  await page.locator('[data-testid="stage"]').screenshot({ path: join(artifacts, 'lattice-3d-box.png') });
  await (await page.$('[data-testid="chart-lattice"]')).screenshot({ path: join(artifacts, 'lattice-box-xz.png') });
  await page.uncheck('input[data-testid="lattice-in-view"]');
  await page.waitForFunction(() => document.querySelector('canvas[data-testid="view3d"]').dataset.latticePieces === '0', null, { timeout: TIMEOUT });
  await page.check('input[data-testid="lattice-in-view"]');
  problems.assertNone();
  return `${cli.rays.length} rays, ${lines.length} stretches (${feasibleCount} feasible), ${cli.components} component(s) as the CLI; x-ray at z = 0.8667 from x = ${cli.rays[fig].feasible[0][0].toFixed(4)}; 3-D view drew ${await drawn()} pieces`;
});

await test('Cancel stops a lattice build in its workers', async () => {
  // 2 × 1000 rays: many seconds of work in wasm
  await request('fig310', ['x', 'z'], [[0.2, 3.8], [0.3, 3.7]], 1000);
  await page.click('[data-testid="lattice-build"]');
  // as soon as the bar moves, Cancel, in the same task (no round trip for the build to end in)
  const { at, readout, state } = await page.evaluate(() => new Promise((ok) => {
    const poll = () => {
      const bar = document.querySelector('[data-testid="lattice-progress"]');
      const st = document.querySelector('[data-testid="lattice-state"]');
      if (st.dataset.state === 'running' && bar.value > 0) {
        const seen = { at: bar.value, readout: st.textContent.trim(), state: st.dataset.state };
        document.querySelector('[data-testid="lattice-cancel"]').click();
        ok(seen);
      } else if (document.querySelector('[data-testid="chart-lattice"] [data-testid="lattice-ray"]') && st.dataset.state === 'idle') {
        ok({ at: 1, readout: 'finished before Cancel', state: 'idle' });
      } else setTimeout(poll, 10);
    };
    poll();
  }));
  if (state !== 'running') throw new Error(`the build was not running when Cancel was pressed: ${readout}`);
  await page.waitForSelector('[data-testid="lattice-state"][data-state="idle"]', { state: 'attached', timeout: TIMEOUT });
  await page.waitForTimeout(500);
  if (await page.$('[data-testid="chart-lattice"]')) throw new Error('a lattice is shown after Cancel');
  if (await page.$eval('button[data-testid="lattice-build"]', (b) => b.disabled)) throw new Error('Build is still disabled after Cancel');
  problems.assertNone();
  return `stopped at ${(at * 100).toFixed(0)} % of 2000 rays (“${readout}”)`;
});

/** Plans `query` of the shown preset with the lattice planner in a worker, recording the frames
 * meanwhile; then the strip's sections of the planned trajectory must equal `cablenav verify` on
 * the exported scenario with the plan (and the 3-D view's too), and the A* polyline be drawn. */
async function planAndCompare(query, shot) {
  await openTab(page, 'planning');
  await page.selectOption('select[data-testid="planner"]', 'ray-lattice');
  await page.selectOption('select[data-testid="plan-query"]', query);
  await recordFrames(page, `document.querySelector('[data-testid="plan-status"]').dataset.state`);
  const started = Date.now();
  await page.click('[data-testid="plan-run"]');
  await page.waitForFunction(() => !['running', 'idle'].includes(document.querySelector('[data-testid="plan-status"]').dataset.state), null, { timeout: PLAN_TIMEOUT, polling: 100 });
  const seconds = (Date.now() - started) / 1000;
  await page.waitForTimeout(200);
  const { frames, states } = await stopFrames(page);
  const state = await page.getAttribute('[data-testid="plan-status"]', 'data-state');
  const status = (await page.textContent('[data-testid="plan-status"]')).trim();
  if (state !== 'found') throw new Error(`planning ended "${state}": ${status}`);
  // frame i is the gap since frame i − 1: the run's if it was running at either end
  const during = frames.filter((f, i) => states[i] === 'running' || (i > 0 && states[i - 1] === 'running'));
  const f = frameStats(during);
  writeFileSync(join(artifacts, `${shot}-frames.json`), JSON.stringify({ frames, states }));
  if (f.n < 3) throw new Error(`only ${f.n} frames drawn during a ${seconds.toFixed(1)} s run: the main thread was blocked`);
  // the strip shows the planned trajectory's exact sections; the 3-D view draws them and the A* polyline
  await page.waitForSelector('section[data-testid="result"][data-follow="planned"] svg[data-testid="strip"]', { timeout: TIMEOUT });
  const got = await stripSections(page);
  const view = (await page.getAttribute('canvas[data-testid="view3d"]', 'data-sections')).split(' ').filter(Boolean).map((x) => { const [kind, t0, t1] = x.split(':'); return { kind, t0: Number(t0), t1: Number(t1) }; });
  const polyline = Number(await page.getAttribute('canvas[data-testid="view3d"]', 'data-polyline-poses'));
  if (polyline < 2) throw new Error(`the A* polyline is not drawn (${polyline} poses)`);
  await openTab(page, 'exports');
  const download = page.waitForEvent('download');
  await page.click('[data-testid="export-planned-scenario"]');
  const file = join(scratch, `${shot}.json`);
  await (await download).saveAs(file);
  const exported = JSON.parse(readFileSync(file, 'utf8'));
  const traj = exported.trajectories[exported.trajectories.length - 1];
  const heading = await page.textContent('section[data-testid="result"] h2');
  if (!heading.includes(traj.name)) throw new Error(`the strip's heading "${heading}" does not name the planned trajectory "${traj.name}"`);
  const want = cliSections(cliVerify(root, file, traj.name));
  if (JSON.stringify(got) !== JSON.stringify(want)) throw new Error(`strip ${JSON.stringify(got)}\n  CLI ${JSON.stringify(want)}`);
  if (JSON.stringify(view) !== JSON.stringify(want)) throw new Error(`3-D view ${JSON.stringify(view)}\n  CLI ${JSON.stringify(want)}`);
  await page.locator('[data-testid="stage"]').screenshot({ path: join(artifacts, `${shot}.png`) });
  problems.assertNone();
  return `${seconds.toFixed(1)} s; ${status}; strip = CLI: ${want.map((s) => `${s.kind}[${s.t0}, ${s.t1}]`).join(' ')} (“${traj.name}”, ${traj.pieces?.length ?? 1} piece(s)); A* polyline ${polyline} poses; `
    + `frames while planning: ${f.n}, median ${f.median.toFixed(1)} ms, worst ${f.worst.toFixed(1)} ms, ${f.dropped} over 25 ms (recorded, not asserted)`;
}

await test('lattice planning of cdpr7-box "over-box" in a worker: the page keeps drawing; the strip equals `cablenav verify` on the exported plan', () => planAndCompare('over-box', 'lattice-plan-box'));

await test('the lattice planner\'s steps: 1 is refused with the CLI\'s error, 9 plans as `cablenav plan --steps 9`, and they ride in the URL', async () => {
  await openTab(page, 'planning');
  await page.selectOption('select[data-testid="planner"]', 'ray-lattice');
  await page.selectOption('select[data-testid="plan-query"]', 'over-box');
  const setSteps = async (n) => {
    await page.fill('input[data-testid="plan-steps"]', String(n));
    await page.dispatchEvent('input[data-testid="plan-steps"]', 'change');
  };
  const planned = async () => {
    await page.click('[data-testid="plan-run"]');
    await page.waitForFunction(() => !['running', 'idle'].includes(document.querySelector('[data-testid="plan-status"]').dataset.state), null, { timeout: PLAN_TIMEOUT, polling: 100 });
    return { state: await page.getAttribute('[data-testid="plan-status"]', 'data-state'), status: (await page.textContent('[data-testid="plan-status"]')).trim() };
  };
  const args = ['plan', 'static/scenarios/cdpr7-box.json', '--query', 'over-box', '--planner', 'lattice', '--steps'];
  // out of range: the core's error, as the CLI prints it
  await setSteps(1);
  const refused = await planned();
  const cli = spawnSync(cliBinary(root), [...args, '1'], { cwd: root, encoding: 'utf8' });
  const want = cli.stderr.trim().replace(/^cablenav: /, '');
  if (cli.status === 0 || !want.startsWith('--steps:')) throw new Error(`the CLI accepted --steps 1: ${cli.stdout} ${cli.stderr}`);
  if (refused.state !== 'error' || refused.status !== `The planner refused: ${want}`) throw new Error(`page: ${refused.state} "${refused.status}"; CLI: "${want}"`);
  // 9 steps: the lattice the CLI builds
  await setSteps(9);
  const ok = await planned();
  const ref = cliJson(root, [...args, '9']);
  const same = `${ref.rays} rays, ${ref.components} component(s)`;
  if (ok.state !== ref.status || !ok.status.includes(same) || !ok.status.includes(ref.message.slice(ref.message.indexOf('(lattice')))) throw new Error(`page: ${ok.state} "${ok.status}"; CLI: ${ref.status}, ${same}, ${ref.message}`);
  if (!ok.status.includes(`A* polyline: ${ref.polyline.length} points`)) throw new Error(`page: "${ok.status}"; CLI polyline of ${ref.polyline.length} points`);
  // the steps and the planner are in the address, and come back from it
  const hash = await page.evaluate(() => location.hash);
  if (!hash.endsWith('&tab=planning&planner=ray-lattice&steps=9')) throw new Error(`hash ${hash}`);
  await page.reload({ waitUntil: 'load' });
  await page.waitForSelector('[role="tabpanel"][data-testid="panel-planning"]:not([hidden]) input[data-testid="plan-steps"]', { timeout: TIMEOUT });
  const back = [await page.inputValue('input[data-testid="plan-steps"]'), await page.$eval('select[data-testid="planner"]', (s) => s.value)];
  if (back.join() !== '9,ray-lattice') throw new Error(`after a reload: steps and planner ${back}`);
  // the atlas has no steps: the field is disabled
  await page.selectOption('select[data-testid="planner"]', 'continuation');
  if (!(await page.$eval('input[data-testid="plan-steps"]', (i) => i.disabled))) throw new Error('the steps field is enabled for the atlas');
  await page.selectOption('select[data-testid="planner"]', 'ray-lattice');
  await setSteps(7);
  problems.assertNone();
  return `refused "${want}"; 9 steps: ${same} as the CLI; ${hash.slice(hash.indexOf('&'))} restored after a reload`;
});

await test('lattice planning of Robocrane "q1-q2" (with its wrench set) in a worker: the strip equals `cablenav verify` on the exported plan', async () => {
  await page.selectOption('select[data-testid="preset"]', 'robocrane');
  await page.waitForSelector('section[data-testid="result"][data-origin="robocrane"] svg[data-testid="strip"]', { timeout: TIMEOUT });
  await page.waitForFunction(() => !document.querySelector('[data-testid="plan-run"]').disabled, null, { timeout: TIMEOUT });
  return planAndCompare('q1-q2', 'lattice-plan-robocrane');
});

await close();
finish(`screenshots in ${artifacts}`);
