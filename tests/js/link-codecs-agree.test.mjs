// The page's link codec (web/link/) and the CLI's (cli/link_codec.cpp, zlib) agree both ways:
// a link either one writes opens in the other with the same scene, and the scene samples
// bit-identically after the round trip.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { encodeState, decodeFragment } from '../../web/link/link-codec.js';

const root = new URL('../../', import.meta.url).pathname;
const cli = process.env.PDESURF_CLI ?? join(root, 'build/native/pdesurf');
const run = (...args) => spawnSync(cli, args, { encoding: 'utf8' });
const index = JSON.parse(readFileSync(join(root, 'examples/index.json'), 'utf8'));

test('C++ encode-link -> JS decode gives the scene file', async () => {
  for (const { id, file } of index.examples) {
    const scene = JSON.parse(readFileSync(join(root, 'examples', file), 'utf8'));
    const r = run('encode-link', join(root, 'examples', file), '--grid', '40x50');
    assert.equal(r.status, 0, r.stderr);
    const state = await decodeFragment(`http://localhost:8000/web/#${r.stdout.trim()}`);
    assert.deepEqual(state.scene, scene, id);
    assert.deepEqual(state.grid, { nu: 40, nv: 50 }, id);
  }
});

test('JS encode -> C++ decode-link samples bit-identically', async () => {
  const dir = mkdtempSync(join(tmpdir(), 'pdesurf-agree-'));
  for (const { id, file } of index.examples) {
    const path = join(root, 'examples', file);
    const scene = JSON.parse(readFileSync(path, 'utf8'));
    const fragment = await encodeState({ scene, grid: { nu: 32, nv: 32 }, camera: { position: [1, 2, 3], target: [0, 0, 0] } });
    const r = run('decode-link', `#${fragment}`);
    assert.equal(r.status, 0, `${id}: ${r.stderr}`);
    assert.deepEqual(JSON.parse(r.stdout), scene, id);
    const decoded = join(dir, `${id}.json`);
    writeFileSync(decoded, r.stdout);
    const a = run('sample', path, '--grid', '5x6');
    const b = run('sample', decoded, '--grid', '5x6');
    assert.equal(b.stdout, a.stdout, `${id}: samples differ`);
  }
});
