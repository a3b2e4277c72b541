// The npm package as a user gets it: `npm pack`'s tarball (target/npm/cablenav-*.tgz, made by
// `npm/build.sh --pack`) unpacked into a scratch node_modules/, imported by its package name.
// Its reports must equal what the CLI prints with --json (CABLENAV, else target/debug/cablenav),
// its errors must name the field, and its types must declare every function's report.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, mkdirSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = resolve(fileURLToPath(new URL('../..', import.meta.url)));
const tarballs = readdirSync(join(root, 'target', 'npm')).filter((f) => /^cablenav-.*\.tgz$/.test(f));
assert.equal(tarballs.length, 1, `one tarball in target/npm (run npm/build.sh --pack): ${tarballs}`);
const scratch = mkdtempSync(join(tmpdir(), 'cablenav-npm-'));
const installed = join(scratch, 'node_modules', 'cablenav');
mkdirSync(installed, { recursive: true });
execFileSync('tar', ['-xzf', join(root, 'target', 'npm', tarballs[0]), '-C', installed, '--strip-components=1']);
// A module inside the scratch project, so that `cablenav/web` resolves through its node_modules.
writeFileSync(join(scratch, 'load.mjs'), "export * from 'cablenav/web'; export { default } from 'cablenav/web';\n");
const cablenav = await import(join(scratch, 'load.mjs'));
cablenav.initSync({ module: readFileSync(join(installed, 'web', 'cablenav_bg.wasm')) });

const cliPath = process.env.CABLENAV ?? join(root, 'target', 'debug', 'cablenav');
const cli = (...args) => JSON.parse(execFileSync(cliPath, [...args.map(String), '--json'], { encoding: 'utf8' }));
const presets = readdirSync(join(root, 'static', 'scenarios')).filter((f) => f.endsWith('.json'));
const preset = (name) => readFileSync(join(root, 'static', 'scenarios', name), 'utf8');

test('verify equals `cablenav verify --json` on every preset and trajectory', () => {
  assert.ok(presets.length >= 5);
  for (const file of presets) {
    const text = preset(file);
    for (const { name } of JSON.parse(text).trajectories) {
      const expected = cli('verify', join(root, 'static', 'scenarios', file), '--trajectory', name);
      assert.deepEqual(cablenav.verify(text, name), expected, `${file} ${name}`);
      assert.deepEqual(cablenav.verify(JSON.parse(text), name), expected, `${file} ${name} (object)`);
    }
  }
});

/**
 * Deep equality with numbers allowed 1e-12 relative apart: the core's maths functions (sin,
 * atan2, …) come from Rust's libm on wasm32 and from glibc natively, and those may differ in the
 * last bit (a slice's fixed θ prints as 0.9 natively, 0.9000000000000001 in wasm). Everything
 * else — strings, classes, counts, keys, array lengths — must be identical.
 */
function close(actual, expected, path = '') {
  if (typeof expected === 'number' && typeof actual === 'number') {
    assert.ok(Math.abs(actual - expected) <= 1e-12 * Math.max(1, Math.abs(expected)), `${path}: ${actual} vs ${expected}`);
  } else if (expected !== null && typeof expected === 'object') {
    assert.equal(typeof actual, 'object', path);
    assert.deepEqual(Object.keys(actual ?? {}), Object.keys(expected), path);
    for (const key of Object.keys(expected)) close(actual[key], expected[key], `${path}.${key}`);
  } else {
    assert.equal(actual, expected, path);
  }
}

test('timed trajectories: seconds, checkAt and the envelope with inertia equal the CLI', () => {
  const timed = join(root, 'static', 'scenarios', 'robocrane-timed.json');
  const text = preset('robocrane-timed.json');
  for (const { name } of JSON.parse(text).trajectories) {
    const report = cablenav.verify(text, name);
    close(report, cli('verify', timed, '--trajectory', name));
    assert.ok(report.seconds.duration > 0, name);
    for (const t of [0, 0.3, 1]) {
      close(cablenav.checkAt(text, t, name), cli('check', timed, '--trajectory', name, '--t', t));
    }
  }
  close(cablenav.envelope(text, 'swing', 10), cli('envelope', timed, '--trajectory', 'swing', '--samples', 10));
  const fastest = cablenav.time(text, 'swing', 100);
  close(fastest, cli('time', timed, '--trajectory', 'swing', '--cells', 100));
  assert.ok(fastest.duration >= fastest.uncertified_duration && fastest.uncertified_duration > 0);
  assert.throws(() => cablenav.time(text, 'swing', undefined, 0.7), (e) => e.name === 'ScenarioError' && e.field === 'margin');
  assert.throws(() => cablenav.checkAt(text, 1.5), (e) => e.name === 'ScenarioError' && e.field === 't');
});

test('check, ray, envelope, slice and plan equal the CLI (to the last bits of libm)', () => {
  const box = join(root, 'static', 'scenarios', 'cdpr7-box.json');
  const robocrane = join(root, 'static', 'scenarios', 'robocrane.json');
  close(cablenav.check(preset('cdpr7-box.json'), 'fig310'), cli('check', box, '--pose', 'fig310'));
  close(cablenav.check(preset('robocrane.json'), 'q1'), cli('check', robocrane, '--pose', 'q1'));
  close(cablenav.ray(preset('cdpr7-box.json'), 'fig310', 'x', 0.2, 3.8), cli('ray', box, '--pose', 'fig310', '--vary', 'x', '--range', 0.2, 3.8));
  close(cablenav.envelope(preset('robocrane.json'), undefined, 20), cli('envelope', robocrane, '--samples', 20));
  // the singularity curves near θ = ±π follow det J where it hovers about 0, and libm's last bits
  // may split and chain the arcs there differently: every point of a long curve (10 points or
  // more) of either lies within 1e-9 of a point of the other's curves
  const mapOurs = cablenav.slice(preset('robocrane.json'), 'q1', 'phi', 'theta', 30);
  const mapTheirs = cli('slice', robocrane, '--pose', 'q1', '--axes', 'phi,theta', '--res', 30);
  const points = (curves) => curves.flat();
  const longPoints = (curves) => curves.filter((c) => c.length >= 10).flat();
  assert.ok(longPoints(mapTheirs.singular_curves).length > 0, 'the CLI traces long singularity curves');
  for (const [a, b, what] of [[mapOurs, mapTheirs, 'ours'], [mapTheirs, mapOurs, 'the CLI\'s']]) {
    const others = points(b.singular_curves);
    for (const p of longPoints(a.singular_curves)) {
      assert.ok(others.some((q) => Math.hypot(p[0] - q[0], p[1] - q[1]) <= 1e-9), `${what} curve point ${p} is on no curve of the other`);
    }
  }
  delete mapOurs.singular_curves;
  delete mapTheirs.singular_curves;
  close(mapOurs, mapTheirs);
  close(
    cablenav.slice(preset('cdpr7-box.json'), 'start', 'x', 'y', 20, [0, 4, 0, 4]),
    cli('slice', box, '--pose', 'start', '--axes', 'x,y', '--res', 20, '--range', 0, 4, 0, 4),
  );
  const ours = cablenav.plan(preset('robocrane.json'), 'q1-q2', undefined, 0.3, 0.3);
  const theirs = cli('plan', robocrane, '--query', 'q1-q2', '--radius', 0.3, '--epsilon', 0.3);
  assert.equal(ours.seconds, null); // no clock in the core on wasm32
  delete ours.seconds;
  delete theirs.seconds;
  assert.equal(ours.elapsed_ms, null);
  delete ours.elapsed_ms;
  delete theirs.elapsed_ms;
  close(ours, theirs);
  assert.equal(ours.status, 'found');
});

test("plan takes the CLI's atlas options minRadius and heuristicWeight", () => {
  const robocrane = join(root, 'static', 'scenarios', 'robocrane.json');
  const text = preset('robocrane.json');
  const defaults = cablenav.plan(text, 'q1-q2');
  const u = undefined;
  for (const [name, option, ours] of [
    ['min_radius', '--min-radius', cablenav.plan(text, 'q1-q2', u, u, u, u, u, 1)],
    ['heuristic_weight', '--heuristic-weight', cablenav.plan(text, 'q1-q2', u, u, u, u, u, u, 1)],
  ]) {
    const theirs = cli('plan', robocrane, '--query', 'q1-q2', option, 1);
    delete ours.seconds;
    delete theirs.seconds;
    delete ours.elapsed_ms;
    delete theirs.elapsed_ms;
    close(ours, theirs);
    assert.equal(ours.status, 'found');
    assert.equal(ours.params[name], 1);
    // it changes the search: the defaults (min_radius 0.1, heuristic_weight 1.5) take 13 charts
    assert.notEqual(ours.charts, defaults.charts, name);
  }
  // refused by the core as the CLI refuses them, naming the argument
  for (const [args, field, words] of [
    [[u, u, u, u, u, -1], 'minRadius', 'positive finite'],
    [[u, u, u, u, u, NaN], 'minRadius', 'positive finite'],
    [[u, u, u, u, u, u, 0.5], 'heuristicWeight', '≥ 1'],
    [[u, u, u, u, u, u, Infinity], 'heuristicWeight', '≥ 1'],
  ]) {
    assert.throws(() => cablenav.plan(text, 'q1-q2', ...args), (e) => {
      assert.equal(e.name, 'ScenarioError');
      assert.equal(e.field, field, e.message);
      assert.ok(e.message.startsWith(`${field}: `) && e.reason.includes(words), e.message);
      return true;
    });
  }
});

test('lattice and the lattice planner equal the CLI (to the last bits of libm)', () => {
  const box = join(root, 'static', 'scenarios', 'cdpr7-box.json');
  const ours = cablenav.lattice(preset('cdpr7-box.json'), 'start', ['x', 'y', 'z'], [0.2, 3.8, 1.1, 2.9, 0.3, 3.7], 5);
  close(ours, cli('lattice', box, '--pose', 'start', '--axes', 'x,y,z', '--range', 0.2, 3.8, 1.1, 2.9, 0.3, 3.7, '--steps', 5));
  assert.deepEqual(ours.steps, [5, 5, 5]);
  assert.equal(ours.rays.length, 75);
  close(
    cablenav.lattice(JSON.parse(preset('cdpr7-box.json')), 'start', ['x', 'y'], [0, 4, 0, 4], [5, 3]),
    cli('lattice', box, '--pose', 'start', '--axes', 'x,y', '--range', 0, 4, 0, 4, '--steps', '5,3'),
  );
  const plan = cablenav.plan(preset('cdpr7-box.json'), 'over-box', undefined, undefined, undefined, 'lattice', 5);
  const theirs = cli('plan', box, '--query', 'over-box', '--planner', 'lattice', '--steps', 5);
  assert.equal(plan.seconds, null); // no clock in the core on wasm32
  delete plan.seconds;
  delete theirs.seconds;
  delete plan.elapsed_ms;
  delete theirs.elapsed_ms;
  close(plan, theirs);
  assert.deepEqual(plan.steps, [5, 5, 5]);
});

test('multi-link robots: joint coordinates by name, equal to the CLI', () => {
  const path = join(root, 'static', 'multilink', 'bmarm-x4-2.json');
  const arm = readFileSync(path, 'utf8');
  const q = Math.PI / 4;
  close(cablenav.ray(arm, 'below', 'alpha', -q, q), cli('ray', path, '--pose', 'below', '--vary', 'alpha', '--range', -q, q));
  const ours = cablenav.lattice(arm, 'fig312', ['alpha', 'beta'], [-q, q, -q, q], 10);
  close(ours, cli('lattice', path, '--pose', 'fig312', '--axes', 'alpha,beta', '--range', -q, q, -q, q, '--steps', 10));
  assert.equal(ours.components, 2);
  close(cablenav.verify(arm, 'across the gap'), cli('verify', path, '--trajectory', 'across the gap'));
  assert.throws(() => cablenav.ray(arm, 'fig312', 'x', 0, 1), (e) => e.field === 'vary' && /alpha, beta, gamma, theta/.test(e.message));
  // the atlas planner (the default) refuses a chain, naming the lattice planner in npm's words
  assert.throws(() => cablenav.plan(arm, 'any'), (e) => e.field === 'plan' && /the "lattice" planner/.test(e.message) && !/--planner/.test(e.message));
});

test('an arm imported with its links\' masses holds its weight as the CLI says', () => {
  const model = join(root, '..', 'shared', 'models', 'caspr', 'BMArm');
  const read = (f) => readFileSync(join(model, `BMArm_${f}.xml`), 'utf8');
  const { scenario } = cablenav.importCaspr('BMArm', read('bodies'), read('cables'));
  assert.equal(scenario.format, 'cablenav-scenario/6');
  assert.equal(scenario.robot.closure, false);
  assert.deepEqual(scenario.robot.links.map((l) => l.mass), [0.9810187, 0.1313765]);
  scenario.configurations.bent = { ...scenario.configurations.initial, theta: -0.95 };
  scenario.trajectories = [{ name: 'bend', through: ['initial', 'bent'] }];
  const file = join(scratch, 'bmarm.json');
  writeFileSync(file, JSON.stringify(scenario));
  const ours = cablenav.verify(scenario, 'bend');
  close(ours, cli('verify', file, '--trajectory', 'bend'));
  assert.deepEqual(ours.boundaries.map((b) => b.constraint), ['static feasibility']);
  scenario.robot.links[1].mass = 0;
  assert.throws(() => cablenav.verify(scenario, 'bend'), (e) => e.name === 'ScenarioError' && e.field === 'robot.links[1].mass');
});

test('errors are ScenarioErrors naming the field', () => {
  const scenario = JSON.parse(preset('cdpr7.json'));
  const throws = (f, field) => {
    assert.throws(f, (e) => {
      assert.equal(e.name, 'ScenarioError');
      assert.equal(e.field, field, e.message);
      assert.ok(e.message.startsWith(`${field}: `) && e.reason.length > 0, e.message);
      return true;
    });
  };
  scenario.robot.cables[3].base = [0, 4];
  throws(() => cablenav.verify(scenario), 'robot.cables[3].base');
  throws(() => cablenav.verify('{"format": "cablenav-scenario/1", "robot": '), 'robot');
  const good = preset('cdpr7.json');
  throws(() => cablenav.verify(good, 'nope'), 'trajectory');
  throws(() => cablenav.verify(good, undefined, 0), 'pointwise');
  throws(() => cablenav.ray(good, 'start', 'w', 0, 1), 'vary');
  throws(() => cablenav.ray(good, 'start', 'x', 1, 0), 'range');
  throws(() => cablenav.check(good, 'nobody'), 'pose');
  throws(() => cablenav.slice(good, 'start', 'x', 'y', 10), 'range');
  throws(() => cablenav.slice(good, 'start', 'x', 'y', 10, [0, 1, 2]), 'range');
  throws(() => cablenav.plan(preset('robocrane.json'), 'q1-q2', 0), 'maxCharts');
  throws(() => cablenav.plan(good, 'q1-q2', undefined, undefined, undefined, 'rrt'), 'planner');
  throws(() => cablenav.plan(good, 'q1-q2', undefined, undefined, undefined, 'atlas', 5), 'steps');
  // `steps` belongs to the lattice planner (the core's one check, in JavaScript's words)
  assert.throws(() => cablenav.plan(good, 'q1-q2', undefined, undefined, undefined, undefined, 5), { message: 'steps: is an option of the "lattice" planner' });
  // and the atlas options to the atlas planner: refused with the lattice planner, not ignored
  assert.throws(() => cablenav.plan(good, 'q1-q2', 100, undefined, undefined, 'lattice'), { message: 'maxCharts: is an option of the "atlas" planner' });
  throws(() => cablenav.plan(good, 'q1-q2', undefined, undefined, undefined, 'lattice', undefined, undefined, 2), 'heuristicWeight');
  throws(() => cablenav.lattice(good, 'start', ['x', 'w'], [0, 1, 0, 1], 5), 'axes');
  throws(() => cablenav.lattice(good, 'start', ['x', 'y'], [0, 1, 0, 1], 1), 'steps');
  throws(() => cablenav.lattice(good, 'start', ['x', 'y'], [0, 1, 0, 1], 'many'), 'steps');
  throws(() => cablenav.lattice(good, 'start', ['x', 'y'], [0, 1], 5), 'ranges');
});

test('the bundler entry loads (ES module import of the .wasm) and agrees with the web entry', () => {
  const script = "import('cablenav').then((c) => console.log(JSON.stringify(c.verify(process.argv[1], 'quadratic'))))";
  const out = execFileSync(process.execPath, ['--experimental-wasm-modules', '--no-warnings', '--input-type=module', '-e', script, preset('cdpr7-tree.json')], { cwd: scratch, encoding: 'utf8' });
  assert.deepEqual(JSON.parse(out), cablenav.verify(preset('cdpr7-tree.json'), 'quadratic'));
});

test('the TypeScript declarations type every function with its report', () => {
  for (const target of ['web', 'bundler']) {
    const dts = readFileSync(join(installed, target, 'cablenav.d.ts'), 'utf8');
    for (const [fn, report] of [['verify', 'VerifyReport'], ['check', 'PoseReport'], ['ray', 'RayReport'], ['envelope', 'TensionEnvelope'], ['time', 'TimingReport'], ['slice', 'SliceMap'], ['lattice', 'LatticeReport'], ['plan', 'PlanReport \\| LatticePlanReport \\| PlanReport\\[\\] \\| LatticePlanReport\\[\\] \\| PlanWithAtlas']]) {
      assert.match(dts, new RegExp(`export function ${fn}\\(scenario: ScenarioInput[^)]*\\): ${report};`), `${target}: ${fn}`);
      for (const name of report.split(' \\| ').map((n) => n.replace('\\[\\]', ''))) assert.match(dts, new RegExp(`export interface ${name} \\{`), `${target}: ${name}`);
    }
    assert.match(dts, /export function plan\([^)]*minRadius\?: number[^)]*heuristicWeight\?: number/, `${target}: plan's atlas options`);
  }
  assert.equal(cablenav.version(), JSON.parse(readFileSync(join(installed, 'package.json'), 'utf8')).version);
});

test('importCaspr converts a CASPR model as `cablenav import` does, timed splines included', () => {
  const model = join(root, '..', 'shared', 'models', 'caspr', 'CoGiRo');
  const read = (f) => readFileSync(join(model, `CoGiRo_${f}.xml`), 'utf8');
  const written = join(scratch, 'cogiro.json');
  execFileSync(cliPath, ['import', model, '--out', written]);
  const { scenario, notes } = cablenav.importCaspr('CoGiRo', read('bodies'), read('cables'), read('trajectories'));
  close(scenario, JSON.parse(readFileSync(written, 'utf8')));
  assert.ok(Array.isArray(notes));
  close(cablenav.verify(scenario, 'long_stable'), cli('verify', written, '--trajectory', 'long_stable'));
  const untimed = cablenav.importCaspr('CoGiRo', read('bodies'), read('cables'));
  assert.deepEqual(untimed.scenario.trajectories.map((t) => t.name), ['hold initial']);
  assert.throws(() => cablenav.importCaspr('x', read('cables'), read('cables')), (e) => e.name === 'ScenarioError' && e.field === 'bodies');
  // another cable set of the file, as `cablenav import --cable-set` picks it
  const spatial = join(root, '..', 'shared', 'models', 'caspr', 'Example_spatial');
  const file = (f) => readFileSync(join(spatial, `Example_spatial_${f}.xml`), 'utf8');
  const cross = join(scratch, 'cross.json');
  execFileSync(cliPath, ['import', spatial, '--cable-set', 'cross_8_cables', '--out', cross]);
  close(cablenav.importCaspr('Example_spatial', file('bodies'), file('cables'), file('trajectories'), 'cross_8_cables').scenario, JSON.parse(readFileSync(cross, 'utf8')));
  assert.throws(() => cablenav.importCaspr('x', file('bodies'), file('cables'), undefined, 'nine'), (e) => e.name === 'ScenarioError' && e.field === 'cable_set');
});

test('plan takes several queries (one report each, the atlas kept) and paper coordinates', () => {
  const robocrane = join(root, 'static', 'scenarios', 'robocrane.json');
  const text = preset('robocrane.json');
  const u = undefined;
  const ours = cablenav.plan(text, ['q1-q2', 'q3-q4']);
  const theirs = cli('plan', robocrane, '--query', 'q1-q2', '--query', 'q3-q4');
  assert.deepEqual(ours.map((r) => r.query), ['q1-q2', 'q3-q4']);
  for (const [a, b] of ours.map((r, k) => [r, theirs[k]])) {
    for (const key of ['seconds', 'elapsed_ms']) {
      delete a[key];
      delete b[key];
    }
  }
  close(ours, theirs);
  assert.equal(ours[1].reused_charts, ours[0].charts);
  assert.deepEqual(cablenav.plan(text, ['q3-q4']).map((r) => r.query), ['q3-q4']);
  const paper = cablenav.plan(text, 'q3-q4', u, u, u, u, u, u, u, false);
  assert.equal(paper.params.identify_angles, false);
  assert.ok(paper.charts > 100, `${paper.charts} charts`);
  assert.throws(() => cablenav.plan(text, 'q3-q4', u, u, u, 'lattice', u, u, u, false), (e) => e.field === 'identifyAngles' || /identifyAngles/.test(e.message));
  assert.throws(() => cablenav.plan(text, [], u), /query/);
});

test('plan keeps an atlas across calls (its file text in, the atlas out)', () => {
  const text = preset('robocrane.json');
  const u = undefined;
  const first = cablenav.plan(text, 'q1-q2', u, u, u, u, u, u, u, u, '');
  assert.ok(first.atlas.startsWith('{"format":"cablenav-atlas/1"'));
  assert.equal(first.reports.length, 1);
  const again = cablenav.plan(text, 'q1-q2', u, u, u, u, u, u, u, u, first.atlas);
  assert.equal(again.reports[0].reused_charts, first.reports[0].charts);
  assert.equal(again.reports[0].charts, first.reports[0].charts);
  assert.throws(() => cablenav.plan(text, 'q1-q2', u, u, 0.3, u, u, u, u, u, first.atlas), (e) => e.field === 'atlas');
});
