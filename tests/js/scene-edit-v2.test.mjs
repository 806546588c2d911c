// Version-2 editing of the page state: expression fields written into the scene,
// string boundary slots through order changes, parameters added and removed, and the
// pure helpers behind the URL hash, the gallery and the inline error placement.
import { describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { createSceneState } from '../../web/state/scene-state.js';
import { boundarySlot, forceOf, hasExpressions } from '../../web/state/expression-edit.js';
import { defaultRange, parameterNameProblem } from '../../web/state/parameter-edit.js';
import { readHash, exampleIdFromHash } from '../../web/state/hash.js';
import { groupByPaper } from '../../web/ui/gallery.js';
import { fieldForMessage } from '../../web/ui/expression-field.js';

function fig2a() {
  const s = createSceneState();
  s.setScene({
    format: 'pdesurf-scene', version: 2,
    parameters: { r0: { value: 1.8, min: 0.8, max: 3 } },
    patches: [
      { name: 'blend', kind: 'pde', operator: { order: 4, b: 1, c: 2, d: 1 },
        boundary: { x: { u0: ['r0*cos(v)', 'r0p*cos(v)'], u1: ['r1*cos(v)', 'r1p*cos(v)'] }, z: { u1: ['h1', 'h1p'] } } },
      { name: 'plane', kind: 'surface', x: 'r0*cos(v)', y: 'r0*sin(v)', z: '0' },
    ],
  }, 'you2004-fig2a');
  return s;
}
const scene = (s) => JSON.parse(s.text());

describe('expression fields', () => {
  it('read missing coordinates, lists and entries as "0"', () => {
    const s = fig2a();
    const blend = s.patch('blend');
    assert.equal(hasExpressions(s.scene), true);
    assert.equal(hasExpressions({ version: 1 }), false);
    assert.equal(boundarySlot(blend, 'x', 'u0', 1), 'r0p*cos(v)');
    assert.equal(boundarySlot(blend, 'y', 'u0', 0), '0');
    assert.equal(boundarySlot(blend, 'z', 'u0', 1), '0');
    assert.equal(forceOf(blend, 'x'), '0');
  });

  it('write boundary slots, forces and surface coordinates where the solver reads them', () => {
    const s = fig2a();
    s.setExpression('blend', { kind: 'boundary', axis: 'x', end: 'u1', k: 1 }, 'r1p*cos(v) + 0.1');
    s.setExpression('blend', { kind: 'boundary', axis: 'y', end: 'u0', k: 1 }, 'sin(v)'); // y had nothing
    s.setExpression('blend', { kind: 'force', axis: 'z' }, 'u*(1 - u)');
    s.setExpression('plane', { kind: 'surface', axis: 'z' }, '0.2*t');
    const p = scene(s).patches;
    assert.deepEqual(p[0].boundary.x.u1, ['r1*cos(v)', 'r1p*cos(v) + 0.1']);
    assert.deepEqual(p[0].boundary.y, { u0: ['0', 'sin(v)'] });
    assert.deepEqual(p[0].force, { z: 'u*(1 - u)' });
    assert.equal(p[1].z, '0.2*t');
    s.setExpression('blend', { kind: 'force', axis: 'z' }, '  '); // empty: no force at all
    assert.equal('force' in scene(s).patches[0], false);
    assert.throws(() => s.setExpression('nope', { kind: 'force', axis: 'x' }, '1'), /no patch/);
    assert.throws(() => s.setExpression('blend', { kind: 'what', axis: 'x' }, '1'), /unknown expression field/);
  });

  it('keep string slots through order changes and pad with "0", never a term list', () => {
    const s = fig2a();
    s.setOperatorOrder('blend', 'x', 2);
    assert.deepEqual(scene(s).patches[0].boundary.x, { u0: ['r0*cos(v)'], u1: ['r1*cos(v)'] });
    s.setOperatorOrder('blend', 'x', 6);
    assert.deepEqual(scene(s).patches[0].boundary.x, { u0: ['r0*cos(v)', 'r0p*cos(v)', '0'], u1: ['r1*cos(v)', 'r1p*cos(v)', '0'] });
    s.setOperatorOrder('blend', 'z', 6);
    assert.deepEqual(scene(s).patches[0].boundary.z, { u0: ['0', '0', '0'], u1: ['h1', 'h1p', '0'] });
    s.setOperatorOrder('blend', 'x', 4);
    assert.deepEqual(scene(s).patches[0].boundary.x.u0, ['r0*cos(v)', 'r0p*cos(v)']);
  });
});

describe('parameters', () => {
  it('add with a range around the value, and refuse bad or taken names', () => {
    const s = fig2a();
    assert.deepEqual(s.addParameter('k', 0.3), { value: 0.3, min: -0.7, max: 1.3 });
    assert.deepEqual(defaultRange(0), [-1, 1]);
    assert.deepEqual(defaultRange(-5), [-10, 0]);
    assert.throws(() => s.addParameter('k', 1), /already a parameter/);
    assert.throws(() => s.addParameter('2x', 1), /not a name/);
    assert.throws(() => s.addParameter('sin', 1), /already a constant, variable or function/);
    assert.throws(() => s.addParameter('q', NaN), /finite/);
    assert.equal(parameterNameProblem(s.scene, ''), 'a parameter needs a name');
    assert.match(parameterNameProblem(s.scene, 'x'.repeat(65)), /at most 64/);
    assert.match(parameterNameProblem(s.scene, '__proto__'), /reserved/);
    assert.equal(parameterNameProblem(s.scene, 'constructor'), null); // assignment makes an own key
  });

  it('remove, even one an expression still uses (the solver then says where)', () => {
    const s = fig2a();
    s.removeParameter('r0');
    assert.deepEqual(scene(s).parameters, {});
    assert.throws(() => s.removeParameter('r0'), /no parameter/);
    const bare = createSceneState();
    bare.setScene({ version: 2, patches: [] }, null);
    bare.addParameter('a', 2);
    assert.deepEqual(scene(bare).parameters, { a: { value: 2, min: 0, max: 4 } });
  });
});

describe('URL hash', () => {
  it('tells a state link from an example id and from nothing', () => {
    assert.deepEqual(readHash('#s=1.abc+def'), { kind: 'state', text: 's=1.abc+def' });
    assert.deepEqual(readHash('#example=x&s=1.abc'), { kind: 'state', text: 'example=x&s=1.abc' });
    assert.deepEqual(readHash('#example=you2004-fig2a'), { kind: 'example', id: 'you2004-fig2a' });
    assert.deepEqual(readHash('#example=%3Cb%3E'), { kind: 'example', id: '<b>' });
    assert.deepEqual(readHash(''), { kind: 'none' });
    assert.deepEqual(readHash('#sx=1'), { kind: 'none' });
    assert.equal(exampleIdFromHash('#s=1.abc'), null);
  });
});

describe('gallery grouping', () => {
  it('groups by paper in catalogue order', () => {
    const groups = groupByPaper([
      { id: 'a', source: { paper: 'seed 000' } }, { id: 'b', source: { paper: 'seed 003' } },
      { id: 'c', source: { paper: 'seed 000' } }, { id: 'd', source: null },
    ]);
    assert.deepEqual([...groups.keys()], ['seed 000', 'seed 003', 'other examples']);
    assert.deepEqual(groups.get('seed 000').map((e) => e.id), ['a', 'c']);
  });
});

describe('inline error placement', () => {
  const fields = ['patches[0].boundary.x.u0[1]', 'patches[0].boundary.x.u0[10]', 'patches[1].x', 'patches[0].force.x']
    .map((path) => ({ path }));
  const last = fields[2];
  it('puts a message beside the field it names', () => {
    assert.equal(fieldForMessage(fields, "patches[0].boundary.x.u0[1]: col 5: unknown function 'cso'", last), fields[0]);
    assert.equal(fieldForMessage(fields, 'patches[0].boundary.x.u0[10]: col 1: x', last), fields[1]);
    assert.equal(fieldForMessage(fields, "patches[0].force.x: col 1: unknown parameter 'p0'", null), fields[3]);
  });
  it('uses the field edited last only when the message names no field', () => {
    assert.equal(fieldForMessage(fields, "patch 'blend': component z: 'sqrt(x)' is not finite at v = 0", last), last);
    assert.equal(fieldForMessage(fields, 'patches[0].operator.b: b_x = 0 removes the 4th u-derivative', last), null);
    assert.equal(fieldForMessage(fields, 'component z: not finite', null), null);
  });
});
