// pdesurf import (issue 40): models exported to STEP and IGES and imported again are the same
// surfaces within each face's certified deviation, at the same (u, v); blends by reference to
// the imported faces certify as they did on the originals; a part made by Open CASCADE
// (examples/cad/) imports, and its example blends and fills it; bad files are named errors
// that write nothing. docs/cad-import.md.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const root = new URL('../../', import.meta.url).pathname;
const cli = process.env.PDESURF_CLI ?? join(root, 'build/native/pdesurf');
const sanitized = process.env.PDESURF_CLI_SANITIZED === '1';
const dir = mkdtempSync(join(tmpdir(), 'pdesurf-import-'));
const example = (id) => join(root, 'examples', `${id}.json`);

function run(args) {
  return spawnSync(cli, args, { encoding: 'utf8' });
}

function grid(scenePath, patch) {
  const r = run(['sample', scenePath, '--patch', patch, '--grid', '9x13']);
  assert.equal(r.status, 0, r.stderr);
  return r.stdout.trim().split('\n').slice(1).map((l) => l.split(',').map(Number));
}

function report(scenePath) {
  const r = run(['check', scenePath, '--json']);
  assert.ok(r.status === 0 || r.status === 1, r.stderr);
  return JSON.parse(r.stdout);
}

// Examples whose blends meet their surfaces by reference (a curve trimline among them).
const BY_REFERENCE = ['ref-offset-cylinders-g2', 'ref-torus-plane', 'ref-sphere-fillet', 'ref-pipe-tjoint', 'you2004-fig8a'];

for (const format of ['step', 'igs']) {
  test(`import: exported ${format.toUpperCase()} comes back as the same surfaces, and blends by reference to them certify`, { skip: sanitized }, () => {
    for (const id of BY_REFERENCE) {
      const cad = join(dir, `${id}.${format}`), back = join(dir, `${id}-${format}.json`);
      const ex = run(['export', example(id), '-o', cad]);
      assert.equal(ex.status, 0, ex.stderr);
      const deviations = Object.fromEntries([...ex.stdout.matchAll(/^ {2}(\S+): (?:exact|certified deviation (\S+))/gm)].map((m) => [m[1], Number(m[2] ?? 0)]));
      const im = run(['import', cad, '-o', back]);
      assert.equal(im.status, 0, im.stderr);
      const imported = JSON.parse(readFileSync(back, 'utf8'));
      const original = JSON.parse(readFileSync(example(id), 'utf8'));
      assert.equal(imported.patches.length, original.patches.length, `${id}: one patch per face`);
      // STEP keeps the faces' names; IGES faces come unnamed through OCCT: matched by order.
      const names = original.patches.map((p) => p.name);
      if (format === 'step') assert.deepEqual(imported.patches.map((p) => p.name), names, id);
      names.forEach((name, k) => {
        const a = grid(example(id), name), b = grid(back, imported.patches[k].name);
        let worst = 0;
        a.forEach((row, i) => {
          assert.ok(Math.abs(row[0] - b[i][0]) < 1e-12 && Math.abs(row[1] - b[i][1]) < 1e-12, `${id} ${name}: same (u, v)`);
          worst = Math.max(worst, Math.hypot(row[2] - b[i][2], row[3] - b[i][3], row[4] - b[i][4]));
        });
        assert.ok(worst <= deviations[name] * 1.0001 + 1e-15, `${id} ${name}: ${worst} against the certified ${deviations[name]}`);
      });
      // The blends (every patch that is not a primary) kept, every primary replaced by its face.
      const rebuilt = structuredClone(original);
      rebuilt.version = Math.max(4, original.version);
      rebuilt.patches = original.patches.map((p, k) => {
        if (!['surface', 'ruled', 'separable'].includes(p.kind)) return p;
        const face = { ...imported.patches[k], name: p.name };
        if (p.meets) face.meets = p.meets;
        return face;
      });
      const path = join(dir, `${id}-${format}-rebuilt.json`);
      writeFileSync(path, JSON.stringify(rebuilt));
      const before = report(example(id)), after = report(path);
      assert.equal(after.joins.length, before.joins.length, id);
      after.joins.forEach((j, i) => {
        assert.equal(j.level, before.joins[i].level);
        assert.ok(j.ok, `${id}: ${j.patch}:${j.end} - ${j.surface}:${j.edge} on the imported face: G0 ${j.g0}, G1 ${j.g1_deg}, G2 ${j.g2_rel}`);
      });
    }
  });
}

test('import: bad files are named errors and write nothing', { skip: sanitized }, () => {
  const out = join(dir, 'nothing.json');
  const cases = [
    [join(dir, 'missing.step'), /cannot be read/],
    [(() => { const p = join(dir, 'part.obj'); writeFileSync(p, 'v 0 0 0\n'); return p; })(), /unknown extension \.obj/],
    [(() => { const p = join(dir, 'part.3dm'); writeFileSync(p, 'x'); return p; })(), /a \.3dm file is read by rhino3dm: node scripts\/import-3dm\.mjs part\.3dm -o scene\.json/],
    [(() => { const p = join(dir, 'junk.stp'); writeFileSync(p, 'not a STEP file\n'); return p; })(), /ParseError: the file: Open CASCADE could not read it as STEP/],
    [(() => { const p = join(dir, 'junk.iges'); writeFileSync(p, '\0\0\0garbage'); return p; })(), /could not read it as IGES|holds no shape|has no faces/],
  ];
  for (const [path, want] of cases) {
    const r = run(['import', path, '-o', out]);
    assert.equal(r.status, 1, path);
    assert.match(r.stderr, want);
    assert.ok(!existsSync(out), 'nothing written');
  }
  assert.match(run(['import', example('you2004-fig4a'), '--grid', '4x4']).stderr, /import takes FILE and -o SCENE.json only/);
});

test('import: the example part (examples/cad/part.step) is what its script makes, imports as the example says, and certifies closed', { skip: sanitized }, () => {
  const scene = JSON.parse(readFileSync(example('cad-part'), 'utf8'));
  const imported = (path) => {
    const r = spawnSync(cli, ['import', path], { encoding: 'utf8', maxBuffer: 1 << 26 });
    assert.equal(r.status, 0, r.stderr);
    return JSON.parse(r.stdout).patches;
  };
  const committed = imported(join(root, 'examples/cad/part.step'));
  assert.deepEqual(committed.map((p) => p.name), ['body', 'neck'], 'the faces keep the names the file gives them');
  // The example's faces are the import of the committed file, exactly.
  assert.deepEqual(scene.patches.slice(0, 2), committed);
  // Made again by its script (examples/cad/make-part.cpp), the file imports to the same faces.
  const maker = process.env.PDESURF_OCCT_MAKE_PART ?? join(root, 'build/native/tests/occt/occt_make_part');
  const again = join(dir, 'part.step');
  const made = spawnSync(maker, [again], { encoding: 'utf8' });
  assert.equal(made.status, 0, made.stderr);
  assert.deepEqual(imported(again), committed);
  const r = report(example('cad-part'));
  assert.ok(r.ok, JSON.stringify(r.joins));
  assert.deepEqual(r.joins.map((j) => `${j.patch}:${j.end} ${j.level} ${j.ok}`).sort(),
    ['base:u0 G1 true', 'cap:u0 G1 true', 'shoulder:u0 G2 true', 'shoulder:u1 G2 true']);
  assert.equal(r.bodies.length, 1);
  assert.ok(r.bodies[0].closed, 'one closed body');
});
