// The certified B-spline export through the wasm module and the page's wrapper
// (exportCad, docs/wasm-api.md): STEP and IGES text from the module read back by Open CASCADE
// against the native CLI's own samples, the faces' plain data consistent (knots, poles,
// deviations within the tolerance, the same figures as the CLI), bad options and unreachable
// tolerances named errors.
//   PDESURF_CLI=build/native/pdesurf PDESURF_BUILD_DIR=build node --test tests/js/wasm-cad.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { PdesurfError } from '../../web/solver/pdesurf-solver.js';
import { loadTestSolver } from './test-solver.mjs';

const root = new URL('../../', import.meta.url);
const solver = await loadTestSolver();
const cli = process.env.PDESURF_CLI ?? new URL('build/native/pdesurf', root).pathname;
const readback = process.env.PDESURF_OCCT_READBACK ?? join(dirname(cli), 'tests/occt/occt_readback');
const examplePath = (id) => new URL(`examples/${id}.json`, root).pathname;
const scene = (id) => readFileSync(examplePath(id), 'utf8');
const dir = mkdtempSync(join(tmpdir(), 'pdesurf-wasm-cad-'));

function cliSamples(id, names) {
  return names.map((name) => {
    const r = spawnSync(cli, ['sample', examplePath(id), '--patch', name, '--grid', '9x13'], { encoding: 'utf8' });
    assert.equal(r.status, 0, r.stderr);
    return { name, samples: r.stdout.trim().split('\n').slice(1).map((l) => l.split(',').map(Number)) };
  });
}

// A Bézier example, a blend between closed borders, the fills of Fig. 8c; the free edges each
// must have when read back (the open borders: fig4a's two rings, a lone Bézier patch's four,
// fig8c's strips' outer borders and ends).
const FREE_EDGES = { 'you2004-fig4a': 2, 'wu2015-fig1a': 4, 'you2004-fig8c': 36 };
for (const id of ['you2004-fig4a', 'wu2015-fig1a', 'you2004-fig8c']) {
  test(`${id}: the module's STEP and IGES read back in Open CASCADE within the tolerance of the native surfaces`, () => {
    for (const format of ['step', 'iges']) {
      const out = solver.exportCad(scene(id), { format });
      assert.ok(out.tolerance > 0);
      assert.ok(out.faces.length >= 1);
      for (const f of out.faces) {
        assert.equal(f.knotsU.length, f.countU + f.degreeU + 1);
        assert.equal(f.knotsV.length, f.countV + f.degreeV + 1);
        assert.equal(f.poles.length, 3 * f.countU * f.countV);
        assert.ok(f.poles instanceof Float64Array && f.knotsU instanceof Float64Array);
        assert.ok(f.deviation <= out.tolerance, `${f.name}: ${f.deviation} > ${out.tolerance}`);
        assert.equal(f.degenerate.length, 4);
      }
      const file = join(dir, `${id}.${format === 'step' ? 'step' : 'igs'}`);
      writeFileSync(file, out.text);
      const expect = join(dir, `${id}.${format}.json`);
      const wanted = { tolerance: out.tolerance, faces: cliSamples(id, out.faces.map((f) => f.name)) };
      // STEP carries the topology (issue 36): the shells the module reports are what OCCT reads.
      if (format === 'step') {
        assert.ok(Array.isArray(out.shells) && out.shells.length >= 1);
        assert.equal(out.shells.reduce((n, s) => n + s.faces, 0), out.faces.length);
        wanted.topology = { closedShells: out.shells.filter((s) => s.closed).length, freeEdges: FREE_EDGES[id], edgesOnMoreThanTwoFaces: 0 };
      }
      writeFileSync(expect, JSON.stringify(wanted));
      const back = spawnSync(readback, [file, expect], { encoding: 'utf8' });
      assert.equal(back.status, 0, `${format}: ${back.stdout.slice(0, 600)} ${back.stderr.slice(0, 300)}`);
    }
  });
}

test('the module reports the same fit as the CLI: poles, deviations within 1e-6 relative', () => {
  const out = solver.exportCad(scene('you2004-fig4a'));
  const text = spawnSync(cli, ['export', examplePath('you2004-fig4a'), '-o', join(dir, 'cli.step')], { encoding: 'utf8' }).stdout;
  for (const f of out.faces) {
    const m = new RegExp(`^  ${f.name}: certified deviation (\\S+) .* poles (\\d+)x(\\d+)`, 'm').exec(text);
    assert.ok(m, `${f.name} in: ${text}`);
    assert.equal(f.countU, Number(m[2]));
    assert.equal(f.countV, Number(m[3]));
    assert.ok(Math.abs(f.deviation - Number(m[1])) <= 1e-2 * f.deviation + 1e-12, `${f.deviation} vs ${m[1]}`);
  }
  // The joins between the faces: the CLI's lines, the same verdicts and figures (printed to
  // 3 significant digits, normals to 2).
  const lines = [...text.matchAll(/^ {2}(\S+) (\S+) - (\S+) .*: (G[012]), gap (\S+) \(allowed \S+\)(?:, normals (\S+) deg.*)?: (\S+)$/gm)];
  assert.equal(out.joins.length, lines.length);
  assert.ok(out.joins.length >= 2, text);
  out.joins.forEach((j, k) => {
    const [, patch, end, surface, level, gap, normal, verdict] = lines[k];
    assert.deepEqual([j.patch, j.end, j.surface, j.level, j.ok], [patch, end, surface, level, verdict === 'ok']);
    assert.ok(j.ok && j.gap <= j.allowedGap, JSON.stringify(j));
    assert.ok(Math.abs(j.gap - Number(gap)) <= 1e-2 * j.gap + 1e-12, `${j.gap} vs ${gap}`);
    if (level !== 'G0') assert.ok(j.normalDeg <= 0.01 && Math.abs(j.normalDeg - Number(normal)) <= 5e-2 * j.normalDeg + 1e-30, `${j.normalDeg} vs ${normal}`);
  });
});

test('bad options and unreachable tolerances are named errors; the module keeps working', () => {
  const bad = [
    [{ tolerance: -1 }, /tolerance: must be a positive finite number/],
    [{ tolerance: NaN }, /tolerance/],
    [{ tolerance: 'tight' }, /tolerance/],
    [{ degree: 4 }, /degree: must be 3 or 5/],
    [{ format: 'dxf' }, /format: must be "step", "iges", "3dm" or "faces"/],
  ];
  for (const [options, message] of bad) {
    assert.throws(() => solver.exportCad(scene('you2004-fig4a'), options), (e) => e instanceof PdesurfError && e.code === 'InvalidField' && message.test(e.message));
  }
  assert.throws(() => solver.exportCad(scene('you2004-fig4a'), { tolerance: 1e-300 }),
    (e) => e instanceof PdesurfError && e.code === 'TooLarge' && /patch 'blend': the fit reached a certified deviation of/.test(e.message));
  assert.throws(() => solver.exportCad('{"format": "pdesurf-scene"'), (e) => e instanceof PdesurfError && e.code === 'ParseError');
  assert.equal(solver.exportCad(scene('you2004-fig4a'), { format: 'step', degree: 3, tolerance: 1e-4 }).faces.length, 3);
});
