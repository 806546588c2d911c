// The curvature maps' colour scale and the join report's model (web/state/), on
// made-up data: the rules the page's legend and joins folder show.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { curvatureScale, quantile, formatValue } from '../../web/state/curvature-scale.js';
import { normaliseReport, highlightedKeys, joinKey, joinFigures, crossingText } from '../../web/state/join-report.js';

const ramp = (n, lo, hi) => Float32Array.from({ length: n }, (_, k) => lo + ((hi - lo) * k) / (n - 1));

test('quantile interpolates a sorted array', () => {
  const s = Float64Array.from([0, 1, 2, 3, 4]);
  assert.equal(quantile(s, 0), 0);
  assert.equal(quantile(s, 1), 4);
  assert.equal(quantile(s, 0.5), 2);
  assert.equal(quantile(s, 0.625), 2.5);
});

test('symmetric scale: ±max|k| at 100 %, a smaller limit at a lower percentile', () => {
  const a = ramp(101, -1, 3);
  const full = curvatureScale([a], { scale: 'symmetric', percentile: 100 });
  assert.ok(Math.abs(full.max - 3) < 1e-6 && Math.abs(full.min + 3) < 1e-6);
  assert.equal(full.clamped, 0);
  assert.ok(Math.abs(full.dataMin + 1) < 1e-6 && Math.abs(full.dataMax - 3) < 1e-6);
  const p90 = curvatureScale([a], { scale: 'symmetric', percentile: 90 });
  assert.ok(p90.max < 3 && p90.max > 2.4, `90 %: ${p90.max}`);
  assert.equal(p90.min, -p90.max);
  assert.ok(p90.clamped > 0.05 && p90.clamped < 0.15, `clamped ${p90.clamped}`);
});

test('percentile scale spans [P(100-p), P(p)] over every patch', () => {
  const s = curvatureScale([ramp(51, 0, 1), ramp(50, 1.02, 2)], { scale: 'percentile', percentile: 95 });
  assert.ok(s.min > 0 && s.min < 0.15, `min ${s.min}`);
  assert.ok(s.max > 1.85 && s.max < 2, `max ${s.max}`);
});

test('fixed scale takes the typed range, in order', () => {
  const s = curvatureScale([ramp(11, -5, 5)], { scale: 'fixed', min: 2, max: -2 });
  assert.deepEqual([s.min, s.max], [-2, 2]);
  assert.ok(Math.abs(s.clamped - 6 / 11) < 1e-12);
});

test('a constant field (a plane) gets a small range around its value; NaN is counted, not used', () => {
  const s = curvatureScale([new Float32Array([0, 0, 0, NaN])], { scale: 'symmetric' });
  assert.ok(s.max > 0 && s.min < 0 && s.max < 1e-6);
  assert.equal(s.nonFinite, 1);
  assert.equal(s.count, 3);
  const e = curvatureScale([], {});
  assert.ok(Number.isFinite(e.min) && Number.isFinite(e.max) && e.max > e.min);
});

test('legend numbers are short', () => {
  assert.equal(formatValue(0), '0');
  assert.equal(formatValue(0.123456), '0.123');
  assert.equal(formatValue(-12.3456), '-12.3');
  assert.equal(formatValue(1.5e-5), '1.50e-5');
});

const RAW = {
  ok: false,
  scene_size: 4.2,
  joins: [
    { patch: 'blend', end: 0, surface: '<b>cyl</b>', edge: 't0', level: 'G1', g0: 1e-9, g1_deg: 0.01, g2_rel: null, fold: false, ok: true, degenerate: 0 },
    { patch: 'blend', end: 1, surface: 'plane', edge: 't0', level: 'G2', g0: 2e-8, g1_deg: 3.5, g2_rel: 0.25, fold: true, ok: false, degenerate: 2 },
  ],
  crossings: [{ patch: 'blend', other: 'plane', u: [0.9, 1], v: [0.1, 0.2] }],
};

test('the join report is normalised and names stay strings', () => {
  const r = normaliseReport(RAW);
  assert.equal(r.ok, false);
  assert.equal(r.joins.length, 2);
  assert.equal(r.joins[0].surface, '<b>cyl</b>');
  assert.equal(r.joins[0].g2Rel, null);
  assert.equal(r.joins[1].g1Deg, 3.5);
  assert.deepEqual(r.crossings[0].u, [0.9, 1]);
  assert.equal(normaliseReport(undefined), null);
  assert.equal(normaliseReport({ joins: [{ patch: 'b', end: 'u1' }] }).joins[0].end, 'u1');
  assert.equal(normaliseReport({ joins: [{ patch: 'b', end: 'v0' }] }).joins[0].end, 'v0');
  assert.equal(normaliseReport({ joins: [{ patch: 'b', end: 1 }] }).joins[0].end, 'u1');
  assert.deepEqual(normaliseReport({ ok: false, error: { code: 'InvalidField', message: 'x' } }).error, { code: 'InvalidField', message: 'x' });
  const figs = Object.fromEntries(joinFigures(r.joins[1]));
  assert.equal(figs['G1 angle'], '3.5°');
  assert.equal(figs['G2 mismatch'], '25 %');
  assert.equal(figs.fold, 'yes');
  assert.equal(Object.fromEntries(joinFigures(r.joins[0]))['G2 mismatch'], '—');
  assert.match(crossingText(r.crossings[0]), /“blend” crosses “plane” at u ∈ \[0\.9, 1\], v ∈ \[0\.1, 0\.2\]/);
});

test('failing joins are highlighted unless unticked; others when ticked', () => {
  const r = normaliseReport(RAW);
  const [ok, fail] = r.joins.map(joinKey);
  assert.deepEqual(highlightedKeys(r, new Map()), [fail]);
  assert.deepEqual(highlightedKeys(r, new Map([[fail, false]])), []);
  assert.deepEqual(highlightedKeys(r, new Map([[ok, true]])), [ok, fail]);
  assert.deepEqual(highlightedKeys(null, new Map()), []);
});
