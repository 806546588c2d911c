// The surface library (web/state/surface-library.js): every kind builds a surface the core
// accepts, with fresh valid parameter names, and every kind blends by reference into a plane
// annulus (or rectangle) and into random library surfaces with a certified join.
//   PDESURF_CLI=build/native/pdesurf node --test tests/js/surface-library.test.mjs
import { describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { SURFACE_LIBRARY, addSurface, libraryEntry } from '../../web/state/surface-library.js';
import { newScene, addBlend } from '../../web/state/scene-build.js';
import { PARAMETER_NAME, RESERVED } from '../../web/state/expr-text.js';
import { check, rng, refuses } from './build-helpers.mjs';

const closedKinds = SURFACE_LIBRARY.filter((e) => e.closed);
const openKinds = SURFACE_LIBRARY.filter((e) => !e.closed);
const LEVEL = { tangency: 'G1', curvature: 'G2' };

/** The certificate's verdict on each join, with the promise it had to keep. */
function joinsCertified(scene, continuity, what) {
  const { report, stderr } = check(scene);
  assert.ok(report, `${what}: the core refused the scene: ${stderr}`);
  assert.equal(report.joins.length, 2, what);
  for (const j of report.joins) {
    assert.equal(j.level, LEVEL[continuity], `${what}: ${j.surface} promises ${LEVEL[continuity]}`);
    assert.ok(j.ok, `${what}: join to ${j.surface} fails: G1 ${j.g1_deg}°, G2 ${j.g2_rel}, fold ${j.fold}`);
  }
  return report;
}

describe('library entries', () => {
  it('each has an id, a label, parameters in range and a build', () => {
    const ids = new Set();
    for (const e of SURFACE_LIBRARY) {
      assert.ok(!ids.has(e.id), e.id);
      ids.add(e.id);
      assert.equal(typeof e.label, 'string');
      assert.equal(typeof e.build, 'function');
      for (const p of e.params) assert.ok(p.min <= p.value && p.value <= p.max, `${e.id}.${p.key}`);
    }
    assert.deepEqual([...ids], ['annulus', 'rectangle', 'cylinder', 'cone', 'sphere', 'torus', 'ellipsoid', 'hyperboloid',
      'explicit-disc', 'explicit-rectangle', 'custom']);
  });

  for (const e of SURFACE_LIBRARY) {
    it(`${e.id}: addSurface builds a surface the core accepts, with its own valid parameters`, () => {
      const scene = newScene();
      const name = addSurface(scene, e.id);
      assert.equal(name, `${e.id.replace('-', '_')}1`);
      assert.equal(scene.version, 4);
      const patch = scene.patches[0];
      assert.equal(patch.kind, 'surface');
      assert.deepEqual(Object.keys(scene.parameters).length, e.params.length);
      for (const [pname, p] of Object.entries(scene.parameters)) {
        assert.match(pname, PARAMETER_NAME);
        assert.ok(!RESERVED.has(pname));
        assert.ok(pname.startsWith(`${name}_`), pname);
        assert.ok(p.min <= p.value && p.value <= p.max);
      }
      // v spans [0, 2π] on the closed families, [-1, 1] on the open ones.
      assert.deepEqual(patch.v_range, e.closed ? [0, '2*pi'] : [-1, 1]);
      const { status, stderr } = check(scene);
      assert.equal(status, 0, stderr);
    });
  }

  it('a second surface of a kind gets the next name and parameters of its own', () => {
    const scene = newScene();
    assert.equal(addSurface(scene, 'cylinder'), 'cylinder1');
    assert.equal(addSurface(scene, 'cylinder'), 'cylinder2');
    assert.equal(scene.patches[1].x, 'cylinder2_r*cos(v)');
    assert.deepEqual(scene.patches[1].t_range, ['cylinder2_z0', 'cylinder2_z1']);
    // A parameter already named like the next one is skipped, not overwritten.
    scene.parameters.cylinder3_r = { value: 7, min: 0, max: 9 };
    addSurface(scene, 'cylinder');
    assert.equal(scene.parameters.cylinder3_r.value, 7);
    assert.equal(scene.patches[2].x, 'cylinder3_r2*cos(v)');
    assert.equal(check(scene).status, 0);
  });

  it('a name with markup is stored as text; its parameters get an identifier prefix', () => {
    const scene = newScene();
    assert.equal(addSurface(scene, 'sphere', { name: '<b>x</b>' }), '<b>x</b>');
    assert.equal(scene.patches[0].name, '<b>x</b>');
    assert.ok(Object.keys(scene.parameters).every((n) => n.startsWith('b_x_b_') && PARAMETER_NAME.test(n)));
    assert.equal(check(scene).status, 0);
  });

  it('explicit surfaces take f(x, y) with the entry\'s keys; custom takes its expressions', () => {
    const scene = newScene();
    addSurface(scene, 'explicit-rectangle', { f: 'a*x*y' });
    assert.equal(scene.patches[0].z, 'explicit_rectangle1_a*t*(explicit_rectangle1_w*v)');
    addSurface(scene, 'explicit-disc', { f: 'a*sin(x) + y' });
    assert.equal(scene.patches[1].z, 'explicit_disc1_a*sin((t*cos(v))) + (t*sin(v))');
    addSurface(scene, 'custom', { x: 't', y: 'v', z: 't*v', t_range: [0, 2], v_range: [-1, '1'] });
    assert.deepEqual(scene.patches[2], { name: 'custom1', kind: 'surface', t_range: [0, 2], v_range: [-1, '1'], x: 't', y: 'v', z: 't*v' });
    assert.equal(check(scene).status, 0);
  });

  it('refuses, naming the field, and changes nothing', () => {
    const scene = newScene();
    addSurface(scene, 'cylinder');
    refuses(scene, () => addSurface(scene, 'klein-bottle'), /^kind: no library surface "klein-bottle"/);
    refuses(scene, () => addSurface(scene, 'cone', { name: 'cylinder1' }), /already a patch named "cylinder1"/);
    refuses(scene, () => addSurface(scene, 'cone', { name: '' }), /cannot be empty/);
    refuses(scene, () => addSurface(scene, 'cone', { name: 'a\nb' }), /control characters/);
    refuses(scene, () => addSurface(scene, 'cone', { name: 'é'.repeat(33) }), /at most 64 bytes/);
    refuses(scene, () => addSurface(scene, 'explicit-disc', { f: 'a*q' }), /^f: col 3: unknown parameter 'q'/);
    refuses(scene, () => addSurface(scene, 'explicit-disc', { f: 'a*t' }), /^f: col 3: 't' cannot be used here/);
    refuses(scene, () => addSurface(scene, 'custom', { x: 'cos(v' }), /^x: col 6: unbalanced/);
    refuses(scene, () => addSurface(scene, 'custom', { z: 'sn(t)' }), /^z: col 1: unknown function 'sn'/);
    refuses(scene, () => addSurface(scene, 'custom', { t_range: [0, 't'] }), /^t_range\[1\]: /);
    refuses(scene, () => addSurface(scene, 'custom', { v_range: [0] }), /^v_range: expected \[from, to\]/);
    const v1 = { format: 'pdesurf-scene', version: 1, patches: [] };
    refuses(v1, () => addSurface(v1, 'cylinder'), /^version: a version-1 scene/);
  });
});

describe('library surfaces blended by reference', () => {
  for (const continuity of ['tangency', 'curvature']) {
    it(`every closed kind's t0 blends from a plane annulus's inner border, ${continuity}: certified, no crossings`, () => {
      for (const e of closedKinds) {
        const scene = newScene();
        const plane = addSurface(scene, 'annulus');
        const other = addSurface(scene, e.id);
        addBlend(scene, { surface: plane, at: 't0' }, { surface: other, at: 't0' }, { continuity });
        joinsCertified(scene, continuity, e.id);
        const { status, stderr } = check(scene);
        assert.equal(status, 0, `${e.id}: ${stderr}`);
      }
    });

    it(`every open kind blends from a plane rectangle's border, ${continuity}: certified`, () => {
      for (const e of openKinds) {
        const scene = newScene();
        const plane = addSurface(scene, 'rectangle');
        const other = addSurface(scene, e.id);
        scene.patches[1].z = `${scene.patches[1].z} + 2`; // apart (placement is version 4)
        addBlend(scene, { surface: plane, at: 't1' }, { surface: other, at: 't0' }, { continuity });
        joinsCertified(scene, continuity, e.id);
      }
    });
  }

  it('the default annulus and cylinder make a clean fillet (the Add menu\'s first example)', () => {
    const scene = newScene();
    addSurface(scene, 'annulus');
    addSurface(scene, 'cylinder');
    assert.equal(addBlend(scene, { surface: 'annulus1', at: 't0' }, { surface: 'cylinder1', at: 't0' }), 'blend1');
    const { status, report } = check(scene, 64);
    assert.equal(status, 0);
    assert.equal(report.crossings.length, 0);
    assert.ok(report.joins.every((j) => j.level === 'G1' && j.ok && !j.fold));
  });

  it('120 random pairs over the whole library, both borders, G1 and G2: every join certified', () => {
    const random = rng(20261130);
    const pick = (list) => list[Math.floor(random() * list.length)];
    let crossingFree = 0;
    for (let k = 0; k < 120; k++) {
      const family = random() < 0.8 ? closedKinds : openKinds;
      const [A, B] = [pick(family), pick(family)];
      const [ea, eb] = [pick(['t0', 't1']), pick(['t0', 't1'])];
      const continuity = pick(['tangency', 'curvature']);
      const scene = newScene();
      const a = addSurface(scene, A.id);
      const b = addSurface(scene, B.id);
      addBlend(scene, { surface: a, at: ea }, { surface: b, at: eb }, { continuity });
      const report = joinsCertified(scene, continuity, `${A.id}:${ea} - ${B.id}:${eb} ${continuity}`);
      if (report.crossings.length === 0) crossingFree++;
    }
    // Crossings are geometry (two default surfaces may overlap), not the join: most pairs have none.
    assert.ok(crossingFree >= 60, `${crossingFree} of 120 pairs without crossings`);
  });

  it('libraryEntry finds entries by id', () => {
    assert.equal(libraryEntry('torus').label, 'torus zone');
    assert.equal(libraryEntry('nope'), undefined);
  });
});
