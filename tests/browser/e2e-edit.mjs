// End-to-end test of the scenario editor and sharing, on the built page in headless Chromium.
//   node tests/browser/e2e-edit.mjs [PAGE_DIR]      (default: target/page)
// Needs the native CLI (target/debug/cablenav, built by `cargo test`; CABLENAV overrides) as the
// independent reference: the page's sections after an edit must equal what `cablenav verify`
// prints for the same scenario, and the live pose check must agree with `cablenav check`.
// Covers: editing a via point, a typo kept at its field, the core's errors shown at the field
// (min > max, E not positive definite), obstacles added with a colour, poses, reload keeps the
// edits, the shared link in a fresh browser context, embed mode, JSON export/import, CASPR
// import, keyboard reachability. Screenshots go to tests/browser/artifacts/.

import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { launchChromium, readSections, requirePage, runner, serve, watchProblems } from './harness.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const root = resolve(here, '..', '..');
const pageDir = resolve(root, process.argv[2] ?? process.env.PAGE_DIR ?? 'target/page');
const artifacts = join(here, 'artifacts');
const caspr = resolve(root, '..', 'shared', 'models', 'caspr');
const cli = process.env.CABLENAV ?? resolve(root, 'target', 'debug', 'cablenav');
const scratch = mkdtempSync(join(tmpdir(), 'cablenav-e2e-'));
const TIMEOUT = 60_000;
const EPS = 1e-9;

mkdirSync(artifacts, { recursive: true });
requirePage(pageDir);
if (!existsSync(cli)) {
  console.log(`FAIL no cablenav CLI at ${cli} (run cargo test or cargo build first)`);
  console.log('0 passed, 1 failed');
  process.exit(1);
}
const { test, finish } = runner(10);
const server = await serve(pageDir);
const base = `http://127.0.0.1:${server.address().port}`;
const browser = await launchChromium();

// ---------- helpers ----------
const field = (path) => `[data-field="${path}"]`;

/** The page's scenario JSON (the text the views analyse). */
const source = (page) => page.$eval('textarea[data-testid="source"]', (t) => t.value);

async function open(page, summary) {
  const details = page
    .locator('[data-testid="scenario-editor"] details')
    .filter({ has: page.locator('summary', { hasText: summary }) })
    .first();
  if (!(await details.evaluate((d) => d.open))) await details.locator('summary').first().click();
}

async function pickPreset(page, id) {
  await page.selectOption('select[data-testid="preset"]', id);
  await page.waitForSelector(`section[data-testid="result"][data-origin="${id}"]`, { timeout: TIMEOUT });
}

/** Types into an input as a user does (select all, type), which fires input events. */
async function typeInto(page, selector, text) {
  const input = page.locator(selector);
  await input.click();
  await input.press('Control+a');
  await input.pressSequentially(text);
}

/** The message shown in the smallest element around `selector` that has one. */
async function messageNear(page, selector, container) {
  return page.locator(container, { has: page.locator(selector) }).last().locator('[data-testid="field-error"]').first().textContent();
}

function cliJson(args) {
  return JSON.parse(execFileSync(cli, [...args, '--json'], { encoding: 'utf8' }));
}

/** The CLI's verify report as sections like the page's. */
function cliSections(json, trajectory) {
  const file = join(scratch, 'scenario.json');
  writeFileSync(file, json);
  const r = cliJson(['verify', file, '--trajectory', trajectory]);
  const out = [];
  for (const [t0, t1] of r.feasible) out.push({ kind: 'feasible', t0, t1 });
  for (const [t0, t1] of r.infeasible) out.push({ kind: 'infeasible', t0, t1 });
  for (const [t0, t1] of r.uncertain) out.push({ kind: 'uncertain', t0, t1 });
  return out.sort((a, b) => a.t0 - b.t0);
}

function sameSections(page, ref, what) {
  const a = [...page].sort((x, y) => x.t0 - y.t0);
  if (a.length !== ref.length) throw new Error(`${what}: page ${JSON.stringify(a)} vs CLI ${JSON.stringify(ref)}`);
  a.forEach((s, i) => {
    const r = ref[i];
    if (s.kind !== r.kind || Math.abs(s.t0 - r.t0) > EPS || Math.abs(s.t1 - r.t1) > EPS)
      throw new Error(`${what}: section ${i} page ${JSON.stringify(s)} vs CLI ${JSON.stringify(r)}`);
  });
}

// ---------- tests ----------
const contextA = await browser.newContext({ viewport: { width: 1200, height: 900 }, acceptDownloads: true });
const problemsA = watchProblems(contextA);
const page = await contextA.newPage();
let edited = ''; // the scenario after the edits, for reload and sharing

await test('editing a via point refits the polynomial and the page agrees with `cablenav verify`', async () => {
  await page.goto(`${base}/`, { waitUntil: 'load' });
  await pickPreset(page, 'cdpr7-box');
  await open(page, 'Trajectories');
  const via = (k, a) => field(`trajectories[1].translation.polynomial.via[${k}][${a}]`);
  await page.waitForSelector(via(1, 2));
  const before = await page.inputValue(via(1, 0));
  if (before !== '1.2') throw new Error(`via point P1 x shows ${before}, expected 1.2 (x = 2 − 2.7τ + 2.2τ² at τ = 0.5)`);
  await typeInto(page, via(1, 0), '3');
  await typeInto(page, via(1, 1), '2');
  await typeInto(page, via(1, 2), '0.6');
  await page.waitForSelector('section[data-testid="result"][data-origin="edited"]', { timeout: TIMEOUT });
  edited = await source(page);
  const poly = JSON.parse(edited).trajectories[1].translation.polynomial;
  const expect = [[2, 4.5, -5], [1.5, 1.2, -0.4], [1, -3.6, 5.6]]; // through the 3 points at τ = 0, ½, 1
  poly.forEach((row, i) => row.forEach((c, j) => {
    if (Math.abs(c - expect[i][j]) > 1e-9) throw new Error(`coefficients ${JSON.stringify(poly)} vs ${JSON.stringify(expect)}`);
  }));
  await page.selectOption('select[data-testid="trajectory"]', '1');
  await page.waitForSelector('section[data-testid="result"][data-trajectory-index="1"]');
  const sections = await readSections(page);
  const ref = cliSections(edited, 'quadratic');
  sameSections(sections, ref, 'after the via point edit');
  if (!ref.some((s) => s.kind === 'infeasible')) throw new Error('the edit was meant to make part of the path infeasible');
  await page.screenshot({ path: join(artifacts, 'edit-via-point.png'), fullPage: true });
  problemsA.assertNone();
  return `${sections.length} sections = CLI`;
});

await test('a typo stays in its field with a message and is not written', async () => {
  await open(page, 'Robot');
  const f = field('robot.cables[2].base[0]');
  const text = await source(page);
  await typeInto(page, f, '4,5');
  if ((await page.inputValue(f)) !== '4,5') throw new Error('the typed text was replaced');
  const msg = await messageNear(page, f, 'label');
  if (!/not a number/.test(msg) || !/4\.5/.test(msg)) throw new Error(`message: ${msg}`);
  if ((await source(page)) !== text) throw new Error('an invalid number changed the scenario');
  if ((await page.getAttribute(f, 'aria-invalid')) !== 'true') throw new Error('not marked invalid');
  await typeInto(page, f, '4');
  if ((await source(page)) !== text) throw new Error('restoring the value changed the scenario');
  return JSON.stringify(msg);
});

await test("the core's errors show at the field they name", async () => {
  const min = field('robot.length.min');
  await typeInto(page, min, '20');
  const msg = await messageNear(page, min, 'fieldset');
  if (!/min 20 is greater than max 10/.test(msg)) throw new Error(`length bounds message: ${msg}`);
  const status = await page.textContent('[data-testid="editor-status"]');
  if (!status.includes('robot.length')) throw new Error(`status: ${status}`);
  await page.screenshot({ path: join(artifacts, 'edit-error-at-field.png'), fullPage: true });
  await typeInto(page, min, '0');
  await page.waitForSelector('[data-testid="editor-status"].ok');
  edited = await source(page);
  problemsA.assertNone();
  return JSON.stringify(msg);
});

await test('the wrench ellipsoid E is checked positive definite by the core', async () => {
  const saved = await source(page);
  await pickPreset(page, 'robocrane');
  await open(page, 'Wrench');
  await page.selectOption('select[data-testid="ellipsoid-mode"]', 'matrix');
  const e00 = field('wrench.ellipsoid[0][0]');
  await page.waitForSelector(e00);
  if ((await page.inputValue(e00)) !== '10000') throw new Error(`E[0][0] = ${await page.inputValue(e00)}, expected 1/0.01² = 10000`);
  await typeInto(page, e00, '-5');
  const msg = await messageNear(page, e00, 'fieldset.matrix');
  if (!/positive definite/.test(msg)) throw new Error(`message: ${msg}`);
  // point_frame is a choice between the two frames
  const frames = await page.$$eval('select[data-testid="point-frame"] option', (os) => os.map((o) => o.value));
  if (frames.join() !== 'platform,world') throw new Error(`point frames ${frames}`);
  await page.screenshot({ path: join(artifacts, 'edit-wrench.png'), fullPage: true });
  // the nominal wrench alone (format 4): no ellipsoid in the file, and the core reads it
  await page.selectOption('select[data-testid="ellipsoid-mode"]', 'none');
  await page.waitForSelector('[data-testid="editor-status"].ok');
  const single = JSON.parse(await source(page));
  if ('ellipsoid' in single.wrench || 'radius' in single.wrench || single.format !== 'cablenav-scenario/4') {
    throw new Error(`wrench ${JSON.stringify(single.wrench)}, format ${single.format}`);
  }
  // back to the edited 7-cable scenario, through the JSON box
  await page.click('details.editor summary');
  await page.fill('textarea[data-testid="source"]', saved);
  await page.click('button[data-testid="apply"]');
  await page.click('details.editor summary');
  await page.waitForSelector('[data-testid="editor-status"].ok');
  problemsA.assertNone();
  return JSON.stringify(msg);
});

await test('obstacles are added with a colour and poses are checked live like `cablenav check`', async () => {
  await open(page, 'Obstacles');
  const count = await page.locator('[data-testid="obstacle"]').count();
  await page.selectOption('select[data-testid="new-obstacle-type"]', 'cylinder');
  await page.click('button[data-testid="add-obstacle"]');
  await page.waitForFunction((n) => document.querySelectorAll('[data-testid="obstacle"]').length === n + 1, count);
  const color = page.locator(`input[type="color"][data-field="obstacles[${count}].color"]`);
  await color.evaluate((el) => {
    el.value = '#3366cc';
    el.dispatchEvent(new Event('input', { bubbles: true }));
  });
  const s = JSON.parse(await source(page));
  const o = s.obstacles[count];
  if (o.type !== 'cylinder' || o.color !== '#3366cc' || o.name !== 'cylinder 1') throw new Error(`obstacle ${JSON.stringify(o)}`);
  // delete it again
  await page.locator('[data-testid="remove-obstacle"]').nth(count).click();
  await page.waitForFunction((n) => document.querySelectorAll('[data-testid="obstacle"]').length === n, count);

  await open(page, 'Poses');
  const fig = page.locator('[data-testid="pose"]', { hasText: 'fig310' });
  const shown = await fig.locator('[data-testid="pose-check"]').getAttribute('data-feasible');
  writeFileSync(join(scratch, 'poses.json'), await source(page));
  const ref = cliJson(['check', join(scratch, 'poses.json'), '--pose', 'fig310']);
  if (shown !== String(ref.feasible)) throw new Error(`fig310: page says ${shown}, cablenav check ${ref.feasible}`);
  // move it far out: the length bound (10 m) is violated, live
  await typeInto(page, field('poses.fig310.position[0]'), '40');
  await page.waitForFunction(() => {
    const p = [...document.querySelectorAll('[data-testid="pose"]')].find((e) => e.textContent.includes('fig310'));
    return p?.querySelector('[data-testid="pose-check"]')?.dataset.feasible === 'false';
  });
  const verdict = await fig.locator('[data-testid="pose-check"]').textContent();
  if (!/length/.test(verdict)) throw new Error(`verdict ${verdict}`);
  // the slider moves the same number
  const slider = fig.locator('input[type="range"]').first();
  await slider.evaluate((el) => {
    el.value = '2';
    el.dispatchEvent(new Event('input', { bubbles: true }));
  });
  await page.waitForFunction(() => document.querySelector('[data-field="poses.fig310.position[0]"]').value === '2');
  // tilt-and-torsion ⇄ Euler keeps the rotation (the core converts)
  await fig.locator('select[data-testid="orientation-kind"]').selectOption('tilt_torsion');
  const tt = JSON.parse(await source(page)).poses.fig310.tilt_torsion;
  if (!tt || tt.some((x) => Math.abs(x) > 1e-12)) throw new Error(`identity as tilt-torsion: ${JSON.stringify(tt)}`);
  await typeInto(page, field('poses.fig310.position[0]'), '2.0016');
  await fig.locator('select[data-testid="orientation-kind"]').selectOption('quaternion');
  await page.screenshot({ path: join(artifacts, 'edit-poses.png'), fullPage: true });
  edited = await source(page);
  problemsA.assertNone();
  return `fig310 feasible = ${shown}; moved: ${JSON.stringify(verdict.slice(0, 60))}`;
});

let link = '';
await test('a reload keeps the edits', async () => {
  link = await page.inputValue('[data-testid="share-link"]');
  if (!link.includes('#s=')) throw new Error(`share link ${link}`);
  await page.reload({ waitUntil: 'load' });
  await page.waitForSelector('section[data-testid="result"][data-origin="edited"]', { timeout: TIMEOUT });
  const after = await source(page);
  if (after !== edited) throw new Error('the scenario after the reload differs from before');
  problemsA.assertNone();
  return `${after.length} characters kept`;
});

const contextB = await browser.newContext({ viewport: { width: 1000, height: 800 } });
const problemsB = watchProblems(contextB);
await test('the shared link opens the same scenario in a fresh browser context', async () => {
  const fresh = await contextB.newPage();
  await fresh.goto(link, { waitUntil: 'load' });
  await fresh.waitForSelector('section[data-testid="result"][data-origin="edited"]', { timeout: TIMEOUT });
  if ((await source(fresh)) !== edited) throw new Error('the shared scenario differs');
  await fresh.screenshot({ path: join(artifacts, 'shared-link.png'), fullPage: true });
  await fresh.close();
  problemsB.assertNone();
  return `link of ${link.length} characters`;
});

await test('embed mode shows the results without the editor', async () => {
  const snippet = await page.inputValue('[data-testid="embed-snippet"]');
  const src = /src="([^"]+)"/.exec(snippet)?.[1];
  if (!src || !src.includes('?embed=1#s=')) throw new Error(`snippet ${snippet}`);
  const host = await contextB.newPage();
  await host.setContent(`<!doctype html><title>course page</title><p>Course page</p>${snippet}`);
  const frame = await (await host.waitForSelector('iframe')).contentFrame();
  await frame.waitForSelector('section[data-testid="result"] svg[data-testid="strip"]', { timeout: TIMEOUT });
  for (const gone of ['[data-testid="scenario-editor"]', 'select[data-testid="preset"]', '[data-testid="share"]', 'textarea[data-testid="source"]'])
    if (await frame.$(gone)) throw new Error(`embed mode shows ${gone}`);
  if (!(await frame.$('[data-testid="open-full"]'))) throw new Error('no link to the full page');
  if ((await frame.getAttribute('main', 'data-embed')) !== 'true') throw new Error('main is not in embed mode');
  await host.screenshot({ path: join(artifacts, 'embed.png'), fullPage: true });
  await host.close();
  problemsB.assertNone();
  return 'editor hidden, strip shown';
});

await test('JSON export and import by file', async () => {
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('[data-testid="export-json"]')]);
  const file = join(scratch, download.suggestedFilename());
  await download.saveAs(file);
  if (readFileSync(file, 'utf8') !== edited) throw new Error('the exported file differs from the scenario');
  const other = readFileSync(resolve(root, 'static/scenarios/cdpr7-tree.json'), 'utf8').replace('"cdpr7-tree"', '"imported tree"');
  await page.setInputFiles('[data-testid="import-json"]', { name: 'tree.json', mimeType: 'application/json', buffer: Buffer.from(other) });
  await page.waitForFunction(() => document.querySelector('textarea[data-testid="source"]').value.includes('imported tree'));
  if ((await source(page)) !== other) throw new Error('the imported scenario differs from the file');
  problemsA.assertNone();
  return download.suggestedFilename();
});

await test('a CASPR model (bodies + cables files) imports', async () => {
  const dir = join(caspr, 'NIST_ROBOCRANE');
  await page.setInputFiles('[data-testid="import-caspr"]', [join(dir, 'NIST_RoboCrane_bodies.xml'), join(dir, 'NIST_RoboCrane_cables.xml')]);
  await page.waitForSelector('[data-testid="share-message"].ok');
  const s = JSON.parse(await source(page));
  if (s.name !== 'NIST_RoboCrane' || s.robot.cables.length !== 6) throw new Error(`imported ${s.name} with ${s.robot.cables.length} cables`);
  await open(page, 'Robot');
  const rows = await page.locator('[data-testid="cable-row"]').count();
  if (rows !== 6) throw new Error(`${rows} cable rows`);
  if (await page.locator('[data-testid="caspr-cable-set"]').count()) throw new Error('a cable-set choice for a file with one set');
  // a cables file with several cable sets: the default imported, the others offered
  const spatial = join(caspr, 'Example_spatial');
  await page.setInputFiles('[data-testid="import-caspr"]', [join(spatial, 'Example_spatial_bodies.xml'), join(spatial, 'Example_spatial_cables.xml')]);
  await page.waitForSelector('[data-testid="caspr-cable-set"]');
  const sets = await page.$$eval('[data-testid="caspr-cable-set"] option', (os) => os.map((o) => [o.value, o.selected]));
  if (sets.length !== 4 || !sets.some(([id, on]) => id === 'basic_7_cables' && on)) throw new Error(`cable sets offered: ${JSON.stringify(sets)}`);
  if (JSON.parse(await source(page)).robot.cables.length !== 7) throw new Error('the default set has 7 cables');
  await page.selectOption('[data-testid="caspr-cable-set"]', 'cross_8_cables');
  await page.waitForFunction(() => JSON.parse(document.querySelector('textarea[data-testid="source"]').value).robot.cables.length === 8, null, { timeout: 5000 }).catch(() => {});
  const crossed = JSON.parse(await source(page));
  if (crossed.robot.cables.length !== 8) throw new Error(`cross_8_cables imported ${crossed.robot.cables.length} cables`);
  // one file alone is refused with a message
  await page.setInputFiles('[data-testid="import-caspr"]', [join(dir, 'NIST_RoboCrane_bodies.xml')]);
  const msg = await (await page.waitForSelector('[data-testid="share-message"].error')).textContent();
  if (!/both/.test(msg)) throw new Error(`message ${msg}`);
  await page.screenshot({ path: join(artifacts, 'caspr-import.png'), fullPage: true });
  problemsA.assertNone();
  return `${rows} cables`;
});

await test('every editor control is keyboard-reachable and labelled', async () => {
  for (const summary of ['Mass and winches', 'Wrench', 'Obstacles', 'Poses', 'Trajectories']) await open(page, summary);
  const report = await page.$$eval(
    '[data-testid="scenario-editor"] :is(input, select, button, textarea), [data-testid="share"] :is(input, select, button, textarea)',
    (els) =>
      els.map((el) => {
        el.focus();
        const focused = document.activeElement === el;
        const label = el.getAttribute('aria-label') || el.closest('label')?.textContent.trim() || el.textContent.trim();
        return { tag: el.tagName, field: el.dataset.field ?? '', text: el.textContent.trim().slice(0, 40), focused, labelled: !!label };
      }),
  );
  const bad = report.filter((r) => !r.focused || !r.labelled);
  if (bad.length) throw new Error(`not reachable or unlabelled: ${JSON.stringify(bad.slice(0, 5))}`);
  // Tab from the preset picker reaches the trajectory picker
  await page.focus('select[data-testid="preset"]');
  await page.keyboard.press('Tab');
  const next = await page.evaluate(() => document.activeElement?.dataset.testid);
  if (next !== 'trajectory') throw new Error(`Tab went to ${next}`);
  return `${report.length} controls`;
});

await browser.close();
server.close();
finish(`screenshots in ${artifacts}`);
