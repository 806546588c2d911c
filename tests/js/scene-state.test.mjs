// The page state is the scene object: operator and method controls write into it,
// and JSON.stringify(scene) is what the solver sees.
import { describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { createSceneState } from '../../web/state/scene-state.js';

const cond = (fn, coef) => [{ fn, coef }];

function stateWith(patch) {
  const s = createSceneState();
  s.setScene({ patches: [{ name: 'blend', kind: 'pde', ...patch }, { name: 'plane', kind: 'ruled' }] }, 'ex');
  return s;
}
const solved = (s) => JSON.parse(s.text()).patches[0];

describe('operator coefficients', () => {
  it('split the single form per coordinate, keeping the other values and expressions', () => {
    const s = stateWith({ operator: { order: 4, b: 1, c: [2, 2, 'c_z'], d: 'dd' } });
    s.setOperatorParam('blend', 'y', 'b', 0.5);
    assert.deepEqual(solved(s).operator, {
      x: { order: 4, b: 1, c: 2, d: 'dd' },
      y: { order: 4, b: 0.5, c: 2, d: 'dd' },
      z: { order: 4, b: 1, c: 'c_z', d: 'dd' },
    });
    s.setOperatorParam('blend', 'z', 'd', 7); // already per coordinate: only z.d changes
    assert.deepEqual(solved(s).operator.z, { order: 4, b: 1, c: 'c_z', d: 7 });
    assert.deepEqual(solved(s).operator.x, { order: 4, b: 1, c: 2, d: 'dd' });
  });

  it('write coefficients[k] into the coefficient form', () => {
    const s = stateWith({ operator: { order: 4, coefficients: [1, [2, 3, 4], 1] } });
    s.setOperatorParam('blend', 'y', 'coefficients[2]', 5);
    assert.deepEqual(solved(s).operator, {
      x: { order: 4, coefficients: [1, 2, 1] },
      y: { order: 4, coefficients: [1, 3, 5] },
      z: { order: 4, coefficients: [1, 4, 1] },
    });
  });

  it('refuse unknown patches and axes', () => {
    const s = stateWith({ operator: { order: 2, s: 1, t: 1 } });
    assert.throws(() => s.setOperatorParam('nope', 'x', 's', 1), /no pde patch/);
    assert.throws(() => s.setOperatorParam('plane', 'x', 's', 1), /no pde patch/);
    assert.throws(() => s.setOperatorParam('blend', 'w', 's', 1), /axis/);
    assert.throws(() => s.setOperatorOrder('blend', 'x', 3), /order/);
  });
});

describe('operator order', () => {
  const fig2a = () => stateWith({
    operator: { order: 4, b: 1, c: 2, d: 1 },
    boundary: {
      x: { u0: [cond('cos', 'r0'), cond('cos', 'r0p')], u1: [cond('cos', 'r1'), cond('cos', 'r1p')] },
      z: { u0: [[], []], u1: [cond('poly', 'h1'), cond('poly', 'h1p')] },
    },
  });

  it('rewrites the coordinate with defaults and trims its boundary lists', () => {
    const s = fig2a();
    assert.deepEqual(s.setOperatorOrder('blend', 'z', 2), { s: 1, t: 1 });
    const p = solved(s);
    assert.deepEqual(p.operator.z, { order: 2, s: 1, t: 1 });
    assert.deepEqual(p.operator.x, { order: 4, b: 1, c: 2, d: 1 });
    assert.deepEqual(p.boundary.z, { u0: [[]], u1: [cond('poly', 'h1')] });
    assert.deepEqual(p.boundary.x.u1, [cond('cos', 'r1'), cond('cos', 'r1p')]); // other axes untouched
  });

  it('restores trimmed conditions when the order rises again, and pads the rest with zero', () => {
    const s = fig2a();
    const original = solved(s).boundary;
    s.setOperatorOrder('blend', 'z', 2);
    assert.deepEqual(s.setOperatorOrder('blend', 'z', 6), { a: 1 });
    assert.deepEqual(solved(s).boundary.z, {
      u0: [[], [], []],
      u1: [cond('poly', 'h1'), cond('poly', 'h1p'), []],
    });
    s.setOperatorOrder('blend', 'z', 2);
    s.setOperatorOrder('blend', 'z', 4);
    const p = solved(s);
    assert.deepEqual(p.boundary, original);
    assert.deepEqual(p.operator.z, { order: 4, b: 1, c: 2, d: 1 });
  });

  it('creates missing lists, ignores the same order, and forgets the stash on a new scene', () => {
    const s = fig2a();
    assert.equal(s.setOperatorOrder('blend', 'x', 4), null);
    assert.deepEqual(solved(s).operator, { order: 4, b: 1, c: 2, d: 1 }); // untouched
    s.setOperatorOrder('blend', 'y', 6); // y had no boundary entry at all
    assert.deepEqual(solved(s).boundary.y, { u0: [[], [], []], u1: [[], [], []] });

    // A patch of the same name in another scene must not get this scene's conditions.
    s.setOperatorOrder('blend', 'x', 2);
    s.setScene(stateWith({ operator: { order: 2, s: 1, t: 1 }, boundary: { x: { u0: [[]], u1: [[]] } } }).scene, 'other');
    s.setOperatorOrder('blend', 'x', 4);
    assert.deepEqual(solved(s).boundary.x, { u0: [[], []], u1: [[], []] });
  });
});

describe('method', () => {
  it('writes a named method and removes the field for auto', () => {
    const s = stateWith({ operator: { order: 2, s: 1, t: 1 } });
    assert.equal(s.methodOf('blend'), 'auto');
    s.setMethod('blend', 'closed');
    assert.equal(solved(s).method, 'closed');
    assert.equal(s.methodOf('blend'), 'closed');
    s.setMethod('blend', 'auto');
    assert.equal('method' in solved(s), false);
    assert.equal(s.methodOf('blend'), 'auto');
  });
});
