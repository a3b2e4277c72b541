// docs/course-page.html — the npm package on a page without Leptos — in headless Chromium: the
// strip and the boundary table it draws equal `cablenav verify FILE --json` (the CLI built by
// `cargo test`; CABLENAV overrides), and a broken scenario shows the core's error at its field.
// Needs the package built (npm/build.sh). Usage: node tests/browser/course-page.mjs

import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { launchChromium, runner, serve, watchProblems } from './harness.mjs';

const root = resolve(fileURLToPath(new URL('../..', import.meta.url)));
const cli = process.env.CABLENAV ?? join(root, 'target', 'debug', 'cablenav');
const { test, finish } = runner(5);
for (const needed of [cli, join(root, 'npm', 'web', 'cablenav.js')]) {
  if (!existsSync(needed)) {
    console.log(`FAIL missing ${needed} (run cargo test and npm/build.sh first)`);
    finish();
  }
}
const reference = (trajectory) =>
  JSON.parse(execFileSync(cli, ['verify', join(root, 'static', 'scenarios', 'cdpr7-tree.json'), '--trajectory', trajectory, '--json'], { encoding: 'utf8' }));

const server = await serve(root);
const browser = await launchChromium();
const context = await browser.newContext();
const problems = watchProblems(context);
const page = await context.newPage();
await page.goto(`http://127.0.0.1:${server.address().port}/docs/course-page.html`);

async function shown() {
  await page.waitForFunction(() => document.getElementById('summary').textContent !== '');
  return {
    summary: await page.textContent('#summary'),
    rows: await page.$$eval('#boundaries tbody tr', (rows) => rows.map((r) => [...r.cells].map((c) => c.textContent))),
    error: await page.textContent('#error'),
  };
}

for (const trajectory of ['linear', 'quadratic']) {
  await test(`the page's ${trajectory} report equals cablenav verify`, async () => {
    await page.selectOption('#trajectory', trajectory);
    await page.evaluate(() => (document.getElementById('summary').textContent = ''));
    await page.click('#verify');
    const got = await shown();
    const want = reference(trajectory);
    const share = want.feasible.reduce((s, [a, b]) => s + b - a, 0);
    const summary = `${trajectory}: ${(100 * share).toFixed(2)} % of t feasible, ${want.infeasible.length} infeasible section(s)`;
    if (got.summary !== summary) throw new Error(`summary ${got.summary} ≠ ${summary}`);
    const rows = want.boundaries.map((b) => [b.t.toFixed(6), b.constraint, b.enters]);
    if (JSON.stringify(got.rows) !== JSON.stringify(rows)) throw new Error(`rows ${JSON.stringify(got.rows)} ≠ ${JSON.stringify(rows)}`);
    if (got.error) throw new Error(got.error);
    problems.assertNone();
    return `${rows.length} boundaries`;
  });
}

await test('a broken scenario shows the error at its field', async () => {
  const text = await page.inputValue('#scenario');
  const broken = JSON.parse(text);
  broken.robot.cables[2].base = [4, 2];
  await page.fill('#scenario', JSON.stringify(broken));
  await page.click('#verify');
  const error = await page.textContent('#error');
  if (!error.startsWith('robot.cables[2].base: ')) throw new Error(`error shown: ${error}`);
  problems.assertNone();
});

await browser.close();
server.close();
finish();
