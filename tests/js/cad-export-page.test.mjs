// The page's CAD export without a browser: the tolerance field's reading and the figures
// line (web/export/cad-export.js), and how the solver client (web/solver/solver-client.js)
// fits an export between solves, against a fake worker: an export never runs beside a solve,
// goes before a waiting edit, is not cancelled by one, fails with the worker, and errors keep
// the core's code.
//   node --test tests/js/cad-export-page.test.mjs
import { describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { parseTolerance, fitSummary, fitRecord, CAD_FORMATS } from '../../web/export/cad-export.js';
import { createSolverClient } from '../../web/solver/solver-client.js';

describe('the tolerance field', () => {
  it('blank is the default; a positive number is taken as it is', () => {
    for (const t of ['', '  ', undefined, null]) assert.equal(parseTolerance(t), undefined);
    for (const [t, x] of [['1e-4', 1e-4], [' 0.01 ', 0.01], ['.5', 0.5], ['2', 2], ['+3E-6', 3e-6], ['1.', 1]]) assert.equal(parseTolerance(t), x);
  });

  it('anything else is an InvalidField error quoting what was typed', () => {
    for (const t of ['abc', '-1', '0', '0.0', '1e-400', '1e400', '0x10', 'Infinity', 'NaN', '1e5e', '1 e-4', '1,5', '1e-4mm']) {
      assert.throws(() => parseTolerance(t), (e) => e.code === 'InvalidField'
        && e.message === `tolerance "${t.trim()}": a positive number in scene units (e.g. 1e-4), or empty for the default (1e-6 of the scene's diagonal)`, t);
    }
    assert.throws(() => parseTolerance('9'.repeat(500) + 'x'), (e) => e.message.startsWith(`tolerance "${'9'.repeat(40)}…"`));
  });
});

describe('the figures line', () => {
  const face = (name, deviation, extra = {}) => ({ name, deviation, normalsMet: true, normalDeviationDeg: 1e-4, exact: false, ...extra });

  it('gives the faces, the largest certified deviation and the tolerance', () => {
    const fit = { tolerance: 8.2e-6, faces: [face('blend', 5.31e-6), face('cylinder', 1e-7), face('plane', 0)] };
    assert.deepEqual(fitSummary('step', fit), { text: 'STEP: 3 faces, certified within 5.3e-6 (tolerance 8.2e-6)', missed: [], joinsOff: 0 });
    assert.equal(fitSummary('3dm', { tolerance: 1, faces: [face('a', 0, { exact: true })] }).text, '3dm: 1 face (1 exact), certified within 0 (tolerance 1)');
  });

  it('names the patches whose normals missed the target', () => {
    const fit = { tolerance: 1e-3, faces: [face('a', 1e-4, { normalsMet: false, normalDeviationDeg: 0.0234 }), face('b', 2e-4)] };
    assert.deepEqual(fitSummary('iges', fit), {
      text: 'IGES: 2 faces, certified within 2.0e-4 (tolerance 0.001); normals at the ends of a within 0.023° (target 0.01° not reached)',
      missed: ['a'], joinsOff: 0,
    });
    assert.deepEqual(fitRecord({ ...fit, ms: 12 }).faces.map((f) => f.name), ['a', 'b']);
    assert.deepEqual(Object.keys(CAD_FORMATS), ['step', 'iges', '3dm']);
  });

  it('names the joins between the faces that are off their target, and records every join', () => {
    const join = (patch, extra = {}) => ({ patch, end: 'u0', surface: 'plane', edge: 't0', level: 'G1', gap: 1e-7, allowedGap: 1e-5, normalDeg: 0.0012, ok: true, ...extra });
    const faces = [face('blend', 5.31e-6), face('plane', 0)];
    assert.deepEqual(fitSummary('step', { tolerance: 8.2e-6, faces, joins: [join('blend'), join('blend', { end: 'u1', normalDeg: 0.0043 })] }),
      { text: 'STEP: 2 faces, certified within 5.3e-6 (tolerance 8.2e-6)', missed: [], joinsOff: 0 });
    assert.deepEqual(fitSummary('step', { tolerance: 8.2e-6, faces, joins: [join('blend'), join('blend', { end: 'u1', ok: false, gap: 3e-5, normalDeg: 0.05 })] }), {
      text: 'STEP: 2 faces, certified within 5.3e-6 (tolerance 8.2e-6); joins off their target: blend u1 – plane (gap 3.0e-5, normals 0.05°)',
      missed: [], joinsOff: 1,
    });
    assert.deepEqual(fitRecord({ tolerance: 1, faces, joins: [join('blend')], ms: 3 }).joins.map((j) => [j.patch, j.ok]), [['blend', true]]);
  });
});

// A worker that records what it is sent and answers when told.
class FakeWorker {
  constructor() {
    this.sent = [];
    this.terminated = false;
    FakeWorker.all.push(this);
  }
  postMessage(msg) { this.sent.push(msg); }
  terminate() { this.terminated = true; }
  reply(msg) { this.onmessage({ data: msg }); }
}
FakeWorker.all = [];
globalThis.Worker = FakeWorker;

const tick = (ms = 0) => new Promise((r) => setTimeout(r, ms));

function client() {
  FakeWorker.all.length = 0;
  const results = [], errors = [];
  const c = createSolverClient({ onResult: (r, job) => results.push(job.token), onError: (e, job) => errors.push([e.code, job.token]), workerUrl: 'fake' });
  return { c, w: FakeWorker.all[0], results, errors };
}
const solveReply = (msg, ms = 5) => ({ id: msg.id, ok: true, result: { patches: [] }, ms });
const faces = { title: 't', tolerance: 1e-5, faces: [], text: 'ISO-10303-21;' };

describe('exports in the solver client', () => {
  it('an export while idle goes to the worker at once and resolves with the worker time', async () => {
    const { c, w } = client();
    const p = c.exportCad('{}', { format: 'step', tolerance: undefined });
    assert.equal(w.sent.length, 1);
    assert.deepEqual({ ...w.sent[0], id: 0 }, { id: 0, kind: 'exportCad', scene: '{}', options: { format: 'step', tolerance: undefined } });
    w.reply({ id: w.sent[0].id, kind: 'exportCad', ok: true, result: faces, ms: 42 });
    assert.deepEqual(await p, { ...faces, ms: 42 });
  });

  it('a solve asked for during an export waits for it, and no cancel comes', async () => {
    const { c, w, results } = client();
    const p = c.exportCad('{}', { format: 'iges' });
    c.request({ scene: 's1', options: {}, token: 1 });
    c.request({ scene: 's2', options: {}, token: 1 }); // coalesced with s1
    assert.equal(w.sent.length, 1, 'a solve sent beside the export');
    await tick(400); // past the 300 ms after which a waiting edit cancels a solve
    assert.equal(c.restarts, 0);
    assert.equal(w.terminated, false);
    w.reply({ id: w.sent[0].id, kind: 'exportCad', ok: true, result: faces, ms: 400 });
    await p;
    assert.equal(w.sent.length, 2);
    assert.equal(w.sent[1].scene, 's2');
    w.reply(solveReply(w.sent[1]));
    assert.deepEqual(results, [1]);
  });

  it('an export asked for during a solve waits for it and goes before a waiting edit', async () => {
    const { c, w, results } = client();
    c.request({ scene: 's1', options: {}, token: 1 });
    const p = c.exportCad('{}', { format: 'faces' });
    c.request({ scene: 's2', options: {}, token: 1 });
    assert.deepEqual(w.sent.map((m) => m.kind ?? 'solve'), ['solve']);
    w.reply(solveReply(w.sent[0]));
    assert.deepEqual(w.sent.map((m) => m.kind ?? 'solve'), ['solve', 'exportCad']);
    w.reply({ id: w.sent[1].id, kind: 'exportCad', ok: true, result: faces, ms: 1 });
    await p;
    assert.deepEqual(w.sent.map((m) => m.scene), ['s1', '{}', 's2']);
    w.reply(solveReply(w.sent[2]));
    assert.deepEqual(results, [1, 1]);
    assert.equal(c.restarts, 0);
  });

  it('errors keep the core code; a second export at once is refused; a dead worker fails the export', async () => {
    const { c, w } = client();
    const p = c.exportCad('{}', { format: 'step', tolerance: 1e-300 });
    await assert.rejects(c.exportCad('{}', {}), /another export is running/);
    w.reply({ id: w.sent[0].id, kind: 'exportCad', ok: false, error: { code: 'TooLarge', message: "patch 'blend': …" }, ms: 9 });
    await assert.rejects(p, (e) => e.code === 'TooLarge' && e.message === "patch 'blend': …");
    const q = c.exportCad('{}', { format: 'step' });
    w.onerror({ message: 'boom', preventDefault() {} });
    await assert.rejects(q, (e) => e.code === 'Load' && /the solver worker failed: boom/.test(e.message));
    assert.equal(w.terminated, true);
    // The next export starts a new worker.
    const r = c.exportCad('{}', { format: 'step' });
    const w2 = FakeWorker.all.at(-1);
    assert.notEqual(w2, w);
    w2.reply({ id: w2.sent[0].id, kind: 'exportCad', ok: true, result: faces, ms: 3 });
    assert.equal((await r).text, faces.text);
  });
});
