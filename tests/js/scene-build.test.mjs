// Building a scene from nothing (web/state/scene-build.js and the modules it gathers):
// new scene, rename, duplicate, delete with dependents, unused parameters, placement,
// blends and fills between picked borders, trigonometric trimlines. Scenes are checked by
// the real core (the native CLI, and the wasm module for solve → detach → solve); every
// refusal names the field and leaves the scene deep-equal to before.
//   PDESURF_CLI=build/native/pdesurf PDESURF_BUILD_DIR=build node --test tests/js/scene-build.test.mjs
import { describe, it } from 'node:test';
import assert from 'node:assert/strict';
import * as THREE from 'three';
import { loadTestSolver } from './test-solver.mjs';
import {
  newScene, renamePatch, duplicatePatch, deletePatch, dependentsOf, unusedParameters, removeParameter,
  setPlacement, placePoint, addBlend, addFill, addLoopFill, trigCurveFromSamples, addSurface, lowestVersion,
} from '../../web/state/scene-build.js';
import { compile, parameterValues } from '../../web/state/expr-text.js';
import { check, refuses } from './build-helpers.mjs';

const solver = await loadTestSolver();
const solve = (scene) => solver.solve(JSON.stringify(scene), { nu: 16, nv: 24 }).patches;

/** Annulus, cylinder and the blend between them (the Add menu's first fillet). */
function fillet(continuity = 'tangency') {
  const scene = newScene();
  addSurface(scene, 'annulus');
  addSurface(scene, 'cylinder');
  addBlend(scene, { surface: 'annulus1', at: 't0' }, { surface: 'cylinder1', at: 't0' }, { continuity });
  return scene;
}

/** A point of a surface patch at (t, v), its expressions evaluated with the scene's parameters. */
function surfacePoint(scene, name, t, v) {
  const p = scene.patches.find((q) => q.name === name);
  const params = parameterValues(scene);
  return ['x', 'y', 'z'].map((axis) => compile(p[axis], params, ['t', 'v'])({ t, v }));
}
const rangeValue = (scene, x) => compile(String(x), parameterValues(scene))({});

/** The drawn ends [at v0, at v1] of border `at` of surface `name`. */
function borderEnds(scene, name, at) {
  const p = scene.patches.find((q) => q.name === name);
  const t = rangeValue(scene, p.t_range[at === 't0' ? 0 : 1]);
  return p.v_range.map((v) => surfacePoint(scene, name, t, rangeValue(scene, v)));
}

describe('new scene and names', () => {
  it('newScene is an empty version-4 scene', () => {
    assert.deepEqual(newScene(), { format: 'pdesurf-scene', version: 4, title: 'untitled', parameters: {}, patches: [] });
    assert.notEqual(newScene(), newScene());
  });

  it('renamePatch updates blends\' ends, surfaces\' meets and fills\' borders', () => {
    const scene = fillet();
    scene.patches[0].meets = { patch: 'blend1', end: 'u0', at: 't0' };
    scene.patches.push({ name: 'fill', kind: 'bezier', borders: { v0: { surface: 'cylinder1', at: 't1', reverse: false } } });
    renamePatch(scene, 'cylinder1', '<b>x</b>');
    renamePatch(scene, 'blend1', 'fillet');
    assert.equal(scene.patches[1].name, '<b>x</b>', 'markup is just text');
    assert.equal(scene.patches[2].ends.u1.surface, '<b>x</b>');
    assert.equal(scene.patches[0].meets.patch, 'fillet');
    assert.equal(scene.patches[3].borders.v0.surface, '<b>x</b>');
    renamePatch(scene, 'fillet', 'fillet'); // the same name: nothing to do
    scene.patches.pop();
    assert.equal(check(scene).status, 0);
  });

  it('renamePatch refuses a duplicate (naming it), an empty, long or multi-line name, an unknown patch', () => {
    const scene = fillet();
    refuses(scene, () => renamePatch(scene, 'cylinder1', 'annulus1'), /already a patch named "annulus1"/);
    refuses(scene, () => renamePatch(scene, 'cylinder1', ''), /cannot be empty/);
    refuses(scene, () => renamePatch(scene, 'cylinder1', 'x'.repeat(65)), /at most 64 bytes/);
    refuses(scene, () => renamePatch(scene, 'cylinder1', 'a\u0085b'), /control characters/);
    refuses(scene, () => renamePatch(scene, 'cylinder1', 'a\u2028b'), /control characters/);
    refuses(scene, () => renamePatch(scene, 'cylinder1', 'a\ud800'), /lone surrogate/);
    refuses(scene, () => renamePatch(scene, 'nope', 'x'), /no patch named "nope"/);
    renamePatch(scene, 'cylinder1', 'é'.repeat(32)); // 64 bytes: allowed
    assert.equal(check(scene).status, 0);
  });
});

describe('duplicate', () => {
  it('a surface gets its own copies of the parameters only it uses; shared ones stay shared', () => {
    const scene = fillet();
    scene.parameters.shared = { value: 1, min: 0, max: 2 };
    scene.patches[0].z = 'annulus1_h*shared';
    scene.patches[1].meets = { patch: 'blend1', end: 'u1', at: 't0' };
    const before = structuredClone(scene.parameters);
    scene.patches[1].x = 'cylinder1_r*cos(v)*shared';
    assert.equal(duplicatePatch(scene, 'cylinder1'), 'cylinder2');
    const copy = scene.patches[2];
    assert.equal(copy.x, 'cylinder2_r*cos(v)*shared');
    assert.deepEqual(copy.t_range, ['cylinder2_z0', 'cylinder2_z1']);
    assert.equal(copy.meets, undefined, 'meets names the original\'s blend end');
    assert.deepEqual(scene.parameters.cylinder2_r, before.cylinder1_r);
    assert.equal(scene.parameters.shared_2, undefined);
    assert.equal(check(scene).status, 0);
  });

  it('with { share: true } the copy follows the original\'s sliders; a blend copy on its borders is refused', () => {
    const scene = fillet();
    const params = Object.keys(scene.parameters).length;
    assert.equal(duplicatePatch(scene, 'annulus1', { share: true }), 'annulus2');
    assert.equal(Object.keys(scene.parameters).length, params);
    assert.deepEqual(scene.patches[1], { ...scene.patches[0], name: 'annulus2' });
    // A blend's copy would meet the borders the blend meets: three sheets on each, refused.
    refuses(scene, () => duplicatePatch(scene, 'blend1'), /^"blend1" meets "annulus1" \(its u0\): a copy would meet the same edge and three sheets would meet along it; detach it first to duplicate it$/);
    assert.equal(check(scene).status, 0);
  });

  it('refuses a blend whose copy would trim a surface along a second curve', () => {
    const scene = fillet();
    scene.patches[2].ends.u1.at = { t: 'cylinder1_z0 + 0.1*sin(v)', replaces: 't0' };
    // Its copy meets annulus1's t0 (three sheets) and would trim cylinder1 along a second curve.
    refuses(scene, () => duplicatePatch(scene, 'blend1'), /^"blend1" meets "annulus1" \(its u0\): a copy would meet the same edge/);
    refuses(scene, () => duplicatePatch(scene, 'nope'), /no patch named "nope"/);
  });
});

describe('delete', () => {
  it('lists dependents and asks what to do with them when no choice is given', () => {
    const scene = fillet();
    scene.patches.push({ name: 'fill1', kind: 'bezier', borders: { u1: { surface: 'cylinder1', at: 't1' } } });
    assert.deepEqual(dependentsOf(scene, 'cylinder1'), [
      { patch: 'blend1', kind: 'blend', ends: ['u1'] }, { patch: 'fill1', kind: 'fill', edges: ['u1'] },
    ]);
    assert.deepEqual(dependentsOf(scene, 'blend1'), []);
    refuses(scene, () => deletePatch(scene, 'cylinder1'), /^"cylinder1" is named by "blend1" \(u1\), "fill1" \(u1\): delete them too, or detach them/);
    refuses(scene, () => deletePatch(scene, 'cylinder1', { dependents: 'ignore' }), /delete them too, or detach/);
    refuses(scene, () => deletePatch(scene, 'cylinder1', { dependents: 'detach' }), /^blend1\.ends\.u1: no derived conditions/);
    refuses(scene, () => deletePatch(scene, 'nope'), /no patch named "nope"/);
  });

  it('"delete" removes the dependents too, and meets pointing at them', () => {
    const scene = fillet();
    scene.patches[0].meets = { patch: 'blend1', end: 'u0' };
    assert.deepEqual(deletePatch(scene, 'cylinder1', { dependents: 'delete' }), ['cylinder1', 'blend1']);
    assert.deepEqual(scene.patches.map((p) => p.name), ['annulus1']);
    assert.equal(scene.patches[0].meets, undefined);
    assert.equal(check(scene).status, 0);
  });

  it('a patch without dependents just goes', () => {
    const scene = fillet();
    assert.deepEqual(deletePatch(scene, 'blend1'), ['blend1']);
    assert.equal(scene.patches.length, 2);
  });

  for (const continuity of ['tangency', 'curvature']) {
    it(`"detach" types the blend's end from the last solve: it loads and keeps its shape (${continuity})`, () => {
      const scene = fillet(continuity);
      const solved = solve(scene);
      const before = solved.find((p) => p.name === 'blend1').positions;
      deletePatch(scene, 'cylinder1', { dependents: 'detach', solved });
      const blend = scene.patches.find((p) => p.name === 'blend1');
      assert.deepEqual(Object.keys(blend.ends), ['u0']);
      assert.equal(blend.boundary.z.u1.length, continuity === 'curvature' ? 3 : 2);
      const after = solve(scene).find((p) => p.name === 'blend1').positions;
      const worst = before.reduce((m, x, k) => Math.max(m, Math.abs(x - after[k])), 0);
      assert.ok(worst < 1e-5, `moved by ${worst}`);
      const { status, stderr } = check(scene);
      assert.equal(status, 0, stderr);
    });
  }

  it('"detach" on both ends of a blend gives the operator explicit orders', () => {
    const scene = newScene();
    addSurface(scene, 'cylinder');
    addBlend(scene, { surface: 'cylinder1', at: 't0' }, { surface: 'cylinder1', at: 't1' });
    assert.equal(check(scene).status, 0);
    const solved = solve(scene);
    deletePatch(scene, 'cylinder1', { dependents: 'detach', solved });
    assert.equal(scene.patches[0].ends, undefined);
    assert.equal(scene.patches[0].operator.order, 4);
    const { status, stderr } = check(scene);
    assert.equal(status, 0, stderr);
  });

  it('"detach" types a fill\'s border rings into its net from the solved net', () => {
    const n = 3, m = 2;
    const net = new Float64Array(3 * (n + 1) * (m + 1)).map((_, k) => k / 10); // the module's nets are doubles
    const solved = [{ name: 'fill1', kind: 'bezier', netSize: [n + 1, m + 1], controlNet: net }];
    const scene = { version: 4, parameters: {}, patches: [{ name: 's', kind: 'surface' }, {
      name: 'fill1', kind: 'bezier', energy: 'membrane', degree: [n, m],
      borders: { v0: { surface: 's', at: 't0', reverse: false }, u1: { surface: 's', at: 't1', reverse: true } },
    }] };
    const whole = structuredClone(scene);
    deletePatch(whole, 's', { dependents: 'detach', solved });
    const fill = whole.patches[0];
    assert.equal(fill.borders, undefined);
    assert.equal(fill.control_net.length, (n + 1) * (m + 1));
    assert.deepEqual(fill.control_net[5], [15 / 10, 16 / 10, 17 / 10]); // exactly the solved net's numbers
    // With a net already there, only the fixed ring of the detached edge changes.
    const typed = structuredClone(scene);
    typed.patches[1].control_net = Array.from({ length: (n + 1) * (m + 1) }, () => [9, 9, 9]);
    typed.patches[1].borders = { v0: typed.patches[1].borders.v0, v1: { surface: 'other', at: 't0', reverse: false } };
    deletePatch(typed, 's', { dependents: 'detach', solved });
    const cn = typed.patches[0].control_net;
    for (let i = 0; i <= n; i++) {
      for (let j = 0; j <= m; j++) assert.equal(cn[i * (m + 1) + j][0] === 9, j !== 0, `(${i}, ${j})`);
    }
    assert.deepEqual(typed.patches[0].borders, { v1: { surface: 'other', at: 't0', reverse: false } });
    refuses(scene, () => deletePatch(scene, 's', { dependents: 'detach', solved: [] }), /^fill1\.borders: no solved control net/);
  });
});

describe('parameters no patch uses', () => {
  it('are found token-wise and only they can be removed', () => {
    const scene = fillet();
    scene.parameters.t0 = { value: 0, min: 0, max: 1 }; // "at": "t0" is a border, not this parameter
    scene.parameters.sin = { value: 0, min: 0, max: 1 }; // sin(v) is the function
    scene.parameters.p = { value: 1, min: 0, max: 2 };
    scene.patches[2].ends.u0.power = 'p*(1 + 0.1*cos(v))';
    scene.patches[1].x = 'cylinder1_rr*cos(v)';
    scene.patches[1].y = 'cylinder1_rr * sin (v)';
    scene.parameters.cylinder1_rr = { value: 1, min: 0, max: 2 };
    assert.deepEqual(unusedParameters(scene), ['cylinder1_r', 't0', 'sin']);
    refuses(scene, () => removeParameter(scene, 'p'), /^parameters\.p: still used by "blend1"/);
    refuses(scene, () => removeParameter(scene, 'annulus1_r0'), /still used by "annulus1"/);
    refuses(scene, () => removeParameter(scene, 'nope'), /no parameter "nope"/);
    for (const name of unusedParameters(scene)) removeParameter(scene, name);
    assert.deepEqual(unusedParameters(scene), []);
    assert.equal(check(scene).status, 0);
  });
});

describe('placement', () => {
  it('stores X\' = T + R(s X) with R = Rx Ry Rz in degrees, as three.js Euler XYZ does', () => {
    const scene = fillet();
    setPlacement(scene, 'cylinder1', { translate: [1, 'annulus1_h', 0.5], rotate: [30, -45, 'annulus1_r0*10'], scale: 1.5 });
    assert.deepEqual(scene.patches[1].placement, { translate: [1, 'annulus1_h', 0.5], rotate: [30, -45, 'annulus1_r0*10'], scale: 1.5 });
    const X = [0.3, -1.2, 2];
    const m = new THREE.Matrix4().compose(new THREE.Vector3(1, 0, 0.5),
      new THREE.Quaternion().setFromEuler(new THREE.Euler(...[30, -45, 20].map(THREE.MathUtils.degToRad), 'XYZ')), new THREE.Vector3(1.5, 1.5, 1.5));
    const want = new THREE.Vector3(...X).applyMatrix4(m);
    const got = placePoint(scene, scene.patches[1].placement, X);
    [want.x, want.y, want.z].forEach((w, k) => assert.ok(Math.abs(w - got[k]) < 1e-12));
    assert.equal(lowestVersion(scene), 4);
    setPlacement(scene, 'cylinder1', {});
    assert.equal(scene.patches[1].placement, undefined, 'the identity leaves no field');
    setPlacement(scene, 'cylinder1', { translate: [0, 0, 0], rotate: [0, 0, 0], scale: [1, 1, 1] });
    assert.equal('placement' in scene.patches[1], false);
    setPlacement(scene, 'cylinder1', { scale: [1, 2, 'annulus1_r0'] });
    assert.deepEqual(placePoint(scene, scene.patches[1].placement, [1, 1, 1]), [1, 2, 2]);
  });

  it('refuses non-finite values, scale 0, unknown names and non-surfaces, naming the field', () => {
    const scene = fillet();
    refuses(scene, () => setPlacement(scene, 'cylinder1', { translate: [0, NaN, 0] }), /^cylinder1\.placement\.translate\[1\]: not finite/);
    refuses(scene, () => setPlacement(scene, 'cylinder1', { rotate: [Infinity, 0, 0] }), /^cylinder1\.placement\.rotate\[0\]: not finite/);
    refuses(scene, () => setPlacement(scene, 'cylinder1', { scale: 0 }), /^cylinder1\.placement\.scale: must not be 0/);
    refuses(scene, () => setPlacement(scene, 'cylinder1', { scale: [1, 0, 1] }), /^cylinder1\.placement\.scale\[1\]: must not be 0/);
    refuses(scene, () => setPlacement(scene, 'cylinder1', { rotate: [0, 0, 2e6] }), /^cylinder1\.placement\.rotate\[2\]: an angle beyond/);
    refuses(scene, () => setPlacement(scene, 'cylinder1', { scale: '0*annulus1_r0' }), /^cylinder1\.placement\.scale: must not be 0/);
    refuses(scene, () => setPlacement(scene, 'cylinder1', { scale: 'exp(800)' }), /^cylinder1\.placement\.scale: 'exp\(800\)' is not finite/);
    refuses(scene, () => setPlacement(scene, 'cylinder1', { translate: [0, 'q', 0] }), /^cylinder1\.placement\.translate\[1\]: col 1: unknown parameter 'q'/);
    refuses(scene, () => setPlacement(scene, 'cylinder1', { translate: [0, 'v', 0] }), /'v' cannot be used here/);
    refuses(scene, () => setPlacement(scene, 'cylinder1', { translate: [0, 0] }), /translate: expected \[x, y, z\]/);
    refuses(scene, () => setPlacement(scene, 'cylinder1', { spin: 3 }), /placement\.spin: unknown/);
    refuses(scene, () => setPlacement(scene, 'blend1', { scale: 2 }), /^blend1\.placement: only "surface" patches/);
  });

  it('a placed surface is accepted and its blend certified by a version-4 core', () => {
    const scene = fillet();
    setPlacement(scene, 'cylinder1', { translate: [0.2, 0, 'annulus1_r0 - 1.5'], rotate: [5, 0, 0], scale: 1.2 });
    const { status, report, stderr } = check(scene);
    assert.equal(status, 0, stderr);
    assert.ok(report.joins.every((j) => j.ok && j.level === 'G1'));
    setPlacement(scene, 'annulus1', { rotate: [0, 0, 33], scale: [1, 1, 2] });
    assert.equal(check(scene).status, 0);
  });
});

describe('blends', () => {
  it('addBlend names it blend1, copies the common v_range, leaves the operator to the solver', () => {
    const scene = fillet('curvature');
    assert.deepEqual(scene.patches[2], {
      name: 'blend1', kind: 'pde', v_range: [0, '2*pi'],
      ends: {
        u0: { surface: 'annulus1', at: 't0', continuity: 'curvature', power: 1 },
        u1: { surface: 'cylinder1', at: 't0', continuity: 'curvature', power: 1 },
      },
    });
    assert.equal(addBlend(scene, { surface: 'cylinder1', at: 't1' }, { surface: 'annulus1', at: 't1', power: 'annulus1_h + 1' }, { flip: true }), 'blend2');
    assert.deepEqual(scene.patches[3].ends.u1, { surface: 'annulus1', at: 't1', continuity: 'tangency', power: 'annulus1_h + 1', flip: true });
    // 6.283185307179586 is 2*pi: the same numbers, no parameter that could move them apart.
    scene.patches[0].v_range = [0, 2 * Math.PI];
    refuses(scene, () => addBlend(scene, { surface: 'annulus1', at: 't1' }, { surface: 'cylinder1', at: 't1' }, { name: 'third' }),
      /^third\.u0\.at: t1 of "annulus1" is already met by blend2\.u1: three sheets would meet along it/);
    const { report, stderr } = check(scene);
    assert.ok(report, `the core accepts it: ${stderr}`); // blend2's flip folds it back (that is what flip is for), so no "ok" here
  });

  it('a trimline curve from dragged samples blends with a certified join', () => {
    const scene = newScene();
    addSurface(scene, 'annulus');
    addSurface(scene, 'cylinder');
    const samples = [0, 1, 2, 3, 4, 5, 6, 7].map((k) => 2.2 + 0.15 * Math.cos(2 * Math.PI * k / 8) - 0.05 * Math.sin(4 * Math.PI * k / 8));
    const { text } = trigCurveFromSamples(samples, [0, '2*pi'], 3);
    addBlend(scene, { surface: 'annulus1', at: { t: text, replaces: 't0' } }, { surface: 'cylinder1', at: 't0' });
    const { status, report, stderr } = check(scene);
    assert.equal(status, 0, stderr);
    assert.ok(report.joins.every((j) => j.ok && j.level === 'G1'));
  });

  it('refuses mismatched v ranges, the same border twice, bad picks and options', () => {
    const scene = fillet();
    addSurface(scene, 'rectangle');
    refuses(scene, () => addBlend(scene, { surface: 'annulus1', at: 't1' }, { surface: 'rectangle1', at: 't0' }),
      /^v_range: "annulus1" has v in \[0,"2\*pi"\] and "rectangle1" in \[-1,1\]/);
    refuses(scene, () => addBlend(scene, { surface: 'cylinder1', at: 't1' }, { surface: 'cylinder1', at: 't1' }), /^u1\.at: both ends meet t1 of "cylinder1"/);
    refuses(scene, () => addBlend(scene, { surface: 'cylinder1', at: { t: '2', replaces: 't1' } }, { surface: 'cylinder1', at: 't1' }), /both ends meet t1/);
    refuses(scene, () => addBlend(scene, { surface: 'nope', at: 't0' }, { surface: 'cylinder1', at: 't1' }), /^u0\.surface: there is no patch named "nope"/);
    refuses(scene, () => addBlend(scene, { surface: 'blend1', at: 't0' }, { surface: 'cylinder1', at: 't1' }), /^u0\.at: "blend1" is a pde patch: its ends are u0, u1, not "t0"/);
    refuses(scene, () => addBlend(scene, { surface: 'annulus1', at: 't2' }, { surface: 'cylinder1', at: 't1' }), /^u0\.at: must be "t0", "t1"/);
    refuses(scene, () => addBlend(scene, { surface: 'annulus1', at: { t: 't+1' } }, { surface: 'cylinder1', at: 't1' }), /^u0\.at\.t: col 1: 't' cannot be used here/);
    refuses(scene, () => addBlend(scene, { surface: 'annulus1', at: 't1' }, { surface: 'cylinder1', at: 't1' }, { continuity: 'smooth' }), /^u0\.continuity: must be position/);
    refuses(scene, () => addBlend(scene, { surface: 'annulus1', at: 't1' }, { surface: 'cylinder1', at: 't1' }, { power: NaN }), /^u0\.power: not finite/);
    refuses(scene, () => addBlend(scene, { surface: 'annulus1', at: 't1' }, { surface: 'cylinder1', at: 't1' }, { flip: 'yes' }), /^u0\.flip/);
    refuses(scene, () => addBlend(scene, { surface: 'annulus1', at: 't1' }, { surface: 'cylinder1', at: 't1' }, { name: 'blend1' }), /already a patch named "blend1"/);
    // The core's rules between ends: a curve replacing t0 while blend1 meets t0.
    refuses(scene, () => addBlend(scene, { surface: 'annulus1', at: { t: '2.1', replaces: 't0' } }, { surface: 'cylinder1', at: 't1' }),
      /t0 of "annulus1" is replaced by a curve at blend2\.u0, and blend1\.u0 meets it/);
    scene.patches[0].v_range = [0, 'annulus1_h + 2*pi'];
    refuses(scene, () => addBlend(scene, { surface: 'annulus1', at: 't1' }, { surface: 'cylinder1', at: 't1' }), /^v_range: /);
  });
});

describe('fills', () => {
  // Four rectangles around a square hole [-1, 1]², each met at its inner border.
  function frame() {
    const scene = newScene();
    for (const name of ['south', 'east', 'north', 'west']) addSurface(scene, 'rectangle', { name });
    const set = (name, x, y) => Object.assign(scene.patches.find((p) => p.name === name), { x, y, t_range: [1, 2], v_range: [-1, 1] });
    set('south', 'v', '-t');
    set('east', 't', 'v');
    set('north', '-v', 't');
    set('west', '-t', '-v');
    return scene;
  }
  const edgeEnds = (scene, e) => {
    const [p, q] = borderEnds(scene, e.surface, e.at);
    return e.reverse ? [q, p] : [p, q];
  };
  const near = (p, q) => Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]) < 1e-9;

  it('chains four borders picked in any order and either way round, corner to corner', () => {
    for (const order of [['south', 'east', 'north', 'west'], ['west', 'east', 'south', 'north'], ['north', 'south', 'west', 'east']]) {
      const scene = frame();
      const borders = order.map((surface) => ({ surface, at: 't0' }));
      const name = addFill(scene, borders, borders.map((b) => borderEnds(scene, b.surface, b.at)));
      const fill = scene.patches.find((p) => p.name === name);
      assert.equal(name, 'fill1');
      assert.equal(fill.kind, 'bezier');
      assert.deepEqual(fill.degree, [7, 7]);
      assert.equal(fill.energy, 'thin-plate');
      assert.equal(fill.borders.v0.surface, order[0]);
      assert.equal(fill.borders.v0.reverse, false);
      const [v0, u1, v1, u0] = ['v0', 'u1', 'v1', 'u0'].map((e) => edgeEnds(scene, fill.borders[e]));
      assert.ok(near(v0[0], u0[0]) && near(v0[1], u1[0]) && near(u1[1], v1[1]) && near(u0[1], v1[0]), order.join());
      assert.equal(lowestVersion(scene), 4);
    }
  });

  it('refuses borders that do not close, closed borders, a border twice and bad options', () => {
    const scene = frame();
    const borders = ['south', 'east', 'north', 'west'].map((surface) => ({ surface, at: 't0' }));
    const ends = borders.map((b) => borderEnds(scene, b.surface, b.at));
    const far = structuredClone(ends);
    far[2][0][2] += 0.5;
    refuses(scene, () => addFill(scene, borders, far), /^borders: the four borders do not/);
    const outer = borders.map((b, k) => (k === 2 ? { surface: 'north', at: 't1' } : b));
    refuses(scene, () => addFill(scene, outer, outer.map((b) => borderEnds(scene, b.surface, b.at))), /^borders: the four borders do not/);
    refuses(scene, () => addFill(scene, [borders[0], borders[0], borders[1], borders[2]], ends), /^borders\[1\]: t0 of "south" is picked twice/);
    refuses(scene, () => addFill(scene, borders.slice(0, 3), ends), /^borders: expected four/);
    refuses(scene, () => addFill(scene, borders, ends, { degree: [7, 17] }), /^degree: expected \[n, m\]/);
    refuses(scene, () => addFill(scene, borders, ends, { energy: 'soap' }), /^energy: must be/);
    refuses(scene, () => addFill(scene, borders, ends.map((e, k) => (k === 1 ? [e[0], [0, NaN, 0]] : e))), /^endpoints\[1\]\[1\]: expected a point/);
    addSurface(scene, 'annulus');
    const ring = [{ surface: 'annulus1', at: 't0' }, ...borders.slice(1)];
    refuses(scene, () => addFill(scene, ring, ring.map((b) => borderEnds(scene, b.surface, b.at))), /^borders\[0\]: t0 of "annulus1" is closed/);
  });

  it('a fill is accepted and its borders certified by a version-4 core', () => {
    const scene = frame();
    const borders = ['south', 'east', 'north', 'west'].map((surface) => ({ surface, at: 't0' }));
    addFill(scene, borders, borders.map((b) => borderEnds(scene, b.surface, b.at)));
    const { status, stderr } = check(scene);
    assert.equal(status, 0, stderr);
  });
});

describe('PDE ends and Bézier borders as picks (issue 35)', () => {
  // A vase: a pde tube with typed ends (radius 1 at z = 0 to radius 0.6 at z = 2), open at the
  // top; a flat ring above it and a rim of radius 0.6 at z = 2.5.
  function vase() {
    const scene = newScene();
    scene.version = 4;
    scene.patches.push({
      name: 'vase', kind: 'pde', v_range: [0, '2*pi'], operator: { order: 4, b: 1, c: 2, d: 1 },
      boundary: {
        x: { u0: ['cos(v)', '0'], u1: ['0.6*cos(v)', '0'] },
        y: { u0: ['sin(v)', '0'], u1: ['0.6*sin(v)', '0'] },
        z: { u0: ['0', '2'], u1: ['2', '2'] },
      },
    });
    scene.patches.push({ name: 'rim', kind: 'surface', t_range: [0, 0.5], v_range: [0, '2*pi'], x: '0.6*cos(v)', y: '0.6*sin(v)', z: '2.5 + t' });
    return scene;
  }
  const top = [[0.6, 0, 2], [0.6, 0, 2]]; // the vase's u1 at v = 0 and 2π

  it('a fill of a pde end: {patch, at} in the loop, certified by the core', () => {
    const scene = vase();
    const name = addLoopFill(scene, [{ surface: 'vase', at: 'u1' }], [top]);
    assert.deepEqual(scene.patches.at(-1), { name, kind: 'fill', borders: [{ patch: 'vase', at: 'u1' }] });
    const { status, report, stderr } = check(scene);
    assert.equal(status, 0, stderr);
    const joins = report.joins.filter((j) => j.patch === name);
    assert.equal(joins.length, 1);
    assert.ok(joins.every((j) => j.ok && j.level === 'G1'), JSON.stringify(joins));
  });

  it('a blend from a pde end to a surface: a chained end with the pde patch\'s v_range, certified', () => {
    const scene = vase();
    const name = addBlend(scene, { surface: 'vase', at: 'u1' }, { surface: 'rim', at: 't0' }, { continuity: 'tangency', power: 0.5 });
    const blend = scene.patches.find((p) => p.name === name);
    assert.deepEqual(blend.ends.u0, { patch: 'vase', at: 'u1', continuity: 'tangency', power: 0.5 });
    assert.deepEqual(blend.ends.u1, { surface: 'rim', at: 't0', continuity: 'tangency', power: 0.5 });
    assert.deepEqual(blend.v_range, [0, '2*pi']);
    const { status, report, stderr } = check(scene);
    assert.equal(status, 0, stderr);
    assert.ok(report.joins.filter((j) => j.patch === name).every((j) => j.ok && j.level === 'G1'));
  });

  it('refuses a fill as a border, a pde patch\'s t0, a Bézier fill of pde ends, an expression power on a chain', () => {
    const scene = vase();
    addLoopFill(scene, [{ surface: 'vase', at: 'u1' }], [top]);
    refuses(scene, () => addLoopFill(scene, [{ surface: 'fill1', at: 'u0' }], [top]), /^borders\[0\]\.surface: "fill1" is a fill: its border belongs to the patches it closes/);
    refuses(scene, () => addLoopFill(scene, [{ surface: 'vase', at: 't1' }], [top]), /^borders\[0\]\.at: "vase" is a pde patch: its ends are u0, u1, not "t1"/);
    refuses(scene, () => addFill(scene, [0, 1, 2, 3].map(() => ({ surface: 'vase', at: 'u1' })), [top, top, top, top]),
      /^borders\[0\]\.surface: "vase" is a pde patch; a Bézier fill's borders lie on "surface" patches/);
    refuses(scene, () => addBlend(scene, { surface: 'vase', at: 'u1' }, { surface: 'rim', at: 't0' }, { power: 'v' }), /^u0\.power: an end on a patch takes a number/);
    refuses(scene, () => addBlend(scene, { surface: 'vase', at: 'u1' }, { surface: 'rim', at: 't0' }, { power: -1 }), /^u0\.power: must be positive/);
    refuses(scene, () => addBlend(scene, { surface: 'vase', at: 'u1' }, { surface: 'vase', at: 'u1' }), /^u1\.at: both ends meet u1 of "vase"/);
    scene.patches.find((p) => p.name === 'rim').v_range = [0, 3];
    refuses(scene, () => addBlend(scene, { surface: 'vase', at: 'u1' }, { surface: 'rim', at: 't0' }), /^v_range: "vase" has v in \[0,"2\*pi"\] and "rim" in \[0,3\]/);
  });
});

describe('trigonometric trimlines', () => {
  it('recovers a trigonometric sum from equally spaced samples, as text that evaluates to it', () => {
    const tau = (v) => 0.5 + 0.2 * Math.cos(v) - 0.1 * Math.sin(2 * v) + 0.05 * Math.cos(3 * v);
    const samples = Array.from({ length: 9 }, (_, k) => tau((2 * Math.PI * k) / 9));
    const fit = trigCurveFromSamples(samples, [0, '2*pi'], 3);
    assert.equal(fit.text, '0.5 + 0.2*cos(v) - 0.1*sin(2*v) + 0.05*cos(3*v)');
    const f = compile(fit.text, {}, ['v']);
    for (const v of [0, 0.3, 2, 5]) assert.ok(Math.abs(f({ v }) - tau(v)) < 1e-6);
  });

  it('takes [v, t] pairs and other periods; fewer samples mean fewer terms', () => {
    const tau = (v) => 1 + 0.3 * Math.sin((2 * Math.PI * v) / 4);
    const fit = trigCurveFromSamples([0, 0.5, 1.7, 2.2, 3.1].map((v) => [v, tau(v)]), [0, 4], 5);
    assert.equal(fit.a.length, 2, '5 samples determine 2 harmonics');
    assert.match(fit.text, /^1 \+ 0\.3\*sin\(1\.57079632679\*v\)$/);
    assert.equal(trigCurveFromSamples([2, 2], [0, '2*pi']).text, '2');
    const ls = trigCurveFromSamples([1, 2, 1, 2, 1, 2, 1, 2, 1, 2, 1, 2], [0, '2*pi'], 1);
    assert.equal(ls.text, '1.5', 'least squares: the 6th harmonic is beyond K = 1');
  });

  it('refuses what it cannot fit', () => {
    assert.throws(() => trigCurveFromSamples([], [0, 1]), /values: /);
    assert.throws(() => trigCurveFromSamples([1, NaN], [0, 1]), /values\[1\]: not a finite number/);
    assert.throws(() => trigCurveFromSamples([1, 2], [1, 1]), /vRange: v1 must be greater/);
    assert.throws(() => trigCurveFromSamples([1, 2], [0, 'q']), /vRange\[1\]: col 1: unknown parameter 'q'/);
    assert.throws(() => trigCurveFromSamples([[1, 1], [1, 2], [1, 3]], [0, 6]), /do not determine/);
    assert.throws(() => trigCurveFromSamples([1, 2], [0, 1], -1), /maxTerms/);
  });
});

it('a gizmo drag moves the parameters a placement names, clamped to their ranges; expressions stay; one edit', async () => {
  const { dragPlacement, placementValues } = await import('../../web/state/placement.js');
  const scene = {
    format: 'pdesurf-scene', version: 4, parameters: { wing_x: { value: 0.3, min: 0, max: 0.6 }, tilt: { value: 5, min: -10, max: 10 } },
    patches: [{ name: 'w', kind: 'surface', x: 't', y: 'v', z: '0', t_range: [0, 1], v_range: [0, 1], placement: { translate: ['wing_x', 0, '0.1*2'], rotate: [0, 'tilt', 0] } }],
  };
  assert.deepEqual(placementValues(scene, scene.patches[0].placement), { translate: [0.3, 0, 0.2], rotate: [0, 5, 0], scale: 1 });
  dragPlacement(scene, 'w', { translate: [0.5, 0.25, 0.7], rotate: [1, 7, 0], scale: 2 });
  assert.equal(scene.parameters.wing_x.value, 0.5);
  assert.equal(scene.parameters.tilt.value, 7);
  assert.deepEqual(scene.patches[0].placement, { translate: ['wing_x', 0.25, '0.1*2'], rotate: [1, 'tilt', 0], scale: 2 });
  dragPlacement(scene, 'w', { translate: [9, 0.25, 0.2], rotate: [1, -40, 0], scale: 2 });
  assert.equal(scene.parameters.wing_x.value, 0.6, 'past its range: stops at the end');
  assert.equal(scene.parameters.tilt.value, -10);
  // A placement of numbers only is replaced as before.
  scene.patches[0].placement = { translate: [1, 2, 3] };
  dragPlacement(scene, 'w', { translate: [4, 5, 6], rotate: [0, 0, 0], scale: 1 });
  assert.deepEqual(scene.patches[0].placement.translate, [4, 5, 6]);
});
