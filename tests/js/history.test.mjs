// The page's undo history (web/state/history.js): a base, bounded steps that drop the
// oldest, a redo branch cut by a new step, and no step for a state equal to the current one.
//   node --test tests/js/history.test.mjs
import { describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { createHistory, sameSnapshot, DEFAULT_CAPACITY, DEFAULT_MAX_CHARS } from '../../web/state/history.js';

const snap = (value, extra = {}) => ({
  sceneText: JSON.stringify({ parameters: { r: { value } } }),
  grid: { nu: 64, nv: 64 },
  exampleId: 'ex',
  title: 'Example',
  ...extra,
});
const valueOf = (s) => JSON.parse(s.sceneText).parameters.r.value;

describe('undo history', () => {
  it('the first snapshot is the base: nothing to undo or redo', () => {
    const h = createHistory();
    assert.equal(h.current(), null);
    assert.equal(h.push(snap(0)), true);
    assert.equal(h.canUndo(), false);
    assert.equal(h.canRedo(), false);
    assert.equal(h.depth(), 0);
    assert.equal(h.undo(), null);
    assert.equal(h.redo(), null);
    assert.equal(valueOf(h.current()), 0);
  });

  it('undoes and redoes step by step, returning the snapshot to restore', () => {
    const h = createHistory();
    for (let v = 0; v <= 3; v++) h.push(snap(v));
    assert.equal(h.depth(), 3);
    assert.equal(valueOf(h.undo()), 2);
    assert.equal(valueOf(h.undo()), 1);
    assert.equal(h.redoDepth(), 2);
    assert.equal(valueOf(h.redo()), 2);
    assert.equal(valueOf(h.current()), 2);
    assert.equal(valueOf(h.redo()), 3);
    assert.equal(h.redo(), null);
    assert.equal(h.canRedo(), false);
  });

  it('a new step after undos cuts off the redo branch', () => {
    const h = createHistory();
    for (let v = 0; v <= 3; v++) h.push(snap(v));
    h.undo();
    h.undo();
    assert.equal(h.push(snap(10)), true);
    assert.equal(h.canRedo(), false);
    assert.equal(h.redo(), null);
    assert.equal(valueOf(h.undo()), 1);
    assert.equal(valueOf(h.undo()), 0);
    assert.equal(h.undo(), null);
  });

  it('a snapshot equal to the current one is no step (and keeps the redo branch)', () => {
    const h = createHistory();
    h.push(snap(0));
    h.push(snap(1));
    assert.equal(h.push(snap(1)), false);
    assert.equal(h.depth(), 1);
    h.undo();
    assert.equal(h.push(snap(0)), false, 're-committing the restored state is no step');
    assert.equal(h.canRedo(), true);
    assert.equal(valueOf(h.redo()), 1);
  });

  it('the grid, the example and the title are part of the state', () => {
    const h = createHistory();
    h.push(snap(0));
    assert.equal(h.push(snap(0, { grid: { nu: 128, nv: 64 } })), true);
    assert.equal(h.push(snap(0, { grid: { nu: 128, nv: 64 }, exampleId: 'other' })), true);
    assert.equal(h.push(snap(0, { grid: { nu: 128, nv: 64 }, exampleId: 'other', title: 'Other' })), true);
    assert.equal(h.depth(), 3);
    assert.deepEqual(h.undo().grid, { nu: 128, nv: 64 });
    assert.equal(h.undo().exampleId, 'ex');
    assert.deepEqual(h.undo().grid, { nu: 64, nv: 64 });
  });

  it('keeps at least 100 steps by default, then drops the oldest', () => {
    assert.ok(DEFAULT_CAPACITY >= 100);
    const h = createHistory();
    for (let v = 0; v <= DEFAULT_CAPACITY + 50; v++) h.push(snap(v));
    assert.equal(h.depth(), DEFAULT_CAPACITY);
    let last = null;
    let n = 0;
    for (let s = h.undo(); s; s = h.undo()) {
      last = s;
      n++;
    }
    assert.equal(n, DEFAULT_CAPACITY);
    assert.equal(valueOf(last), 50, 'the 50 oldest were dropped');
  });

  it('a small capacity drops the oldest steps', () => {
    const h = createHistory({ capacity: 3 });
    for (let v = 0; v < 10; v++) h.push(snap(v));
    assert.equal(h.depth(), 3);
    assert.deepEqual([h.undo(), h.undo(), h.undo()].map(valueOf), [8, 7, 6]);
    assert.equal(h.undo(), null);
    assert.throws(() => createHistory({ capacity: 0 }), RangeError);
  });

  it('the steps hold at most maxChars of scene text: large scenes drop the oldest, the current one stays', () => {
    const big = (value, chars) => snap(value, { sceneText: JSON.stringify({ parameters: { r: { value } }, pad: 'x'.repeat(chars) }) });
    const h = createHistory({ maxChars: 1000 });
    for (let v = 0; v < 10; v++) h.push(big(v, 280)); // ~320 characters each: three fit
    assert.equal(h.depth(), 2, 'the base and two steps');
    assert.deepEqual([h.undo(), h.undo()].map(valueOf), [8, 7]);
    assert.equal(h.undo(), null);
    // One scene past the budget alone is still the current step (nothing to undo to).
    const one = createHistory({ maxChars: 100 });
    one.push(big(0, 50));
    one.push(big(1, 500));
    assert.equal(valueOf(one.current()), 1);
    assert.equal(one.depth(), 0);
    // The page's default: 64 MiB, four scenes at the 16 MiB a scene may be.
    assert.equal(DEFAULT_MAX_CHARS, 64 << 20);
  });

  it('replace() swaps the current step and cuts the redo branch', () => {
    const h = createHistory();
    h.replace(snap(0)); // no base yet: becomes it
    assert.equal(h.depth(), 0);
    h.push(snap(1));
    h.push(snap(2));
    h.undo();
    h.replace(snap(5));
    assert.equal(h.canRedo(), false);
    assert.equal(valueOf(h.current()), 5);
    assert.equal(valueOf(h.undo()), 0);
  });

  it('replace() by the step before makes the two one (an opening that never drew, undone by the page)', () => {
    const h = createHistory();
    h.push(snap(0));
    h.push(snap(1));
    h.push(snap(9)); // e.g. a file whose scene does not solve
    assert.equal(h.replace(snap(1)), true); // the page shows the scene before it again
    assert.equal(h.depth(), 1);
    assert.equal(valueOf(h.current()), 1);
    assert.equal(valueOf(h.undo()), 0);
  });

  it('snapshots are frozen copies: a caller changing its object changes no step', () => {
    const h = createHistory();
    const s = snap(0);
    h.push(s);
    s.grid.nu = 4;
    s.title = 'changed';
    assert.deepEqual(h.current().grid, { nu: 64, nv: 64 });
    assert.equal(h.current().title, 'Example');
    assert.ok(Object.isFrozen(h.current()) && Object.isFrozen(h.current().grid));
    assert.throws(() => h.push({ sceneText: null, grid: { nu: 1, nv: 1 } }), TypeError);
  });

  it('sameSnapshot compares every field', () => {
    assert.ok(sameSnapshot(snap(1), snap(1)));
    assert.ok(!sameSnapshot(snap(1), snap(2)));
    assert.ok(!sameSnapshot(snap(1), snap(1, { title: 'x' })));
    assert.ok(!sameSnapshot(snap(1), snap(1, { exampleId: null })));
    assert.ok(!sameSnapshot(snap(1), null));
  });
});
