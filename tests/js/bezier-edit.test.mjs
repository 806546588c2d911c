// Pure helpers behind the page's bezier controls: λ weights by region
// (web/state/region-weights.js), initial-net edits (web/state/control-net-edit.js), the
// page state's bezier edits, and the arrow and net geometry (web/viewer/arrow-geometry.js).
import { describe, it } from 'node:test';
import assert from 'node:assert/strict';
import {
  SPLIT, discreteGrid, regionOf, regionSamples, regionSpan, regionWeightsArray, regionValuesFrom, setRegionWeights,
} from '../../web/state/region-weights.js';
import {
  netSizeOf, controlPointRole, controlPointEntry, setControlPointCoordinate,
} from '../../web/state/control-net-edit.js';
import { createSceneState } from '../../web/state/scene-state.js';
import { arrowSegments, arrowLength, boundsDiagonal, gridIndices, SEGMENTS_PER_ARROW } from '../../web/viewer/arrow-geometry.js';

const discretePatch = (np, mp, extra = {}) => ({
  name: 'hat', kind: 'bezier', energy: 'membrane', degree: [2, 2],
  control_net: Array.from({ length: 9 }, (_, k) => [Math.floor(k / 3), k % 3, 0]),
  normals: { grid: [np, mp], field: { x: '0', y: '0', z: '1' }, ...extra },
});

describe('λ weights by region', () => {
  it('splits a direction into three runs, the earlier ones taking the remainder', () => {
    const runs = (count) => [0, 1, 2].map((r) => regionSamples(r, count));
    assert.deepEqual(runs(17), [[0, 5], [6, 11], [12, 16]]);
    assert.deepEqual(runs(9), [[0, 2], [3, 5], [6, 8]]);
    assert.deepEqual(runs(3), [[0, 0], [1, 1], [2, 2]]);
    assert.deepEqual(runs(2), [[0, 0], [1, 1], [-1, -1]]); // a 1-interval grid leaves the last region empty
    for (const count of [2, 3, 4, 11, 17, 257]) {
      let last = 0;
      for (let k = 0; k < count; k++) {
        const r = regionOf(k, count);
        assert.ok(r >= last && r < SPLIT, `monotone regions at ${k}/${count}`);
        last = r;
      }
    }
    assert.deepEqual(regionSpan(0, 16), [0, 5 / 16]);
    assert.deepEqual(regionSpan(2, 16), [12 / 16, 1]);
  });

  it('builds the per-sample list row i major, each sample taking its region\'s value', () => {
    const regions = [1, 2, 3, 4, 5, 6, 7, 8, 9];
    const w = regionWeightsArray(4, 7, regions); // 5 × 8 samples
    assert.equal(w.length, 40);
    for (let i = 0; i <= 4; i++) {
      for (let j = 0; j <= 7; j++) assert.equal(w[i * 8 + j], regions[regionOf(i, 5) * 3 + regionOf(j, 8)], `(${i}, ${j})`);
    }
    assert.equal(w[0], 1);
    assert.equal(w[39], 9);
    assert.equal(w[7], 3); // i = 0, j = 7: first u region, last v region
    assert.throws(() => regionWeightsArray(0, 4, regions), /positive integers/);
    assert.throws(() => regionWeightsArray(4, 4, [1, 2]), /9 finite/);
    assert.throws(() => regionWeightsArray(4, 4, [1, 2, 3, 4, NaN, 6, 7, 8, 9]), /9 finite/);
  });

  it('reads slider values back as region means, clamped; anything else reads as 1', () => {
    const regions = [0, 0.5, 2, 3, 10, 1, 7, 8, 9];
    assert.deepEqual(regionValuesFrom(regionWeightsArray(16, 16, regions), 16, 16), regions);
    // Slider steps of 0.1 come back exactly (a plain mean gives 9.800000000000006 and 0.2999999999999999).
    const tenths = [9.8, 0.3, 0.7, 1.1, 2.9, 9.9, 0.1, 4.4, 6.6];
    assert.deepEqual(regionValuesFrom(regionWeightsArray(16, 16, tenths), 16, 16), tenths);
    const w = regionWeightsArray(2, 2, [1, 1, 1, 1, 1, 1, 1, 1, 1]);
    w[0] = 50; // clamped to the slider's 10
    w[4] = -3; // and 0
    assert.deepEqual(regionValuesFrom(w, 2, 2), [10, 1, 1, 1, 0, 1, 1, 1, 1]);
    assert.deepEqual(regionValuesFrom('u*v', 2, 2), new Array(9).fill(1));
    assert.deepEqual(regionValuesFrom([1, 2], 2, 2), new Array(9).fill(1));
    assert.deepEqual(regionValuesFrom(undefined, 2, 2), new Array(9).fill(1));
  });

  it('writes normals.lambda_weights, and removes it when every region is back at 1', () => {
    const patch = discretePatch(16, 16);
    assert.deepEqual(discreteGrid(patch), [16, 16]);
    setRegionWeights(patch, [1, 1, 1, 1, 4, 1, 1, 1, 1]);
    assert.equal(patch.normals.lambda_weights.length, 289);
    assert.equal(patch.normals.lambda_weights[8 * 17 + 8], 4);
    assert.equal(patch.normals.lambda_weights[0], 1);
    setRegionWeights(patch, new Array(9).fill(1));
    assert.equal('lambda_weights' in patch.normals, false);
    const continuous = { name: 'c', kind: 'bezier', normals: { degree: [3, 3], vectors: [] } };
    assert.equal(discreteGrid(continuous), null);
    assert.throws(() => setRegionWeights(continuous, new Array(9).fill(2)), /no discrete normal field/);
  });
});

describe('initial control net edits', () => {
  it('knows the net size and which rings are fixed', () => {
    assert.deepEqual(netSizeOf({ degree: [7, 4] }), [8, 5]);
    assert.equal(netSizeOf({ degree: [7] }), null);
    assert.equal(netSizeOf({}), null);
    assert.equal(controlPointRole(0, 3, 8, 8, 'membrane'), 'fixed');
    assert.equal(controlPointRole(1, 1, 8, 8, 'membrane'), 'free');
    assert.equal(controlPointRole(6, 3, 8, 8, 'membrane'), 'free');
    assert.equal(controlPointRole(7, 3, 8, 8, 'membrane'), 'fixed');
    assert.equal(controlPointRole(1, 3, 8, 8, 'thin-plate'), 'fixed');
    assert.equal(controlPointRole(6, 3, 8, 8, 'thin-plate'), 'fixed');
    assert.equal(controlPointRole(2, 5, 8, 8, 'thin-plate'), 'free');
  });

  it('sets one coordinate as a number and keeps the others, expressions included', () => {
    const patch = discretePatch(4, 4);
    patch.control_net[4] = ['0.5*2', 1, 'h'];
    const before = structuredClone(patch.control_net);
    setControlPointCoordinate(patch, 1, 1, 'z', 0.75);
    assert.deepEqual(patch.control_net[4], ['0.5*2', 1, 0.75]);
    assert.equal(controlPointEntry(patch, 1, 1, 'x'), '0.5*2');
    assert.deepEqual(before[4], ['0.5*2', 1, 'h'], 'the old point array was replaced, not mutated');
    patch.control_net.forEach((p, k) => {
      if (k !== 4) assert.deepEqual(p, before[k]);
    });
    setControlPointCoordinate(patch, 2, 0, 'x', -3);
    assert.deepEqual(patch.control_net[6], [-3, 0, 0]);
  });

  it('refuses points outside the net, unknown axes, non-numbers and broken nets', () => {
    const patch = discretePatch(4, 4);
    assert.throws(() => setControlPointCoordinate(patch, 3, 0, 'x', 1), /no control point \(3, 0\) in a 3×3 net/);
    assert.throws(() => setControlPointCoordinate(patch, 0, -1, 'x', 1), /no control point/);
    assert.throws(() => setControlPointCoordinate(patch, 0.5, 0, 'x', 1), /no control point/);
    assert.throws(() => setControlPointCoordinate(patch, 0, 0, 'w', 1), /axis must be x, y or z/);
    assert.throws(() => setControlPointCoordinate(patch, 0, 0, 'x', NaN), /finite number/);
    patch.control_net.pop();
    assert.throws(() => setControlPointCoordinate(patch, 0, 0, 'x', 1), /does not hold 3×3 points/);
  });
});

describe('page state: bezier edits', () => {
  const scene = () => ({ format: 'pdesurf-scene', version: 2, patches: [discretePatch(16, 16, { lambda_weights: 'u' }), { name: 'p', kind: 'surface' }] });

  it('writes λ, γ, region weights and control points of the named bezier patch', () => {
    const state = createSceneState();
    state.setScene(scene(), null);
    state.setBezierNumber('hat', 'gamma', 5);
    state.setBezierNumber('hat', 'lambda', 0);
    state.setRegionWeights('hat', [2, 1, 1, 1, 1, 1, 1, 1, 1]);
    state.setControlPointCoordinate('hat', 1, 1, 'y', 0.25);
    const hat = JSON.parse(state.text()).patches[0];
    assert.equal(hat.gamma, 5);
    assert.equal(hat.lambda, 0);
    assert.equal(hat.normals.lambda_weights[0], 2);
    assert.equal(hat.normals.lambda_weights[288], 1);
    assert.deepEqual(hat.control_net[4], [1, 0.25, 0]);
  });

  it('refuses other patches, other keys and non-numbers', () => {
    const state = createSceneState();
    state.setScene(scene(), null);
    assert.throws(() => state.setBezierNumber('p', 'gamma', 1), /not a bezier patch/);
    assert.throws(() => state.setBezierNumber('nope', 'gamma', 1), /no patch named "nope"/);
    assert.throws(() => state.setBezierNumber('hat', 'energy', 1), /lambda or gamma/);
    assert.throws(() => state.setBezierNumber('hat', 'gamma', Infinity), /finite/);
  });
});

describe('arrow and net geometry', () => {
  it('draws a shaft and four barbs per arrow, of the given length, skipping zero vectors', () => {
    const origins = new Float32Array([0, 0, 0, 1, 2, 3, 5, 5, 5]);
    const vectors = new Float32Array([0, 0, 2, 1, 1, 0, 0, 0, 0]);
    const seg = arrowSegments(origins, vectors, 0.5);
    assert.equal(seg.length, 2 * SEGMENTS_PER_ARROW * 6);
    assert.deepEqual(Array.from(seg.slice(0, 6)), [0, 0, 0, 0, 0, 0.5]); // normalised, then scaled
    const tip2 = [1 + 0.5 / Math.SQRT2, 2 + 0.5 / Math.SQRT2, 3];
    const shaft2 = seg.slice(SEGMENTS_PER_ARROW * 6, SEGMENTS_PER_ARROW * 6 + 6);
    shaft2.slice(3).forEach((x, a) => assert.ok(Math.abs(x - tip2[a]) < 1e-6));
    // Barbs start at the tip and end behind it, off the shaft, inside the head's cone.
    for (let b = 1; b < SEGMENTS_PER_ARROW; b++) {
      const s = seg.slice(b * 6, b * 6 + 6);
      assert.deepEqual(Array.from(s.slice(0, 3)), [0, 0, 0.5]);
      const off = Math.hypot(s[3], s[4]);
      assert.ok(s[5] < 0.5 && s[5] > 0.3 && off > 0.01 && off < 0.1, `barb ${b}: ${Array.from(s)}`);
    }
  });

  it('sizes arrows to the spacing of their origins', () => {
    const origins = [];
    for (let i = 0; i <= 10; i++) for (let j = 0; j <= 10; j++) origins.push(i / 10, j / 10, 0);
    assert.ok(Math.abs(boundsDiagonal(origins) - Math.SQRT2) < 1e-12);
    const L = arrowLength(origins);
    assert.ok(L > 0.08 && L < 0.15, `length ${L} for spacing 0.1`);
    assert.equal(arrowLength([]), 0);
  });

  it('joins a net along its rows and columns', () => {
    const idx = gridIndices(2, 3); // points 0 1 2 / 3 4 5
    const pairs = new Set();
    for (let k = 0; k < idx.length; k += 2) pairs.add(`${idx[k]}-${idx[k + 1]}`);
    assert.deepEqual([...pairs].sort(), ['0-1', '0-3', '1-2', '1-4', '2-5', '3-4', '4-5']);
    assert.equal(gridIndices(8, 8).length / 2, 2 * 8 * 7);
  });
});
