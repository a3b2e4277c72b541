// End-to-end test of a multi-link robot on the page (the thesis' 4-DoF arm, preset bmarm-x4-2), in
// Debian's headless Chromium driven by playwright-core, against the built page
// (scripts/build-page.sh):
//   node tests/browser/e2e-multilink.mjs [PAGE_DIR]      (default: target/page)
// - the preset loads: the strip of its path "across the gap" equals `cablenav verify` (the
//   infeasible section where cables 2 and 3 pass closer than the clearance), the 3-D view draws
//   the arm's links and cables, and the scrubber moves the arm along the path (cables 2 and 3
//   drawn interfering inside the gap only);
// - the joint sliders: a configuration picked from the list, then one coordinate typed, show the
//   verdict of `cablenav check` at the same configuration, and the cables drawn as interfering are
//   those of its violated conditions;
// - the slice map over the joint coordinates α, β (the others from configuration fig312, the
//   thesis' Fig. 3.12 cross-section) is computed by the workers and agrees with `cablenav slice`
//   (fraction feasible and components), with the path drawn over it;
// - the α–β ray lattice at fig312 with 10 steps (Fig. 3.12) built in the workers equals
//   `cablenav lattice` ray by ray (2 components), drawn in 3-D too; the planning tab says that
//   the preset has no planning query (a multi-link robot's queries are planned by the lattice
//   planner); a query added to the arm (as tests/joint_plan.rs adds it) is planned on the page
//   with the lattice planner (selected for a multi-link robot, the atlas planner disabled) in a
//   worker, its path through configurations added to the scenario,
//   and the strip shows it as `cablenav verify` does on what `cablenav plan --out` wrote;
// - the links' masses typed in the editor raise the file to format 4, and the strip gains the
//   static feasibility boundary `cablenav verify` finds on the page's scenario; a wrench applied
//   to the lower arm in the editor moves it as the CLI says, and so does a torque on the elbow
//   typed under "Forces on joints" (the file raised to format 6);
// - a routed model of CASPR's library (SJTUSnake's bodies, cables and trajectories files) imported
//   on the page is the scenario `cablenav import` writes, drawn with its 36 cables and 24 joint
//   sliders, and the strip of its trajectory `traj_test` is `cablenav verify`'s.
// Screenshots in tests/browser/artifacts/. Ends with "N passed, M failed"; exits 1 on failure.

import { execFileSync } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { begin, cliBinary, cliJson, cliSections, cliVerify, openTab, stripSections, watchProblems } from './harness.mjs';

const { root, artifacts, scratch, test, finish, base, browser, close } = await begin(import.meta.url, { watchdogMinutes: 8, scratch: 'cablenav-multilink-' });
const TIMEOUT = 60_000;
const ARM = 'static/multilink/bmarm-x4-2.json';

const context = await browser.newContext({ viewport: { width: 1366, height: 900 } });
const problems = watchProblems(context);
const page = await context.newPage();
await page.goto(`${base}/#preset=bmarm-x4-2`, { waitUntil: 'load' });
await page.waitForSelector('section[data-testid="result"][data-origin="bmarm-x4-2"] svg[data-testid="strip"]', { timeout: TIMEOUT });

const view = 'canvas[data-testid="view3d"]';
const cables = async () => (await page.getAttribute(view, 'data-cables')).split(' ');
const interfering = (looks) => looks.flatMap((l, i) => (l === 'interfering' ? [i + 1] : []));

/** Waits (up to 10 s) until the strip shows the sections `want` (the CLI's); returns them. */
async function stripBecomes(want) {
  let got = [];
  for (let i = 0; i < 100; i++) {
    got = await stripSections(page);
    if (JSON.stringify(got) === JSON.stringify(want)) return got;
    await page.waitForTimeout(100);
  }
  throw new Error(`strip ${JSON.stringify(got)}\n  CLI ${JSON.stringify(want)}`);
}

/** Moves the scrubber to t (0…1). */
async function scrubTo(t) {
  await page.fill('input[data-testid="scrubber"]', String(Math.round(t * 1000)));
  await page.dispatchEvent('input[data-testid="scrubber"]', 'input');
}

await test('the arm\'s path: the strip equals `cablenav verify`, the view follows the scrubber', async () => {
  const cli = cliVerify(root, ARM, 'across the gap');
  const want = cliSections(cli);
  const got = await stripSections(page);
  if (JSON.stringify(got.map((s) => s.kind)) !== JSON.stringify(want.map((s) => s.kind))) throw new Error(`kinds ${JSON.stringify(got)} vs ${JSON.stringify(want)}`);
  for (let i = 0; i < want.length; i++) {
    if (Math.abs(got[i].t0 - want[i].t0) > 1e-12 || Math.abs(got[i].t1 - want[i].t1) > 1e-12) throw new Error(`section ${i}: ${JSON.stringify(got[i])} vs ${JSON.stringify(want[i])}`);
  }
  const gap = want.find((s) => s.kind === 'infeasible');
  if (!gap) throw new Error('no infeasible section');
  if ((await page.getAttribute(view, 'data-sections')).split(' ').length !== want.length) throw new Error('the 3-D path is not drawn in its sections');
  await scrubTo(gap.t0 / 2);
  await page.waitForFunction((sel) => document.querySelector(sel)?.dataset.cables.split(' ').every((c) => c !== 'interfering'), view, { timeout: TIMEOUT });
  await scrubTo((gap.t0 + gap.t1) / 2);
  await page.waitForFunction((sel) => document.querySelector(sel)?.dataset.cables.includes('interfering'), view, { timeout: TIMEOUT });
  const inside = interfering(await cables());
  if (JSON.stringify(inside) !== '[2,3]') throw new Error(`inside the gap cables ${inside} drawn interfering, expected 2 and 3`);
  const readout = await page.textContent('[data-testid="pose-readout"]');
  if (!/alpha .* beta .* gamma .* theta/.test(readout)) throw new Error(`readout without the joint coordinates: ${readout}`);
  await (await page.$('[data-testid="stage"]')).screenshot({ path: join(artifacts, 'multilink-stage.png') });
  return `${want.length} sections, gap t ∈ [${gap.t0.toFixed(4)}, ${gap.t1.toFixed(4)}], cables ${inside} red inside it`;
});

await test('the joint sliders: a configuration and a typed value give `cablenav check`\'s verdict', async () => {
  const sliders = await page.$$('[data-testid="joint-sliders"] label.joint');
  if (sliders.length !== 4) throw new Error(`${sliders.length} joint sliders, expected 4 (alpha, beta, gamma, theta)`);
  await page.selectOption('select[data-testid="joint-config"]', 'below');
  await page.waitForSelector('[data-testid="joint-verdict"][data-feasible="true"]', { timeout: TIMEOUT });
  const below = cliJson(root, ['check', ARM, '--pose', 'below']);
  if (!below.feasible) throw new Error('the CLI says "below" is infeasible');
  if (interfering(await cables()).length) throw new Error('cables drawn interfering at a feasible configuration');
  // β = 0 from "below" is configuration fig312 (α = 0, γ = −π/12, θ = π/12): inside the gap
  await page.fill('[data-testid="joint-beta"] input.num', '0');
  await page.dispatchEvent('[data-testid="joint-beta"] input.num', 'change');
  await page.waitForSelector('[data-testid="joint-verdict"][data-feasible="false"]', { timeout: TIMEOUT });
  const fig = cliJson(root, ['check', ARM, '--pose', 'fig312']);
  const verdict = await page.textContent('[data-testid="joint-verdict"]');
  if (fig.feasible || verdict !== `infeasible: ${fig.violated.join(', ')}`) throw new Error(`page "${verdict}" vs CLI ${JSON.stringify(fig.violated)}`);
  const red = interfering(await cables());
  const named = [...new Set(fig.violated.flatMap((v) => (v.match(/\d+/g) ?? []).map(Number)))].sort((a, b) => a - b);
  if (JSON.stringify(red) !== JSON.stringify(named)) throw new Error(`cables ${red} drawn interfering, the violated conditions name ${named}`);
  await (await page.$('[data-testid="stage"]')).screenshot({ path: join(artifacts, 'multilink-sliders.png') });
  return `below feasible; β = 0: ${verdict}`;
});

await test('the α–β slice map at fig312 (Fig. 3.12) agrees with `cablenav slice`, the path drawn over it', async () => {
  await openTab(page, 'slice');
  await page.selectOption('select[data-testid="slice-pose"]', 'fig312');
  await page.selectOption('select[data-testid="slice-axis-0"]', 'alpha');
  await page.selectOption('select[data-testid="slice-axis-1"]', 'beta');
  const from = await page.inputValue('input[data-testid="slice-from-0"]');
  if (from !== '-0.7854') throw new Error(`alpha's default range starts at ${from}, not its joint range's -0.7854`);
  await page.click('[data-testid="slice-compute"]');
  await page.waitForSelector('[data-testid="chart-slice"] image', { timeout: TIMEOUT });
  const title = await page.textContent('[data-testid="chart-slice"] figcaption span');
  const m = title.match(/Slice over alpha × beta \((\d+)×\d+ cells; ([\d.]+)% feasible, (\d+) component/);
  if (!m) throw new Error(`title: ${title}`);
  const cli = cliJson(root, ['slice', ARM, '--pose', 'fig312', '--axes', 'alpha,beta', '--res', m[1], '--range', '-0.7854', '0.7854', '-0.7854', '0.7854']);
  if ((cli.fraction_feasible * 100).toFixed(1) !== m[2] || String(cli.components) !== m[3]) throw new Error(`page ${m[2]} % / ${m[3]} components, CLI ${cli.fraction_feasible * 100} % / ${cli.components}`);
  for (const mark of ['slice-start', 'slice-goal', 'slice-path']) if (!(await page.$(`[data-testid="chart-slice"] [data-testid="${mark}"]`))) throw new Error(`no ${mark} on the map`);
  await (await page.$('[data-testid="chart-slice"]')).screenshot({ path: join(artifacts, 'multilink-slice-alpha-beta.png') });
  return `${m[1]}×${m[1]} cells, ${m[2]} % feasible, ${m[3]} component(s), as the CLI`;
});

await test('Fig. 3.12 on the page: the α–β ray lattice at fig312 with 10 steps equals `cablenav lattice`; the planning tab says the preset has no query', async () => {
  const q = String(Math.PI / 4);
  await openTab(page, 'lattice');
  await page.selectOption('select[data-testid="lattice-pose"]', 'fig312');
  await page.selectOption('select[data-testid="lattice-axis-0"]', 'alpha');
  await page.selectOption('select[data-testid="lattice-axis-1"]', 'beta');
  for (let k = 0; k < 2; k++) {
    await page.fill(`input[data-testid="lattice-from-${k}"]`, `-${q}`);
    await page.dispatchEvent(`input[data-testid="lattice-from-${k}"]`, 'change');
    await page.fill(`input[data-testid="lattice-to-${k}"]`, q);
    await page.dispatchEvent(`input[data-testid="lattice-to-${k}"]`, 'change');
  }
  await page.fill('input[data-testid="lattice-steps"]', '10');
  await page.dispatchEvent('input[data-testid="lattice-steps"]', 'change');
  await page.click('[data-testid="lattice-build"]');
  await page.waitForSelector('[data-testid="chart-lattice"] line[data-testid="lattice-ray"]', { state: 'attached', timeout: TIMEOUT });
  const lines = await page.$$eval('[data-testid="chart-lattice"] line[data-testid="lattice-ray"]', (ls) => ls.map((l) => ({
    component: l.dataset.component, from: l.dataset.from.split(',').map(Number), to: l.dataset.to.split(',').map(Number),
  })));
  const cli = cliJson(root, ['lattice', ARM, '--pose', 'fig312', '--axes', 'alpha,beta', '--range', `-${q}`, q, `-${q}`, q, '--steps', '10']);
  const near = (a, b) => Math.abs(a - b) <= 1e-12 * Math.max(1, Math.abs(b));
  for (const [r, ray] of cli.rays.entries()) {
    const along = ray.vary === 'alpha' ? 0 : 1;
    const at = along === 0 ? ray.fixed.beta : ray.fixed.alpha;
    const mine = lines.filter((l) => near(l.from[1 - along], at) && near(l.to[1 - along], at) && l.from[along] !== l.to[along]);
    const feasible = mine.filter((l) => l.component !== 'none').map((l) => [l.from[along], l.to[along], Number(l.component)]).sort((a, b) => a[0] - b[0]);
    const want = ray.feasible.map((iv, p) => [iv[0], iv[1], cli.piece_components[r][p]]);
    const same = feasible.length === want.length && feasible.every((f, i) => near(f[0], want[i][0]) && near(f[1], want[i][1]) && f[2] === want[i][2]);
    if (!same) throw new Error(`ray ${r} (${ray.vary} at ${at}): page ${JSON.stringify(feasible)}\n  CLI ${JSON.stringify(want)}`);
  }
  const heading = await page.$eval('[data-testid="panel-lattice"]', (p) => p.textContent);
  const count = Number(/(\d+) component\(s\)/.exec(heading)?.[1]);
  if (count !== cli.components || cli.components !== 2) throw new Error(`the panel says ${count} component(s), the CLI ${cli.components} (the thesis: 2)`);
  if (!(await page.$('[data-testid="chart-lattice"] [data-testid="lattice-path"]'))) throw new Error('the path is not drawn over the lattice');
  await page.waitForFunction(() => Number(document.querySelector('canvas[data-testid="view3d"]').dataset.latticePieces) > 0, null, { timeout: TIMEOUT });
  await (await page.$('[data-testid="chart-lattice"]')).screenshot({ path: join(artifacts, 'multilink-lattice-fig3-12.png') });
  await openTab(page, 'planning');
  const text = await page.textContent('[data-testid="panel-planning"]');
  // the preset has no queries (tests/joint_plan.rs adds some): the tab says so, and plans none
  if (!text.includes('This scenario has no planning query.')) throw new Error(`planning tab: ${text.slice(0, 200)}`);
  return `${cli.rays.length} rays, ${cli.components} components, ${cli.feasible_points} feasible grid points, as the CLI`;
});

await test('a query of the arm planned with the lattice planner in a worker: the path through configurations, added to the scenario, has the strip of `cablenav verify` on what `cablenav plan --out` wrote', async () => {
  // the preset with two configurations of its upper region and a query between them, as
  // tests/joint_plan.rs has it (the straight path leaves wrench closure)
  const arm = JSON.parse(readFileSync(join(root, ARM), 'utf8'));
  const [g, th] = [-Math.PI / 12, Math.PI / 12];
  arm.configurations.ul = { alpha: -0.1, beta: 0.75, gamma: g, theta: th };
  arm.configurations.lr = { alpha: 0.59, beta: 0.22, gamma: g, theta: th };
  arm.queries = [{ name: 'around', start: 'ul', goal: 'lr', fixed: ['gamma', 'theta'] }];
  const text = JSON.stringify(arm, null, 2);
  const file = join(scratch, 'arm-queries.json');
  writeFileSync(file, text);
  const out = join(scratch, 'arm-planned.json');
  const cli = cliJson(root, ['plan', file, '--query', 'around', '--planner', 'lattice', '--out', out]);
  if (cli.status !== 'found') throw new Error(`the CLI: ${cli.status}`);
  const want = cliSections(cliVerify(root, out, 'around-lattice'));
  await page.setInputFiles('[data-testid="import-json"]', { name: 'arm-queries.json', mimeType: 'application/json', buffer: Buffer.from(text) });
  await openTab(page, 'planning');
  // the lattice planner is the one a multi-link robot is planned with: selected, the atlas disabled
  const planner = await page.$eval('select[data-testid="planner"]', (s) => ({ value: s.value, atlas: s.querySelector('option[value="continuation"]').disabled }));
  if (planner.value !== 'ray-lattice' || !planner.atlas) throw new Error(`planner select for the arm: ${JSON.stringify(planner)}`);
  await page.click('[data-testid="plan-run"]');
  await page.waitForFunction(() => !['running', 'idle'].includes(document.querySelector('[data-testid="plan-status"]').dataset.state), null, { timeout: TIMEOUT, polling: 100 });
  const state = await page.getAttribute('[data-testid="plan-status"]', 'data-state');
  const status = (await page.textContent('[data-testid="plan-status"]')).trim();
  if (state !== 'found') throw new Error(`the page: ${state} "${status}"`);
  await page.click('[data-testid="plan-add-path"]');
  const got = await stripBecomes(want);
  return `${status.slice(0, 80)}…; strip ${JSON.stringify(got)} as the CLI`;
});

await test('the links\' masses typed in the editor: the format becomes 4, and the strip holds the arm\'s weight as `cablenav verify` does', async () => {
  const text = readFileSync(join(root, ARM), 'utf8');
  await page.setInputFiles('[data-testid="import-json"]', { name: 'arm.json', mimeType: 'application/json', buffer: Buffer.from(text) });
  await page.waitForSelector('svg[data-testid="strip"]', { timeout: TIMEOUT });
  const source = () => page.$eval('textarea[data-testid="source"]', (t) => t.value);
  const details = page.locator('[data-testid="scenario-editor"] details').filter({ has: page.locator('summary', { hasText: 'Links and joints' }) }).first();
  if (!(await details.evaluate((d) => d.open))) await details.locator('summary').first().click();
  for (const [k, mass] of [[0, '2'], [1, '1']]) {
    const input = page.locator(`[data-field="robot.links[${k}].mass"]`);
    await input.click();
    await input.press('Control+a');
    await input.pressSequentially(mass);
  }
  await page.waitForFunction(() => {
    const d = JSON.parse(document.querySelector('textarea[data-testid="source"]').value);
    return d.format === 'cablenav-scenario/4' && d.robot.links[0].mass === 2 && d.robot.links[1].mass === 1;
  }, null, { timeout: TIMEOUT });
  const file = join(scratch, 'arm-weighed.json');
  writeFileSync(file, await source());
  const cli = cliVerify(root, file, 'across the gap');
  // 2 kg and 1 kg are more than the cables hold near β = 0.4 (the third boundary, t ≈ 0.80)
  if (!cli.boundaries.some((b) => b.constraint === 'static feasibility')) throw new Error(`the CLI names no static feasibility boundary: ${JSON.stringify(cli.boundaries)}`);
  const got = await stripBecomes(cliSections(cli));
  // with masses, the tension bounds the condition reads are offered in the robot's editor
  const robot = page.locator('[data-testid="scenario-editor"] details').filter({ has: page.locator('summary', { hasText: 'Robot' }) }).first();
  if (!(await robot.evaluate((d) => d.open))) await robot.locator('summary').first().click();
  await page.waitForSelector('legend:has-text("Cable tension bounds")', { timeout: TIMEOUT });
  const ticks = await page.$$eval('svg[data-testid="strip"] [data-testid="boundary"] title', (ts) => ts.map((t) => t.textContent));
  if (!ticks.some((t) => t.includes('static feasibility'))) throw new Error(`boundary tooltips ${JSON.stringify(ticks)}`);
  await page.screenshot({ path: join(artifacts, 'multilink-masses.png'), fullPage: true });
  return `strip ${JSON.stringify(got.map((s) => s.kind))} as the CLI; boundaries ${cli.boundaries.map((b) => `${b.constraint} at ${b.t.toFixed(4)}`).join(', ')}`;
});

await test('a wrench applied to a link in the editor: the strip is `cablenav verify`\'s on the page\'s scenario', async () => {
  // the arm with the masses typed above; 1 N down on the lower arm by default, then 3 N
  const details = page.locator('[data-testid="scenario-editor"] details').filter({ has: page.locator('summary', { hasText: 'Wrench on a link' }) }).first();
  if (!(await details.evaluate((d) => d.open))) await details.locator('summary').first().click();
  await page.click('[data-testid="add-link-wrench"]');
  const wrench = () => page.$eval('textarea[data-testid="source"]', (t) => JSON.parse(t.value).wrench);
  await page.waitForFunction(() => JSON.parse(document.querySelector('textarea[data-testid="source"]').value).wrench?.link === 'Lower Arm', null, { timeout: TIMEOUT });
  const fz = page.locator('[data-field="wrench.nominal[2]"]');
  await fz.click();
  await fz.press('Control+a');
  await fz.pressSequentially('-3');
  await page.waitForFunction(() => JSON.parse(document.querySelector('textarea[data-testid="source"]').value).wrench.nominal[2] === -3, null, { timeout: TIMEOUT });
  const file = join(scratch, 'arm-wrench.json');
  writeFileSync(file, await page.$eval('textarea[data-testid="source"]', (t) => t.value));
  const cli = cliVerify(root, file, 'across the gap');
  // the wrench moves the boundary of the weights alone (t ≈ 0.80) earlier
  const statics = cli.boundaries.find((b) => b.constraint === 'static feasibility');
  if (!statics || !(statics.t < 0.79)) throw new Error(`the CLI's static feasibility boundary: ${JSON.stringify(cli.boundaries)}`);
  const got = await stripBecomes(cliSections(cli));
  return `wrench ${JSON.stringify(await wrench())}; strip ${JSON.stringify(got.map((s) => s.kind))} as the CLI, static feasibility from t = ${statics.t.toFixed(4)}`;
});

await test('a torque on the elbow typed under "Forces on joints": format 6, and the strip is `cablenav verify`\'s on the page\'s scenario', async () => {
  // the arm with the masses and the wrench above; 1 N·m about θ's axis helps the cables (the
  // boundary of the weights and the wrench, t ≈ 0.756, moves to t ≈ 0.768)
  const details = page.locator('[data-testid="scenario-editor"] details').filter({ has: page.locator('summary', { hasText: 'Forces on joints' }) }).first();
  if (!(await details.evaluate((d) => d.open))) await details.locator('summary').first().click();
  const fields = await page.$$eval('[data-testid="joint-forces"] [data-field]', (fs) => fs.map((f) => f.getAttribute('data-field')));
  if (JSON.stringify(fields) !== JSON.stringify(['joint_forces.theta'])) throw new Error(`joint force fields ${JSON.stringify(fields)} (the spherical shoulder takes none)`);
  const theta = page.locator('[data-field="joint_forces.theta"]');
  await theta.click();
  await theta.pressSequentially('1');
  await page.waitForFunction(() => {
    const d = JSON.parse(document.querySelector('textarea[data-testid="source"]').value);
    return d.format === 'cablenav-scenario/6' && d.joint_forces?.theta === 1;
  }, null, { timeout: TIMEOUT });
  const file = join(scratch, 'arm-torque.json');
  writeFileSync(file, await page.$eval('textarea[data-testid="source"]', (t) => t.value));
  const cli = cliVerify(root, file, 'across the gap');
  const statics = cli.boundaries.find((b) => b.constraint === 'static feasibility');
  if (!statics || !(statics.t > 0.765)) throw new Error(`the CLI's static feasibility boundary: ${JSON.stringify(cli.boundaries)}`);
  const got = await stripBecomes(cliSections(cli));
  return `strip ${JSON.stringify(got.map((s) => s.kind))} as the CLI, static feasibility from t = ${statics.t.toFixed(4)}`;
});

await test('a routed model of CASPR\'s library imported on the page (SJTUSnake: 36 cables over 432 segments): the scenario is `cablenav import`\'s and the strip of its `traj_test` is `cablenav verify`\'s', async () => {
  const dir = join(root, '..', 'shared', 'models', 'caspr', 'SJTUSnake');
  await page.setInputFiles('[data-testid="import-caspr"]', ['bodies', 'cables', 'trajectories'].map((f) => join(dir, `SJTUSnake_${f}.xml`)));
  await page.waitForFunction(() => JSON.parse(document.querySelector('textarea[data-testid="source"]').value).name === 'SJTUSnake', null, { timeout: TIMEOUT });
  const text = await page.$eval('textarea[data-testid="source"]', (t) => t.value);
  const imported = JSON.parse(text);
  // the CLI's conversion of the same directory
  const cli = JSON.parse(execFileSync(cliBinary(root), ['import', dir], { cwd: root, encoding: 'utf8', maxBuffer: 64 << 20 }));
  if (JSON.stringify(imported) !== JSON.stringify(cli)) throw new Error('the page imported another scenario than `cablenav import`');
  const routed = imported.robot.cables.filter((c) => c.via || c.from).length;
  if (imported.format !== 'cablenav-scenario/6' || imported.robot.cables.length !== 36 || routed < 30) throw new Error(`${imported.format}, ${imported.robot.cables.length} cables, ${routed} routed`);
  const file = join(scratch, 'snake.json');
  writeFileSync(file, text);
  const report = cliVerify(root, file, 'traj_test');
  const want = cliSections(report);
  // a file loaded is shown from its first trajectory (not from the index shown before it)
  await page.waitForFunction(() => document.querySelector('section[data-testid="result"]')?.textContent.includes('SJTUSnake — traj_test'), null, { timeout: TIMEOUT });
  const got = await stripBecomes(want);
  const drawn = (await page.getAttribute(view, 'data-cables')).split(' ').length;
  if (drawn !== 36) throw new Error(`${drawn} cables drawn`);
  const sliders = await page.$$('[data-testid="joint-sliders"] label.joint');
  if (sliders.length !== 24) throw new Error(`${sliders.length} joint sliders, expected 24`);
  await (await page.$('[data-testid="stage"]')).screenshot({ path: join(artifacts, 'multilink-snake.png') });
  return `${routed} of 36 cables routed; strip ${JSON.stringify(got.map((s) => s.kind))} as the CLI`;
});

await test('no console errors, page errors or failed requests', async () => {
  if (problems.length) throw new Error(problems.join('\n'));
});

await close();
finish();
