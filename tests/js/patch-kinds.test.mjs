// One table of patch kinds in each half (issue 39): the core's (cpp/scene/patch_kinds.hpp,
// through the module's patchKinds()) and the page's (web/state/patch-kinds.js) name the same
// kinds, and agree on which the core solves and which are PDEs.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { wasmDir } from './test-solver.mjs';
import { KIND_NAMES, kindInfo } from '../../web/state/patch-kinds.js';

test("the core's kinds are the page's, solved and PDE alike", async () => {
  const { default: create } = await import(new URL('pdesurf.js', wasmDir).href);
  const Module = await create({ wasmBinary: readFileSync(new URL('pdesurf.wasm', wasmDir)) });
  const core = Array.from(Module.patchKinds());
  assert.deepEqual(core.map((k) => k.name).sort(), [...KIND_NAMES].sort());
  for (const k of core) {
    const page = kindInfo(k.name);
    assert.equal(page.solved, k.solvedAs !== 'primary', `${k.name}: solved`);
    assert.equal(page.pde, k.solvedAs === 'pde', `${k.name}: pde`);
    assert.ok(k.since >= 1 && k.since <= 4, `${k.name}: since ${k.since}`);
  }
});
