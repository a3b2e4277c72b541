// End-to-end test of timed trajectories and the platform's mass on the page (scenario format 4,
// docs/dynamics.md), in Debian's headless Chromium driven by playwright-core, against the built
// page (scripts/build-page.sh):
//   node tests/browser/e2e-timing.mjs [PAGE_DIR]      (default: target/page)
// - the timed Robocrane preset: for each trajectory the strip equals `cablenav verify`, and the
//   Intervals tab shows its sections in seconds and the shortest certified duration of the CLI's
//   `seconds` report;
// - a trajectory's duration typed in the editor: the format becomes 4, the sections and the
//   timing follow (against the CLI on the page's own scenario text); a duration of 0 stays in
//   its field with a message and is not written;
// - the tension envelope of a timed trajectory: its axis in seconds, its tensions with the
//   platform's inertia (the CLI's `envelope`);
// - "Make it a timed spline": a trajectory becomes a quintic spline through knots (its start and
//   end poses, at rest), edited knot by knot, verified as the CLI verifies the page's text;
// - "Give the platform a mass" on the 7-cable preset: the mass section appears, the format becomes
//   4, and a mass typed there changes what the page verifies as the CLI does;
// - "Fastest safe timing" of the swing: Cancel, then the certified duration, the binding
//   stretches and the plot against `cablenav time`.
// Screenshots in tests/browser/artifacts/. Ends with "N passed, M failed"; exits 1 on failure.

import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { begin, cliJson, cliSections, openTab, stripSections, watchProblems } from './harness.mjs';

const { root, artifacts, scratch, test, finish, base, browser, close } = await begin(import.meta.url, { watchdogMinutes: 8, scratch: 'cablenav-timing-' });
const TIMEOUT = 60_000;
const TIMED = 'static/scenarios/robocrane-timed.json';

const context = await browser.newContext({ viewport: { width: 1366, height: 900 } });
const problems = watchProblems(context);
const page = await context.newPage();
await page.goto(`${base}/#preset=robocrane-timed`, { waitUntil: 'load' });
await page.waitForSelector('section[data-testid="result"][data-origin="robocrane-timed"] svg[data-testid="strip"]', { timeout: TIMEOUT });
await openTab(page, 'intervals');

const field = (path) => `[data-field="${path}"]`;
const source = () => page.$eval('textarea[data-testid="source"]', (t) => t.value);

async function open(summary) {
  const details = page.locator('[data-testid="scenario-editor"] details').filter({ has: page.locator('summary', { hasText: summary }) }).first();
  if (!(await details.evaluate((d) => d.open))) await details.locator('summary').first().click();
}

async function typeInto(selector, text) {
  const input = page.locator(selector);
  await input.click();
  await input.press('Control+a');
  await input.pressSequentially(text);
}

/** The CLI's verify report of the page's current scenario text. */
async function cliOfPage(trajectory) {
  const file = join(scratch, 'page.json');
  writeFileSync(file, await source());
  return cliJson(root, ['verify', file, '--trajectory', trajectory]);
}

/** The page's strip and timing equal the CLI report `cli`. */
async function sameAsCli(cli, what) {
  const got = await stripSections(page);
  const want = cliSections(cli);
  if (got.length !== want.length || got.some((s, i) => s.kind !== want[i].kind || Math.abs(s.t0 - want[i].t0) > 1e-12 || Math.abs(s.t1 - want[i].t1) > 1e-12)) {
    throw new Error(`${what}: strip ${JSON.stringify(got)} vs CLI ${JSON.stringify(want)}`);
  }
  const minDuration = await page.getAttribute('[data-testid="time-scale"]', 'data-min-duration');
  const expected = cli.seconds.min_duration;
  if (expected === null ? minDuration !== '' : Math.abs(Number(minDuration) - expected) > 1e-12) {
    throw new Error(`${what}: page's shortest duration "${minDuration}" vs CLI ${expected}`);
  }
  const rows = await page.$$eval('table[data-testid="seconds"] tbody tr', (trs) => trs.length);
  const count = cli.seconds.feasible.length + cli.seconds.infeasible.length + cli.seconds.uncertain.length;
  if (rows !== count) throw new Error(`${what}: ${rows} rows in seconds, CLI ${count}`);
  return { sections: want.length, minDuration: expected };
}

await test('the timed Robocrane: strip, sections in seconds and the shortest duration equal `cablenav verify`', async () => {
  const names = JSON.parse(await source()).trajectories.map((t) => t.name);
  const out = [];
  for (const [i, name] of names.entries()) {
    await page.selectOption('select[data-testid="trajectory"]', String(i));
    await page.waitForSelector(`section[data-testid="result"][data-trajectory-index="${i}"]`, { timeout: TIMEOUT });
    await page.waitForSelector(`[data-testid="timing"][data-trajectory="${name}"]`, { timeout: TIMEOUT });
    const cli = await cliOfPage(name);
    const r = await sameAsCli(cli, name);
    const summary = await page.textContent('[data-testid="time-scale"]');
    if (!summary.includes(cli.seconds.min_time_scale_note)) throw new Error(`${name}: the page does not give the CLI's note: ${summary}`);
    out.push(`${name}: ${r.sections} sections, shortest ${r.minDuration?.toFixed(4)} s`);
  }
  await page.screenshot({ path: join(artifacts, 'timing-preset.png'), fullPage: true });
  problems.assertNone();
  return out.join('; ');
});

await test('the tension envelope of a timed trajectory: axis in seconds, inertia included as `cablenav envelope` has it', async () => {
  const names = JSON.parse(await source()).trajectories.map((t) => t.name);
  const swing = names.indexOf('swing');
  await page.selectOption('select[data-testid="trajectory"]', String(swing));
  await page.waitForSelector(`section[data-testid="result"][data-trajectory-index="${swing}"]`, { timeout: TIMEOUT });
  await openTab(page, 'tension');
  await page.waitForFunction(() => (document.querySelector('[data-testid="tension-axis"]')?.textContent ?? '').startsWith('time'), null, { timeout: TIMEOUT });
  const ticks = await page.$$eval('[data-testid="tension-tick"]', (ts) => ts.slice(0, 3).map((t) => t.textContent));
  if (ticks.join('|') !== '0 s|0.4 s|0.8 s') throw new Error(`ticks ${ticks}`);
  const file = join(scratch, 'page.json');
  writeFileSync(file, await source());
  const env = cliJson(root, ['envelope', file, '--trajectory', 'swing', '--samples', '200']);
  const violated = env.tension_min.some((m, k) => m && m.some((v, i) => v < env.bounds[i][0])) || env.tension_max.some((m) => m && m.some((v, i) => v > env.bounds[i][1]));
  const panels = await page.$$eval('[data-testid="tension-panel"]', (ps) => ps.map((p) => p.dataset.violated === 'true'));
  if (panels.length !== 6 || panels.some(Boolean) !== violated) throw new Error(`panels ${panels} vs CLI violated ${violated}`);
  await page.screenshot({ path: join(artifacts, 'timing-tension.png'), fullPage: true });
  await openTab(page, 'intervals');
  return `ticks ${ticks.join(', ')}; bounds left ${violated ? 'somewhere' : 'nowhere'}, as the CLI's envelope says`;
});

await test('the fastest safe timing of `swing`: certified duration, binding stretches and plot as `cablenav time` gives them; Cancel stops it', async () => {
  // the swing is selected (the previous test) and the Intervals tab open
  await page.waitForSelector('[data-testid="fastest-run"]', { timeout: TIMEOUT });
  // Cancel right after starting: no result, the status says so
  await page.click('[data-testid="fastest-run"]');
  await page.click('[data-testid="fastest-cancel"]', { timeout: TIMEOUT });
  await page.waitForFunction(() => document.querySelector('[data-testid="fastest-status"]')?.textContent === 'cancelled', null, { timeout: TIMEOUT });
  if (await page.$('[data-testid="fastest"]')) throw new Error('a result after Cancel');
  await page.click('[data-testid="fastest-run"]');
  await page.waitForSelector('[data-testid="fastest"][data-trajectory="swing"]', { timeout: TIMEOUT });
  const file = join(scratch, 'page.json');
  writeFileSync(file, await source());
  const cli = cliJson(root, ['time', file, '--trajectory', 'swing']);
  const duration = Number(await page.getAttribute('[data-testid="fastest"]', 'data-duration'));
  const uncertified = Number(await page.getAttribute('[data-testid="fastest"]', 'data-uncertified'));
  // wasm's sin and cos may differ from the native build's in the last bit: equal to 1e-9
  if (Math.abs(duration - cli.duration) > 1e-9 * cli.duration) throw new Error(`page ${duration} s, CLI ${cli.duration} s`);
  if (Math.abs(uncertified - cli.uncertified_duration) > 1e-9 * cli.duration) throw new Error(`uncertified: page ${uncertified}, CLI ${cli.uncertified_duration}`);
  const rows = await page.$$eval('table[data-testid="fastest-binding"] tbody tr', (trs) => trs.map((tr) => tr.lastElementChild.textContent));
  if (rows.join('|') !== cli.binding.map((b) => b.constraint).join('|')) throw new Error(`binding: page ${rows}, CLI ${cli.binding.map((b) => b.constraint)}`);
  const bands = await page.$$eval('[data-testid="chart-fastest"] [data-testid="binding-band"]', (bs) => bs.length);
  const panels = await page.$$eval('[data-testid="chart-fastest"] [data-testid="fastest-panel"] path', (ps) => ps.length);
  if (bands !== cli.binding.length || panels !== 1 + 6) throw new Error(`${bands} bands, ${panels} lines`);
  await page.screenshot({ path: join(artifacts, 'timing-fastest.png'), fullPage: true });
  problems.assertNone();
  return `${duration.toFixed(4)} s certified (CLI ${cli.duration.toFixed(4)} s), ${rows.length} binding stretches, cancel stopped the first run`;
});

await test('a duration typed in the editor: the format becomes 4 and the page follows the CLI; 0 is refused', async () => {
  // the first trajectory, timed 2 s in the preset: 1 s instead is faster than its 1.796 s minimum
  await page.selectOption('select[data-testid="trajectory"]', '0');
  await open('Trajectories');
  const f = field('trajectories[0].duration');
  await typeInto(f, '1');
  await page.waitForFunction(() => JSON.parse(document.querySelector('textarea[data-testid="source"]').value).trajectories[0].duration === 1, null, { timeout: TIMEOUT });
  await page.waitForSelector('[data-testid="timing"][data-trajectory="slerp q1-q2"][data-duration="1.0"]', { timeout: TIMEOUT });
  const cli = await cliOfPage('slerp q1-q2');
  if (!cli.seconds.infeasible.length) throw new Error('1 s was meant to be too fast');
  const r = await sameAsCli(cli, 'after typing 1 s');
  const before = await source();
  await typeInto(f, '0');
  const msg = await page.locator('label', { has: page.locator(f) }).last().locator('[data-testid="field-error"]').first().textContent();
  if (!/positive/.test(msg)) throw new Error(`a duration of 0: message "${msg}"`);
  if ((await source()) !== before) throw new Error('a duration of 0 was written');
  return `1 s: ${r.sections} sections like the CLI, 0 kept in the field ("${msg}")`;
});

await test('"Make it a timed spline": knots from the trajectory\'s ends, edited, verified as the CLI does', async () => {
  const names = JSON.parse(await source()).trajectories.map((t) => t.name);
  const swing = names.indexOf('swing');
  await page.selectOption('select[data-testid="trajectory"]', String(swing));
  await open('Trajectories');
  await page.locator('[data-testid="to-spline"]').nth(swing).click();
  await page.waitForFunction((k) => !!JSON.parse(document.querySelector('textarea[data-testid="source"]').value).trajectories[k].knots, swing, { timeout: TIMEOUT });
  await page.waitForSelector('[data-testid="spline-item"] [data-testid="knot"]', { timeout: TIMEOUT });
  let doc = JSON.parse(await source());
  if (doc.trajectories[swing].knots.length !== 2 || doc.trajectories[swing].knots[1].time !== 0.8) throw new Error(`knots ${JSON.stringify(doc.trajectories[swing].knots)}`);
  await page.waitForSelector(`[data-testid="timing"][data-trajectory="swing"][data-duration="0.8"]`, { timeout: TIMEOUT });
  const first = await sameAsCli(await cliOfPage('swing'), 'the swing as a spline');
  // a third knot, two seconds in, and the second knot moved 10 cm up
  await page.click('[data-testid="add-knot"]');
  await page.waitForFunction((k) => JSON.parse(document.querySelector('textarea[data-testid="source"]').value).trajectories[k].knots.length === 3, swing, { timeout: TIMEOUT });
  await typeInto(field(`trajectories[${swing}].knots[2].time`), '2');
  const z = doc.trajectories[swing].knots[1].position[2];
  await typeInto(field(`trajectories[${swing}].knots[1].position[2]`), String(z + 0.1));
  await page.waitForFunction(([k, z]) => {
    const t = JSON.parse(document.querySelector('textarea[data-testid="source"]').value).trajectories[k];
    return t.knots[2].time === 2 && Math.abs(t.knots[1].position[2] - z) < 1e-12;
  }, [swing, z + 0.1], { timeout: TIMEOUT });
  await page.waitForSelector(`[data-testid="timing"][data-trajectory="swing"][data-duration="2.0"]`, { timeout: TIMEOUT });
  const second = await sameAsCli(await cliOfPage('swing'), 'three knots');
  await page.screenshot({ path: join(artifacts, 'timing-spline.png'), fullPage: true });
  problems.assertNone();
  return `two knots: ${first.sections} section(s), shortest ${first.minDuration?.toFixed(4)} s; three: ${second.sections}, shortest ${second.minDuration?.toFixed(4)} s`;
});

await test('"Give the platform a mass" on the 7-cable preset: format 4, and a typed mass verified as the CLI does', async () => {
  await page.goto(`${base}/#preset=cdpr7`, { waitUntil: 'load' });
  await page.waitForSelector('section[data-testid="result"][data-origin="cdpr7"] svg[data-testid="strip"]', { timeout: TIMEOUT });
  // the trajectory picked on the previous page stays picked: compare the first one
  await page.selectOption('select[data-testid="trajectory"]', '0');
  await open('Mass and winches');
  await page.click('[data-testid="add-dynamics"]');
  await page.waitForSelector('[data-testid="dynamics"]', { timeout: TIMEOUT });
  await page.waitForFunction(() => !!JSON.parse(document.querySelector('textarea[data-testid="source"]').value).robot.dynamics, null, { timeout: TIMEOUT });
  const doc = JSON.parse(await source());
  if (doc.format !== 'cablenav-scenario/4' || !doc.robot.dynamics) throw new Error(`after adding a mass: format ${doc.format}, dynamics ${JSON.stringify(doc.robot.dynamics)}`);
  // with tensions up to 12 N the 1 kg platform is held on the end of "linear" (from the boundary
  // where the weight leaves the available wrench set), a 2 kg one nowhere
  await open('Robot');
  await typeInto(field('robot.tension.max'), '12');
  await page.waitForFunction(() => JSON.parse(document.querySelector('textarea[data-testid="source"]').value).robot.tension?.max === 12, null, { timeout: TIMEOUT });
  await page.waitForSelector('section[data-testid="result"][data-origin="edited"] svg[data-testid="strip"]', { timeout: TIMEOUT });
  const name = JSON.parse(await source()).trajectories[0].name;
  const compare = async (what) => {
    const cli = await cliOfPage(name);
    const got = await stripSections(page);
    const want = cliSections(cli);
    if (got.length !== want.length || got.some((g, k) => g.kind !== want[k].kind || Math.abs(g.t0 - want[k].t0) > 1e-12 || Math.abs(g.t1 - want[k].t1) > 1e-12)) {
      throw new Error(`${what}: strip ${JSON.stringify(got)} vs CLI ${JSON.stringify(want)}`);
    }
    return cli;
  };
  const light = await compare('1 kg');
  if (!light.boundaries.some((b) => b.constraint === 'wrench feasibility') || !light.feasible.length) throw new Error(`1 kg: ${JSON.stringify(light)}`);
  await typeInto(field('robot.dynamics.mass'), '2');
  await page.waitForFunction(() => JSON.parse(document.querySelector('textarea[data-testid="source"]').value).robot.dynamics.mass === 2, null, { timeout: TIMEOUT });
  await page.waitForFunction(() => [...document.querySelectorAll('svg[data-testid="strip"] rect[data-testid="section"]')].every((r) => r.dataset.kind === 'infeasible'), null, { timeout: TIMEOUT });
  const heavy = await compare('2 kg');
  if (heavy.feasible.length) throw new Error(`2 kg: ${JSON.stringify(heavy)}`);
  await page.screenshot({ path: join(artifacts, 'timing-mass.png'), fullPage: true });
  problems.assertNone();
  return `1 kg held from t = ${light.feasible[0][0].toFixed(4)} (wrench feasibility), 2 kg nowhere, both as the CLI says`;
});

await test('a point mass (Laval\'s CSPR, batotp\'s case): its fastest safe timing on the page equals `cablenav time`', async () => {
  await page.goto(`${base}/#preset=laval-cspr3dof`, { waitUntil: 'load' });
  await page.waitForSelector('section[data-testid="result"][data-origin="laval-cspr3dof"] svg[data-testid="strip"]', { timeout: TIMEOUT });
  await openTab(page, 'intervals');
  await page.waitForSelector('[data-testid="fastest-run"]', { timeout: TIMEOUT });
  await page.click('[data-testid="fastest-run"]');
  await page.waitForSelector('[data-testid="fastest"][data-trajectory="batotp-path"]', { timeout: 4 * TIMEOUT });
  const cli = cliJson(root, ['time', 'static/scenarios/laval-cspr3dof.json', '--trajectory', 'batotp-path']);
  const duration = Number(await page.getAttribute('[data-testid="fastest"]', 'data-duration'));
  if (!(cli.duration > 0) || Math.abs(duration - cli.duration) > 1e-9 * cli.duration) throw new Error(`page ${duration} s, CLI ${cli.duration} s`);
  const rows = await page.$$eval('table[data-testid="fastest-binding"] tbody tr', (trs) => trs.map((tr) => tr.lastElementChild.textContent));
  if (rows.join('|') !== cli.binding.map((b) => b.constraint).join('|')) throw new Error(`binding: page ${rows}, CLI ${cli.binding.map((b) => b.constraint)}`);
  // the speed and the three cables' tensions
  const panels = await page.$$eval('[data-testid="chart-fastest"] [data-testid="fastest-panel"] path', (ps) => ps.length);
  if (panels !== 1 + 3) throw new Error(`${panels} lines`);
  await page.screenshot({ path: join(artifacts, 'timing-point-mass.png'), fullPage: true });
  problems.assertNone();
  return `${duration.toFixed(4)} s certified (CLI ${cli.duration.toFixed(4)} s), ${rows.length} binding stretches`;
});

await close();
finish();
