// The page state is the scene object: operator sliders write plain numbers into it.
import { it } from 'node:test';
import assert from 'node:assert/strict';
import { createSceneState } from '../../web/state/scene-state.js';

it('writes one operator component, widening a scalar to a 3-array', () => {
  const s = createSceneState();
  s.setScene({ patches: [{ name: 'blend', kind: 'pde', operator: { order: 4, b: 1, c: [2, 2, 'c_z'], d: 'dd' } }] }, 'x');
  s.setOperatorComponent('blend', 'b', 'y', 0.5);
  s.setOperatorComponent('blend', 'c', 'x', 3);
  s.setOperatorComponent('blend', 'd', 'z', 7);
  assert.deepEqual(JSON.parse(s.text()).patches[0].operator, { order: 4, b: [1, 0.5, 1], c: [3, 2, 'c_z'], d: ['dd', 'dd', 7] });
  assert.throws(() => s.setOperatorComponent('nope', 'b', 'x', 1), /no pde patch/);
});
