// A cold start's first solve done ahead (web/solver/ahead-solve.js in the worker, and how
// web/solver/solver-client.js takes it), without a browser: the worker side against a stubbed
// fetch and a fake solver, the client side against a fake worker. A result solved ahead is
// used only for a request of exactly its scene text and options, once; anything else is
// solved as usual.
//   node --test tests/js/solve-ahead.test.mjs
import { describe, it, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { createAheadSolve, OPENING_OPTIONS } from '../../web/solver/ahead-solve.js';
import { sameSolve } from '../../web/solver/same-solve.js';
import { createSolverClient } from '../../web/solver/solver-client.js';
import { DEFAULT_GRID } from '../../web/state/scene-state.js';

const tick = (ms = 0) => new Promise((r) => setTimeout(r, ms));

describe('sameSolve', () => {
  it('the same text and options in any key order; anything else differs', () => {
    const a = { scene: '{"p":1}', options: { nu: 64, nv: 64, joins: true } };
    assert.ok(sameSolve(a, { scene: '{"p":1}', options: { joins: true, nv: 64, nu: 64 } }));
    assert.ok(!sameSolve(a, { scene: '{"p": 1}', options: a.options }));
    assert.ok(!sameSolve(a, { scene: a.scene, options: { ...a.options, nu: 65 } }));
    assert.ok(!sameSolve(a, { scene: a.scene, options: { ...a.options, curvature: false } }));
  });

  it('opens an example as the page does: the default grid, no curvature, joins, no crossings', () => {
    assert.deepEqual(OPENING_OPTIONS, { ...DEFAULT_GRID, curvature: false, joins: true, crossings: false });
  });
});

describe('the worker side: createAheadSolve', () => {
  const catalogue = { format: 'pdesurf-examples', version: 1, examples: [
    { id: 'first', file: 'first.json', title: 'First' },
    { id: 'other', file: 'other-file.json', title: 'Other' },
  ] };
  const scenes = { 'first.json': { title: 'first', patches: [] }, 'other-file.json': { title: 'other', patches: [1, 2] } };
  let fetched;
  beforeEach(() => {
    fetched = [];
    globalThis.fetch = async (url) => {
      fetched.push(url);
      const name = url.replace('/examples/', '');
      const body = name === 'index.json' ? catalogue : scenes[name];
      return body ? { ok: true, text: async () => JSON.stringify(body) } : { ok: false, status: 404, text: async () => '' };
    };
  });

  function setUp() {
    const solved = [], posted = [];
    const solve = (solver, scene, options) => {
      solved.push([scene, options]);
      return [{ patches: [], scene }, ['buffer']];
    };
    const ahead = createAheadSolve(Promise.resolve('solver'), solve, (msg, transfer) => posted.push([msg, transfer]));
    return { ahead, solved, posted };
  }

  it('solves the example the hash names with the opening options and posts it unasked, once', async () => {
    const { ahead, solved, posted } = setUp();
    ahead.start('#example=other');
    ahead.start('#example=first'); // once per worker
    await tick(10);
    assert.deepEqual(fetched, ['/examples/index.json', '/examples/other-file.json']);
    const text = JSON.stringify(scenes['other-file.json']);
    assert.deepEqual(solved, [[text, OPENING_OPTIONS]]);
    assert.equal(posted.length, 1);
    const [msg, transfer] = posted[0];
    assert.equal(msg.scene, text);
    assert.deepEqual(msg.options, OPENING_OPTIONS);
    assert.equal(msg.result.solvedAhead, true);
    assert.ok(msg.ms >= 0);
    assert.deepEqual(transfer, ['buffer']);
    assert.equal(await ahead.take(text, OPENING_OPTIONS), null, 'posted: no second use');
  });

  it('no hash or an unknown example: the first of the catalogue; a state link: nothing solved, and the page told so', async () => {
    for (const hash of ['', '#', '#example=nope']) {
      const { ahead, posted } = setUp();
      ahead.start(hash);
      await tick(10);
      assert.equal(posted[0][0].scene, JSON.stringify(scenes['first.json']), hash);
    }
    fetched.length = 0;
    const { ahead, posted, solved } = setUp();
    ahead.start('#s=abc');
    await tick(10);
    assert.deepEqual([posted, solved, fetched], [[[{ result: null }, []]], [], []]);
    assert.equal(await ahead.take('x', {}), null);
  });

  it('a request that arrives while it is solved takes it if it asks for the same; else it is dropped unposted', async () => {
    const text = JSON.stringify(scenes['first.json']);
    {
      const { ahead, posted } = setUp();
      ahead.start('#example=first');
      const taken = await ahead.take(text, { ...OPENING_OPTIONS });
      assert.equal(taken.result.scene, text);
      await tick(10);
      assert.deepEqual(posted, []);
    }
    {
      const { ahead, posted } = setUp();
      ahead.start('#example=first');
      assert.equal(await ahead.take(text, { ...OPENING_OPTIONS, curvature: true }), null);
      await tick(10);
      assert.deepEqual(posted, []);
    }
  });

  it('a catalogue or scene that cannot be fetched posts that none will come (the page\'s request reports why)', async () => {
    globalThis.fetch = async () => ({ ok: false, status: 500, text: async () => '' });
    const { ahead, posted, solved } = setUp();
    ahead.start('#example=first');
    await tick(10);
    assert.deepEqual([posted, solved], [[[{ result: null }, []]], []]);
    assert.equal(await ahead.take('x', OPENING_OPTIONS), null);
  });

  it('a solve that throws posts that none will come', async () => {
    const posted = [];
    const ahead = createAheadSolve(Promise.resolve('solver'), () => { throw new Error('no'); }, (msg, transfer) => posted.push([msg, transfer]));
    ahead.start('#example=first');
    await tick(10);
    assert.deepEqual(posted, [[{ result: null }, []]]);
  });
});

// A worker that records what it is sent and answers when told.
class FakeWorker {
  constructor() {
    this.sent = [];
    FakeWorker.all.push(this);
  }
  postMessage(msg) { this.sent.push(msg); }
  terminate() {}
  reply(msg) { this.onmessage({ data: msg }); }
}
FakeWorker.all = [];

describe('the page side: the solver client', () => {
  const scene = '{"title":"first"}';
  const aheadMsg = () => ({ kind: 'ahead', scene, options: OPENING_OPTIONS, result: { patches: ['solved ahead'] }, ms: 7 });
  function client({ earlyWorker = false } = {}) {
    globalThis.Worker = FakeWorker;
    FakeWorker.all.length = 0;
    // web/boot.js's worker, started with the page's hash: the only one that solves ahead.
    globalThis.__pdesurfEarlyWorker = earlyWorker ? new FakeWorker() : undefined;
    const results = [];
    const c = createSolverClient({ onResult: (r, job, ms) => results.push([r.patches[0], job.token, ms]), onError: () => {}, workerUrl: 'fake' });
    return { c, w: FakeWorker.all[0], results };
  }

  it('the first request for that scene and those options takes it without asking the worker, after the caller\'s task', async () => {
    const { c, w, results } = client();
    w.reply(aheadMsg());
    c.request({ scene, options: { joins: true, crossings: false, curvature: false, nv: 64, nu: 64 }, token: 1 });
    assert.deepEqual(results, [], 'not inside the request');
    await tick();
    assert.deepEqual(results, [['solved ahead', 1, 7]]);
    assert.deepEqual(w.sent, []);
  });

  it('another scene or other options go to the worker, and the result ahead is dropped', async () => {
    for (const job of [{ scene: '{"title":"other"}', options: OPENING_OPTIONS }, { scene, options: { ...OPENING_OPTIONS, curvature: true } }]) {
      const { c, w, results } = client();
      w.reply(aheadMsg());
      c.request({ ...job, token: 1 });
      assert.equal(w.sent.length, 1);
      w.reply({ id: w.sent[0].id, ok: true, result: { patches: ['solved'] }, ms: 3 });
      c.request({ scene, options: OPENING_OPTIONS, token: 1 }); // no second use
      assert.equal(w.sent.length, 2);
      w.reply({ id: w.sent[1].id, ok: true, result: { patches: ['solved'] }, ms: 4 });
      await tick();
      assert.deepEqual(results, [['solved', 1, 3], ['solved', 1, 4]]);
    }
  });

  it('arriving while that request runs, it answers it; the worker\'s own reply is dropped', async () => {
    const { c, w, results } = client();
    c.request({ scene, options: OPENING_OPTIONS, token: 1 });
    assert.equal(w.sent.length, 1);
    w.reply(aheadMsg());
    assert.deepEqual(results, [['solved ahead', 1, 7]]);
    w.reply({ id: w.sent[0].id, ok: true, result: { patches: ['solved again'] }, ms: 3 });
    assert.deepEqual(results, [['solved ahead', 1, 7]]);
    c.request({ scene: 'edit', options: OPENING_OPTIONS, token: 1 }); // the client is free again
    assert.equal(w.sent.length, 2);
    w.reply({ id: w.sent[1].id, ok: true, result: { patches: ['edit'] }, ms: 1 });
  });

  it('arriving after a request for something else was answered, it is ignored', async () => {
    const { c, w, results } = client();
    c.request({ scene: 'edit', options: OPENING_OPTIONS, token: 1 });
    w.reply({ id: w.sent[0].id, ok: true, result: { patches: ['solved'] }, ms: 3 });
    w.reply(aheadMsg());
    c.request({ scene, options: OPENING_OPTIONS, token: 2 });
    assert.equal(w.sent.length, 2, 'asked the worker');
    await tick();
    assert.deepEqual(results, [['solved', 1, 3]]);
    w.reply({ id: w.sent[1].id, ok: true, result: { patches: ['solved'] }, ms: 2 });
    assert.deepEqual(results, [['solved', 1, 3], ['solved', 2, 2]]);
  });

  it('a newer request in the same task wins over the result ahead', async () => {
    const { c, w, results } = client();
    w.reply(aheadMsg());
    c.request({ scene, options: OPENING_OPTIONS, token: 1 });
    c.request({ scene: 'another scene', options: OPENING_OPTIONS, token: 2 });
    await tick();
    assert.deepEqual(results, []);
    assert.deepEqual(w.sent.map((m) => m.scene), ['another scene']);
    w.reply({ id: w.sent[0].id, ok: true, result: { patches: ['another'] }, ms: 2 });
    assert.deepEqual(results, [['another', 2, 2]]);
  });

  describe('onAhead: the surface solved ahead, for the page to draw before it is wired (web/first-surface.js)', () => {
    const heard = (c) => {
      const got = [];
      const stop = c.onAhead((msg) => got.push(msg && msg.result.patches[0]));
      return { got, stop };
    };

    it('tells its listeners when it comes, or at once if it is here; the first request still takes it', async () => {
      const { c, w, results } = client({ earlyWorker: true });
      const early = heard(c);
      assert.deepEqual(early.got, []);
      w.reply(aheadMsg());
      assert.deepEqual(early.got, ['solved ahead']);
      assert.deepEqual(heard(c).got, ['solved ahead'], 'here already');
      c.request({ scene, options: OPENING_OPTIONS, token: 1 });
      await tick();
      assert.deepEqual(results, [['solved ahead', 1, 7]]);
      // Taken: the worker may now measure its report (held so as not to slow the first frame).
      assert.deepEqual(w.sent, [{ kind: 'certifyAhead' }]);
      assert.deepEqual(early.got, ['solved ahead'], 'told once');
    });

    it('null when none will come: the worker says so, it fails, or it is not the worker that solves ahead', async () => {
      {
        const { c, w } = client({ earlyWorker: true });
        const l = heard(c);
        w.reply({ kind: 'ahead', result: null });
        assert.deepEqual(l.got, [null]);
        assert.deepEqual(heard(c).got, [null], 'and to later listeners at once');
        c.request({ scene, options: OPENING_OPTIONS, token: 1 });
        assert.equal(w.sent.length, 1, 'the request goes to the worker');
        w.reply({ id: w.sent[0].id, ok: true, result: { patches: ['solved'] }, ms: 3 });
      }
      {
        const { c, w } = client({ earlyWorker: true });
        const l = heard(c);
        w.onerror({ preventDefault() {}, message: 'boom' });
        assert.deepEqual(l.got, [null]);
      }
      {
        const { c } = client();
        assert.deepEqual(heard(c).got, [null], 'a worker of its own');
      }
      {
        const { c, w } = client({ earlyWorker: true });
        c.request({ scene: 'edit', options: OPENING_OPTIONS, token: 1 });
        assert.deepEqual(heard(c).got, [null], 'a request was made: no use waiting');
        w.reply({ id: w.sent[0].id, ok: true, result: { patches: ['solved'] }, ms: 3 });
      }
    });

    it('a listener that stopped is not told; the result is still kept for the request', async () => {
      const { c, w, results } = client({ earlyWorker: true });
      const l = heard(c);
      l.stop();
      w.reply(aheadMsg());
      assert.deepEqual(l.got, []);
      c.request({ scene, options: OPENING_OPTIONS, token: 1 });
      await tick();
      assert.deepEqual(results, [['solved ahead', 1, 7]]);
    });
  });

  it('certifyAhead: the worker that solved ahead is told once that its surface is drawn; another worker never', async () => {
    {
      const { c, w } = client({ earlyWorker: true });
      w.reply(aheadMsg());
      c.certifyAhead(); // web/first-surface.js, after that frame
      c.request({ scene, options: OPENING_OPTIONS, token: 1 }); // taking it says so too
      await tick();
      c.certifyAhead();
      assert.deepEqual(w.sent, [{ kind: 'certifyAhead' }]);
    }
    {
      const { c, w } = client();
      w.reply(aheadMsg());
      c.certifyAhead();
      c.request({ scene, options: OPENING_OPTIONS, token: 1 });
      await tick();
      assert.deepEqual(w.sent, []);
    }
  });
});
