// web/solver/pdesurf-solver.js against a stand-in module: the wrapper turns the
// module's result-or-error value into data or a thrown PdesurfError.
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { loadSolver, PdesurfError } from '../../web/solver/pdesurf-solver.js';
import { hasWasmSimd } from '../../web/solver/wasm-features.js';

// A factory with the real module's shape: solveScene(text, nu, nv) -> {ok, ...}.
const STUB = `
export default async function createModule(opts) {
  return {
    gotBinary: !!opts.wasmBinary,
    solveScene(text, nu, nv) {
      const s = JSON.parse(text);
      if (s.fail) return { ok: false, error: { code: s.fail, message: 'bad ' + s.fail } };
      if (s.throwRaw) throw 12345;
      const V = (nu + 1) * (nv + 1);
      const ends = s.ends ? { u1: { surface: 'sphere', derived: { x: ['cos(v)', '2*cos(v)'], y: ['sin(v)', '0'], z: ['1', '0.5'] } } } : undefined;
      return { ok: true, patches: [{ name: 'blend', kind: 'pde', ends,
        operator: { x: { order: 4, params: { b: 2, c: 1, d: 1 } }, y: { order: 2, params: { s: 1, t: 0.5 } }, z: { order: 6, params: { a: 3 } } }, method: 'closed', methods: ['auto', 'closed'],
        positions: new Float32Array(3 * V).fill(1), normals: new Float32Array(3 * V), uvs: new Float32Array(2 * V),
        indices: new Uint32Array(6 * nu * nv) }] };
    },
  };
}`;

describe('solver wrapper', () => {
  let dir, solver;
  before(async () => {
    dir = fs.mkdtempSync(path.join(os.tmpdir(), 'pdesurf-stub-'));
    const file = path.join(dir, 'pdesurf.js');
    fs.writeFileSync(file, STUB);
    solver = await loadSolver({ moduleUrl: pathToFileURL(file).href, wasmBinary: new Uint8Array(8) });
  });
  after(() => fs.rmSync(dir, { recursive: true, force: true }));

  it('passes wasmBinary to the factory', () => {
    assert.equal(solver.module.gotBinary, true);
  });

  it('accepts a scene object or JSON text and returns typed arrays', () => {
    for (const scene of [{ patches: [] }, '{"patches": []}']) {
      const { patches } = solver.solve(scene, { nu: 2, nv: 3 });
      assert.equal(patches.length, 1);
      const p = patches[0];
      assert.ok(p.positions instanceof Float32Array && p.positions.length === 3 * 12);
      assert.ok(p.indices instanceof Uint32Array && p.indices.length === 36);
      assert.deepEqual(p.operator, { x: { order: 4, params: { b: 2, c: 1, d: 1 } }, y: { order: 2, params: { s: 1, t: 0.5 } }, z: { order: 6, params: { a: 3 } } });
    }
  });

  it('passes the derived conditions of ends by reference through, and gives none otherwise', () => {
    const [p] = solver.solve({ ends: true }, { nu: 2, nv: 2 }).patches;
    assert.deepEqual(p.ends, { u1: { surface: 'sphere', derived: { x: ['cos(v)', '2*cos(v)'], y: ['sin(v)', '0'], z: ['1', '0.5'] } } });
    assert.equal(solver.solve({}, { nu: 2, nv: 2 }).patches[0].ends, undefined);
  });

  it('throws PdesurfError with the code for an error result', () => {
    assert.throws(() => solver.solve({ fail: 'DegenerateOperator' }), (e) =>
      e instanceof PdesurfError && e instanceof Error && e.code === 'DegenerateOperator' && e.message === 'bad DegenerateOperator');
  });

  it('turns a raw throw into PdesurfError Internal', () => {
    assert.throws(() => solver.solve({ throwRaw: true }), (e) => e instanceof PdesurfError && e.code === 'Internal');
  });

  it('reports a module that cannot be loaded', async () => {
    await assert.rejects(loadSolver({ moduleUrl: pathToFileURL(path.join(dir, 'missing.js')).href }),
      (e) => e instanceof PdesurfError && e.code === 'Load');
  });
});

// The worker hands the wrapper a module compiled as it streamed in (solver-worker.js): the
// real module, instantiated from it; and one that cannot be instantiated fails the load
// rather than leaving it waiting forever (emscripten's instantiateWasm hook has no error path).
describe('solver wrapper: a compiled module', () => {
  const build = process.env.PDESURF_BUILD_DIR || path.join(path.dirname(new URL(import.meta.url).pathname), '..', '..', 'build');
  const wasmDir = path.resolve(build, 'wasm');
  const moduleUrl = pathToFileURL(path.join(wasmDir, 'pdesurf.js')).href;
  const scene = fs.readFileSync(new URL('../../examples/you2004-fig2a.json', import.meta.url), 'utf8');

  it('is instantiated and solves, given as a module or a promise of one', async () => {
    const bytes = fs.readFileSync(path.join(wasmDir, 'pdesurf.wasm'));
    for (const wasmModule of [await WebAssembly.compile(bytes), WebAssembly.compile(bytes)]) {
      const solver = await loadSolver({ moduleUrl, wasmModule });
      const { patches } = solver.solve(scene, { nu: 8, nv: 8 });
      assert.equal(patches.length, 3);
      assert.equal(patches[0].positions.length, 3 * 81);
      assert.ok(patches.every((p) => p.positions.every(Number.isFinite)));
    }
  });

  it('one that cannot be instantiated (an import the glue lacks) fails the load with Load', { timeout: 20_000 }, async () => {
    // (import "x" "y" (func)): the glue offers no "x".
    const bytes = Uint8Array.of(0, 0x61, 0x73, 0x6d, 1, 0, 0, 0, 1, 4, 1, 0x60, 0, 0, 2, 7, 1, 1, 0x78, 1, 0x79, 0, 0);
    await assert.rejects(loadSolver({ moduleUrl, wasmModule: WebAssembly.compile(bytes) }),
      (e) => e instanceof PdesurfError && e.code === 'Load' && /cannot start the solver module/.test(e.message));
  });

  it('a module that cannot be compiled fails the load with Load', async () => {
    await assert.rejects(loadSolver({ moduleUrl, wasmModule: WebAssembly.compile(Uint8Array.of(0, 1, 2, 3)) }),
      (e) => e instanceof PdesurfError && e.code === 'Load');
  });
});

// The module needs WebAssembly SIMD; every supported browser has it, and one without it is
// told so by name (node cannot turn SIMD off, so an engine without it is a stand-in whose
// validate refuses every module).
describe('solver wrapper: an engine without WebAssembly SIMD', () => {
  const build = process.env.PDESURF_BUILD_DIR || path.join(path.dirname(new URL(import.meta.url).pathname), '..', '..', 'build');
  const wasmDir = path.resolve(build, 'wasm');
  const moduleUrl = pathToFileURL(path.join(wasmDir, 'pdesurf.js')).href;

  it('node has it, and the module built uses it', () => {
    assert.equal(hasWasmSimd(), true);
    const code = codeSection(fs.readFileSync(path.join(wasmDir, 'pdesurf.wasm')));
    // f32x4.demote_f64x2_zero (0xfd 0x5e): the frame pass converts four values with two of them
    let demotes = 0;
    for (let i = code.indexOf(0xfd); i >= 0; i = code.indexOf(0xfd, i + 1)) if (code[i + 1] === 0x5e) demotes++;
    assert.ok(demotes >= 8, `${demotes} f32x4.demote_f64x2_zero in pdesurf.wasm's code`);
  });

  it('is refused up front with Unsupported, naming what is missing, and no rejection is left unhandled', async () => {
    const validate = WebAssembly.validate;
    const unhandled = [];
    const onUnhandled = (reason) => unhandled.push(reason);
    process.on('unhandledRejection', onUnhandled);
    WebAssembly.validate = () => false;
    try {
      assert.equal(hasWasmSimd(), false);
      const compile = Promise.reject(new Error('CompileError: invalid opcode 0xfd'));
      await assert.rejects(loadSolver({ moduleUrl, wasmModule: compile }),
        (e) => e instanceof PdesurfError && e.code === 'Unsupported' && /lacks WebAssembly SIMD/.test(e.message) && /Safari 16\.4/.test(e.message));
      await new Promise((resolve) => setTimeout(resolve, 20));
      assert.deepEqual(unhandled, []);
    } finally {
      WebAssembly.validate = validate;
      process.off('unhandledRejection', onUnhandled);
    }
    assert.equal(hasWasmSimd(), true);
    assert.equal(hasWasmSimd(null), false);
    assert.equal(hasWasmSimd({ validate: () => { throw new Error('no'); } }), false);
  });
});

// The bytes of a module's code section (id 10): sections are an id and a LEB128 size.
function codeSection(bytes) {
  let at = 8;
  while (at < bytes.length) {
    const id = bytes[at++];
    let size = 0;
    for (let shift = 0; ; shift += 7) {
      const b = bytes[at++];
      size += (b & 0x7f) * 2 ** shift;
      if (b < 0x80) break;
    }
    if (id === 10) return bytes.subarray(at, at + size);
    at += size;
  }
  throw new Error('no code section');
}
