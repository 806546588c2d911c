// Version 3's rules through `pdesurf check` (docs/blends-by-reference.md): two blends on one
// cylinder certify in either patch order; a pole of tau and a zero of dS/dt between the
// samples are the same named error on every grid, naming ends.u0.at and the v.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const root = new URL('../../', import.meta.url).pathname;
const cli = process.env.PDESURF_CLI ?? join(root, 'build/native/pdesurf');
const dir = mkdtempSync(join(tmpdir(), 'pdesurf-v3-rules-'));
const run = (...args) => spawnSync(cli, args, { encoding: 'utf8' });

const surface = (name, x, y, z, t) => ({ name, kind: 'surface', x, y, z, t_range: t, v_range: [0, '2*pi'] });
const end = (s, at) => ({ surface: s, at, continuity: 'tangency' });
const blend = (name, u0, u1) => ({ name, kind: 'pde', v_range: [0, '2*pi'], ends: { u0, u1 } });

// A cylinder z = t in [0, 3], trimmed along tau by "upper", met at t0 (z = 0) by "lower".
function scene({ upperFirst = true, tau = '2 + 0.3*sin(v)', lower = true } = {}) {
  const upper = blend('upper', end('cyl', { t: tau, replaces: 't1' }), end('top', 't0'));
  const blends = lower ? [upper, blend('lower', end('cyl', 't0'), end('bottom', 't0'))] : [upper];
  if (!upperFirst) blends.reverse();
  return { format: 'pdesurf-scene', version: 3, patches: [...blends,
    surface('cyl', 'cos(v)', 'sin(v)', 't', [0, 3]),
    surface('top', '(1.5 + t)*cos(v)', '(1.5 + t)*sin(v)', '3.5', [0, 1]),
    surface('bottom', '(1.5 + t)*cos(v)', '(1.5 + t)*sin(v)', '-1', [0, 1])] };
}

function file(name, s) {
  const f = join(dir, `${name}.json`);
  writeFileSync(f, JSON.stringify(s));
  return f;
}

test('two blends on one trimmed cylinder: check passes in either order, with the same joins', () => {
  const reports = [true, false].map((upperFirst) => {
    const r = run('check', file(`order-${upperFirst}`, scene({ upperFirst })), '--json');
    assert.equal(r.status, 0, r.stderr + r.stdout);
    return JSON.parse(r.stdout);
  });
  const joins = (r) => r.joins.map((j) => `${j.patch}:${j.end} ${j.surface}:${j.edge} ${j.ok}`).sort();
  assert.deepEqual(joins(reports[0]), joins(reports[1]));
  // Named as the scene names it (before issue 38, the trimmed parametrisation's "t1").
  assert.ok(joins(reports[0]).includes('lower:u0 cyl:t0 true'), 'the kept border z = 0 is the cylinder\'s t0');
});

test('a pole of tau between the samples is the same error on every grid, naming ends.u0.at and the v', () => {
  const f = file('pole', scene({ tau: '2 + 0.001/(v - 1.23456)', lower: false }));
  const errors = ['16x16', '48x48', '64x64', '65x65', '128x128'].map((g) => run('check', f, '--grid', g));
  for (const r of errors) {
    assert.equal(r.status, 1);
    assert.match(r.stderr, /InvalidField: patches\[0\]\.ends\.u0\.at: the trimline t = [\d.]+ at v = 1\.23\d* is outside the t_range \[0, 3\] of 'cyl'/);
    assert.equal(r.stderr, errors[0].stderr);
    assert.ok(r.stderr.length <= 600 + f.length + 20);
  }
});
