// Ends by reference in the page state (web/state/ends-edit.js and the scene-state methods
// over it): reading an end with the format's defaults, writing each field where the
// solver reads it, attach and detach, the operator orders they need, and which field a
// solver message is about.
//   node --test tests/js/
import { describe, it } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import {
  readEnd, setEndField, attach, attachDefaults, detach, detachRefusal, withExplicitOrders, powerValue,
  canHaveEnds, surfaceNames, curveFromIsoLine, endErrorField, neededOrder, isByReference,
} from '../../web/state/ends-edit.js';
import { createSceneState } from '../../web/state/scene-state.js';

const EXAMPLES = path.join(path.dirname(fileURLToPath(import.meta.url)), '..', '..', 'examples');
const example = (id) => JSON.parse(fs.readFileSync(path.join(EXAMPLES, `${id}.json`), 'utf8'));
const ORDERS4 = { x: 4, y: 4, z: 4 };
// What the solver gives the sphere fillet's u1 (ref-sphere-fillet, a = 2.2, th0 = 0.9).
const DERIVED_U1 = {
  x: ['0.7833269096274834*cos(v)', '1.7216880377039752*(0.6216099682706644*cos(v))'],
  y: ['0.7833269096274834*sin(v)', '1.7216880377039752*(0.6216099682706644*sin(v))'],
  z: ['0.9783900317293357', '1.3486445699172611'],
};

function fillet() {
  const s = createSceneState();
  s.setScene(example('ref-sphere-fillet'), 'ref-sphere-fillet');
  s.noteSolved([{ name: 'fillet', operator: { x: { order: 4 }, y: { order: 4 }, z: { order: 4 } } }]);
  return s;
}

describe('reading an end', () => {
  it('gives the scene\'s values and the format\'s defaults', () => {
    const blend = example('ref-sphere-fillet').patches[0];
    assert.deepEqual(readEnd(blend, 'u1'), {
      surface: 'sphere', trimline: 't0', tau: '', replaces: 't0', continuity: 'tangency',
      power: 'p1', scale: 'gap', flip: false,
    });
    const curved = { ends: { u0: { surface: 's', at: { t: 'th0 + 0.1', replaces: 't1' }, power: 2, scale: 'surface', flip: true } } };
    assert.deepEqual(readEnd(curved, 'u0'), {
      surface: 's', trimline: 'curve', tau: 'th0 + 0.1', replaces: 't1', continuity: 'tangency',
      power: 2, scale: 'surface', flip: true,
    });
    assert.equal(readEnd(curved, 'u1'), null);
    assert.equal(readEnd({ boundary: {} }, 'u0'), null);
  });

  it('offers ends on blends of version-2/3 scenes with surfaces, or with an end already by reference', () => {
    const v3 = example('ref-sphere-fillet');
    assert.deepEqual(surfaceNames(v3), ['plane', 'sphere']);
    assert.equal(canHaveEnds(v3, v3.patches[0]), true);
    assert.equal(canHaveEnds(v3, v3.patches[1]), false, 'a surface has no ends');
    const v2 = example('you2004-fig2a');
    assert.equal(canHaveEnds(v2, v2.patches[0]), true);
    const noSurfaces = { version: 2, patches: [{ name: 'b', kind: 'pde' }] };
    assert.equal(canHaveEnds(noSurfaces, noSurfaces.patches[0]), false);
    const v1 = { version: 1, patches: [{ name: 'b', kind: 'pde' }, { name: 's', kind: 'ruled' }] };
    assert.equal(canHaveEnds(v1, v1.patches[0]), false);
  });

  it('reads a power\'s current value from a number, a numeric text or a parameter', () => {
    const scene = example('ref-sphere-fillet');
    assert.equal(powerValue(scene, 1.5), 1.5);
    assert.equal(powerValue(scene, ' 0.75 '), 0.75);
    assert.equal(powerValue(scene, 'p1'), 1);
    assert.equal(powerValue(scene, 'p1*2'), null);
    assert.equal(powerValue(scene, 'nope'), null);
  });
});

describe('writing an end', () => {
  it('writes every field where the solver reads it', () => {
    const blend = example('ref-sphere-fillet').patches[0];
    setEndField(blend, 'u1', 'surface', 'plane');
    setEndField(blend, 'u1', 'at', { t: 'th0 + 0.1*sin(2*v)', replaces: 't0' });
    setEndField(blend, 'u1', 'tau', 'th0 + 0.2');
    setEndField(blend, 'u1', 'replaces', 't1');
    setEndField(blend, 'u1', 'continuity', 'curvature');
    setEndField(blend, 'u1', 'power', 2.5);
    setEndField(blend, 'u1', 'scale', 'surface');
    setEndField(blend, 'u1', 'flip', true);
    assert.deepEqual(blend.ends.u1, {
      surface: 'plane', at: { t: 'th0 + 0.2', replaces: 't1' }, continuity: 'curvature', power: 2.5, scale: 'surface', flip: true,
    });
    setEndField(blend, 'u1', 'power', 'p1');
    setEndField(blend, 'u1', 'flip', false);
    setEndField(blend, 'u1', 'at', 't1');
    assert.deepEqual(blend.ends.u1, { surface: 'plane', at: 't1', continuity: 'curvature', power: 'p1', scale: 'surface' });
  });

  it('refuses what the format has no place for', () => {
    const blend = example('ref-sphere-fillet').patches[0];
    assert.throws(() => setEndField(blend, 'u1', 'continuity', 'smooth'), /continuity must be/);
    assert.throws(() => setEndField(blend, 'u1', 'at', 't2'), /at must be/);
    assert.throws(() => setEndField(blend, 'u1', 'tau', 'th0'), /iso-line/);
    assert.throws(() => setEndField(blend, 'u1', 'power', NaN), /finite/);
    assert.throws(() => setEndField(blend, 'u2', 'power', 1), /u0 or u1/);
    assert.throws(() => setEndField(blend, 'u1', 'colour', 1), /unknown end field/);
    assert.throws(() => setEndField({ name: 'b', boundary: {} }, 'u0', 'power', 1), /typed/);
  });

  it('starts a curve as the iso-line it replaces: τ is that border of the surface\'s t_range', () => {
    const scene = example('ref-sphere-fillet');
    assert.deepEqual(curveFromIsoLine(scene, 'sphere', 't0'), { t: 'th0', replaces: 't0' });
    assert.deepEqual(curveFromIsoLine(scene, 'sphere', 't1'), { t: 'pi - 0.05', replaces: 't1' });
    assert.deepEqual(curveFromIsoLine(scene, 'plane', 't1'), { t: '1', replaces: 't1' });
    assert.deepEqual(curveFromIsoLine(scene, 'nope', 't0'), { t: '0', replaces: 't0' });
  });

  it('raises the orders when a continuity needs more, in the single form when all three rise', () => {
    const s = fillet();
    assert.deepEqual(s.setEndField('fillet', 'u1', 'continuity', 'curvature'), ['x', 'y', 'z']);
    const blend = s.patch('fillet');
    assert.deepEqual(blend.operator, { order: 6, a: 1 });
    assert.equal(blend.boundary, undefined, 'no typed lists appear for ends by reference');
    assert.equal(neededOrder(blend), 6);
    // Lowering the continuity keeps the order (a higher one is allowed).
    assert.deepEqual(s.setEndField('fillet', 'u1', 'continuity', 'tangency'), []);
    assert.deepEqual(blend.operator, { order: 6, a: 1 });
  });

  it('raises only the coordinates below, and pads a typed end\'s lists', () => {
    const s = fillet();
    s.noteSolved([{ name: 'fillet', operator: { x: { order: 6 }, y: { order: 4 }, z: { order: 4 } } }]);
    const blend = s.patch('fillet');
    blend.operator = { x: { order: 6, a: 1 }, y: { order: 4, b: 1, c: 2, d: 1 }, z: { order: 4, b: 1, c: 2, d: 1 } };
    detach(blend, 'u0', { x: ['a', 'b'], y: ['c', 'd'], z: ['e', 'f'] }, ORDERS4);
    assert.deepEqual(s.setEndField('fillet', 'u1', 'continuity', 'curvature'), ['y', 'z']);
    assert.deepEqual(blend.operator, { x: { order: 6, a: 1 }, y: { order: 6, a: 1 }, z: { order: 6, a: 1 } });
    assert.deepEqual(blend.boundary.y.u0, ['c', 'd', '0']);
    assert.equal(blend.boundary.y.u1, undefined);
  });
});

describe('operator edits on a blend whose order is left to the solver', () => {
  it('a coefficient of one coordinate splits the single form with the resolved orders', () => {
    const s = fillet();
    s.setOperatorParam('fillet', 'y', 'b', 0.5);
    assert.deepEqual(s.patch('fillet').operator, {
      x: { order: 4, b: 1, c: 2, d: 1 }, y: { order: 4, b: 0.5, c: 2, d: 1 }, z: { order: 4, b: 1, c: 2, d: 1 },
    });
  });

  it('an order change keeps the other coordinates whole and types no referenced end', () => {
    const s = fillet();
    assert.deepEqual(s.setOperatorOrder('fillet', 'z', 6), { a: 1 });
    const blend = s.patch('fillet');
    assert.deepEqual(blend.operator.z, { order: 6, a: 1 });
    assert.deepEqual(blend.operator.x, { order: 4, b: 1, c: 2, d: 1 });
    assert.equal(blend.boundary, undefined);
  });
});

describe('attach and detach', () => {
  it('detach types the derived texts, drops the end, and keeps the order to the other end', () => {
    const s = fillet();
    s.detachEnd('fillet', 'u1', DERIVED_U1);
    const blend = s.patch('fillet');
    assert.deepEqual(blend.boundary.x.u1, DERIVED_U1.x);
    assert.deepEqual(blend.boundary.z.u1, DERIVED_U1.z);
    assert.deepEqual(Object.keys(blend.ends), ['u0']);
    assert.deepEqual(blend.operator, { b: 1, c: 2, d: 1 }, 'u0 is still by reference: the solver infers the order');
  });

  it('detaching the last end gives the operator explicit orders and removes `ends`', () => {
    const s = fillet();
    s.detachEnd('fillet', 'u1', DERIVED_U1);
    s.detachEnd('fillet', 'u0', { x: ['2.2*cos(v)', '-1.7*cos(v)'], y: ['2.2*sin(v)', '-1.7*sin(v)'], z: ['0', '-0'] });
    const blend = s.patch('fillet');
    assert.equal(blend.ends, undefined);
    assert.deepEqual(blend.operator, { order: 4, b: 1, c: 2, d: 1 });
    assert.deepEqual(blend.boundary.x, { u1: DERIVED_U1.x, u0: ['2.2*cos(v)', '-1.7*cos(v)'] });
  });

  it('detaching a curvature end beside a tangency end writes explicit orders (inference would drop to 4)', () => {
    const blend = example('ref-sphere-fillet').patches[0];
    blend.ends.u1.continuity = 'curvature';
    blend.operator = { a: 1 }; // as setEndField raises it
    const derived = { x: [...DERIVED_U1.x, '0'], y: [...DERIVED_U1.y, '0'], z: [...DERIVED_U1.z, '0'] };
    detach(blend, 'u1', derived, { x: 6, y: 6, z: 6 });
    assert.deepEqual(blend.operator, { order: 6, a: 1 });
    assert.deepEqual(Object.keys(blend.ends), ['u0']);
  });

  it('detach refuses a text longer than an expression may be, and changes nothing', () => {
    const blend = example('ref-sphere-fillet').patches[0];
    const before = structuredClone(blend);
    const long = { ...DERIVED_U1, y: [DERIVED_U1.y[0], `1 + ${'0.1*cos(v) + '.repeat(80)}0`] };
    const why = detachRefusal('u1', long);
    assert.match(why, /^cannot detach: the derived yᵤ\(1\) has \d+ characters, more than an expression may have \(1000\); the end stays by reference$/);
    assert.throws(() => detach(blend, 'u1', long, ORDERS4), (e) => e.message === why);
    assert.deepEqual(blend, before);
    assert.equal(detachRefusal('u1', DERIVED_U1), null);
  });

  it('detach refuses a typed end or missing derived texts, and changes nothing then', () => {
    const blend = example('ref-sphere-fillet').patches[0];
    const before = structuredClone(blend);
    assert.throws(() => detach(blend, 'u1', { x: ['1', '2'], y: ['1', '2'] }, ORDERS4), /no derived conditions for z/);
    assert.deepEqual(blend, before);
    assert.throws(() => detach({ name: 'b' }, 'u0', DERIVED_U1, ORDERS4), /typed/);
  });

  it('explicit orders: single form, per coordinate, and no operator', () => {
    assert.deepEqual(withExplicitOrders({ a: 1 }, { x: 6, y: 6, z: 6 }), { order: 6, a: 1 });
    assert.deepEqual(withExplicitOrders({ order: 4, b: 1 }, ORDERS4), { order: 4, b: 1 });
    assert.deepEqual(withExplicitOrders(undefined, ORDERS4), { order: 4, b: 1, c: 2, d: 1 });
    assert.deepEqual(withExplicitOrders({ b: 1, c: 2, d: 1 }, { x: 6, y: 4, z: 4 }), {
      x: { order: 6, b: 1, c: 2, d: 1 }, y: { order: 4, b: 1, c: 2, d: 1 }, z: { order: 4, b: 1, c: 2, d: 1 },
    });
    assert.deepEqual(withExplicitOrders({ x: { a: 1 }, y: { order: 4, b: 1 } }, { x: 6, y: 4, z: 2 }), {
      x: { order: 6, a: 1 }, y: { order: 4, b: 1 }, z: { order: 2, s: 1, t: 1 },
    });
    assert.throws(() => withExplicitOrders({ a: 1 }, {}), /no resolved order/);
  });

  it('attach gives a typed end by reference (the surface that meets it), drops its lists, makes the scene version 3', () => {
    const s = createSceneState();
    s.setScene(example('you2004-fig2a'), 'you2004-fig2a');
    s.noteSolved([{ name: 'blend', operator: { x: { order: 4 }, y: { order: 4 }, z: { order: 4 } } }]);
    s.attachEnd('blend', 'u1');
    const blend = s.patch('blend');
    assert.equal(s.scene.version, 3);
    assert.deepEqual(blend.ends, { u1: { surface: 'cone', at: 't0', continuity: 'tangency', power: 1 } });
    assert.deepEqual(blend.boundary.x, { u0: ['r0*cos(v)', 'r0p*cos(v)'] });
    assert.deepEqual(blend.boundary.z, { u0: ['0', '0'] });
    s.attachEnd('blend', 'u0');
    assert.equal(blend.boundary, undefined);
    assert.equal(blend.ends.u0.surface, 'plane');
    assert.throws(() => s.attachEnd('blend', 'u0'), /already/);
  });

  it('attach defaults: the surface that meets the end at its `meets.at`, else one the other end does not meet; position on order 2', () => {
    const scene = { version: 2, patches: [
      { name: 'b', kind: 'pde' },
      { name: 'first', kind: 'surface' },
      { name: 'second', kind: 'surface', meets: { patch: 'b', end: 'u0', at: 't1' } },
    ] };
    assert.deepEqual(attachDefaults(scene, scene.patches[0], 'u0', ORDERS4), { surface: 'second', at: 't1', continuity: 'tangency', power: 1 });
    assert.deepEqual(attachDefaults(scene, scene.patches[0], 'u1', { x: 2, y: 4, z: 4 }), { surface: 'first', at: 't0', continuity: 'position', power: 1 });
    const blend = { name: 'b', kind: 'pde', ends: { u0: { surface: 'first', at: 't0' } } };
    assert.equal(attachDefaults(scene, blend, 'u1', ORDERS4).surface, 'second', 'not the surface the other end meets');
    assert.throws(() => attachDefaults({ patches: [] }, { name: 'b' }, 'u0'), /no "surface" patch/);
  });

  it('attach then detach round-trips the scene but for the texts', () => {
    const scene = example('ref-sphere-fillet');
    const blend = scene.patches[0];
    detach(blend, 'u1', DERIVED_U1, ORDERS4);
    assert.equal(isByReference(blend, 'u1'), false);
    attach(scene, blend, 'u1', { surface: 'sphere', at: 't0', continuity: 'tangency', power: 'p1' });
    assert.deepEqual(blend, example('ref-sphere-fillet').patches[0]);
  });
});

describe('solver messages about ends', () => {
  it('name the end\'s field, or the end itself, or nothing', () => {
    const at = "patches[0].ends.u1.at: the trimline t = 0.89 at v = 1.6 is outside the t_range [0.9, 3.09] of 'sphere'";
    assert.equal(endErrorField(at, 0, 'u1'), 'at');
    assert.equal(endErrorField(at, 0, 'u0'), null);
    assert.equal(endErrorField(at, 1, 'u1'), null);
    assert.equal(endErrorField('patches[0].ends.u1.at.t: col 6: expression ends too early', 0, 'u1'), 'at');
    assert.equal(endErrorField('InvalidField: patches[2].ends.u0.power: col 4', 2, 'u0'), 'power');
    assert.equal(endErrorField('patches[12].ends.u0: both typed', 1, 'u0'), null);
    assert.equal(endErrorField('patches[1].ends.u0: a surface trimmed twice', 1, 'u0'), 'end');
    assert.equal(endErrorField('patches[0].operator.order: curvature at u1', 0, 'u1'), null);
  });

  it('a message naming two ends is about the first', () => {
    const both = "patches[2].ends.u0.at: meets t1 of 'cyl', which patches[1].ends.u1 replaces by a curve";
    assert.equal(endErrorField(both, 2, 'u0'), 'at');
    assert.equal(endErrorField(both, 1, 'u1'), null);
    const same = "patches[0].ends.u1.at: meets t0 of 'plane', as patches[0].ends.u0 does: the blend would start and end on the same curve";
    assert.equal(endErrorField(same, 0, 'u1'), 'at');
    assert.equal(endErrorField(same, 0, 'u0'), null);
  });
});
