// web/state/hash-sync.js in node, with location/history stubbed: requests made while an
// encode runs collapse into one and the newest state wins; cancel() drops in-flight work;
// flush() waits for the newest state; only a user's camera move (inside start/end) counts.
//   node --test tests/js/
import { describe, it, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { createHashSync } from '../../web/state/hash-sync.js';
import { decodeFragment } from '../../web/link/link-codec.js';
import { hashIsShown } from '../../web/state/hash.js';

const scene = (r) => ({ format: 'pdesurf-scene', version: 2, parameters: { r: { value: r } }, patches: [] });

let writes;
beforeEach(() => {
  writes = [];
  globalThis.location = { hash: '', href: 'http://page/web/' };
  globalThis.history = {
    replaceState(_state, _title, url) {
      location.hash = url;
      location.href = `http://page/web/${url}`;
      writes.push(url);
    },
  };
});

function makeSync() {
  let r = 0;
  const written = [];
  const sync = createHashSync({
    snapshot: () => ({ scene: scene(r), camera: { position: [1, 2, 3], target: [0, 0, 0] } }),
    onWritten: (url) => written.push(url),
    onError: (err) => assert.fail(err),
  });
  return { sync, written, set: (v) => { r = v; } };
}

const rOf = async (hash) => (await decodeFragment(hash)).scene.parameters.r.value;

describe('hash sync', () => {
  it('collapses requests made during an encode; the newest state wins', async () => {
    const { sync, written, set } = makeSync();
    for (let v = 1; v <= 5; v++) {
      set(v);
      sync.request();
    }
    await sync.flush();
    assert.equal(writes.length, 2, 'one encode for the first request, one for all the rest');
    assert.equal(await rOf(writes[0]), 1);
    assert.equal(await rOf(writes[1]), 5);
    assert.match(location.hash, /^#s=1\./);
    assert.equal(written.at(-1), location.href);
    assert.ok(hashIsShown(), 'its own write must count as shown');
  });

  it('cancel() keeps an encode in flight from writing', async () => {
    const { sync } = makeSync();
    sync.request();
    sync.cancel();
    await sync.flush();
    await new Promise((r) => setTimeout(r, 20));
    assert.deepEqual(writes, []);
  });

  it('a camera move writes once it rests; fit() and a plain click do not', async () => {
    const { sync, set } = makeSync();
    const controls = new EventTarget();
    const fire = (type) => controls.dispatchEvent(new Event(type));
    sync.watchCamera(controls);
    fire('change'); // fit() / setCamera(): outside start/end
    fire('start');
    fire('end'); // a click
    await sync.flush();
    assert.deepEqual(writes, []);

    set(7);
    fire('start');
    fire('change');
    fire('end');
    await new Promise((r) => setTimeout(r, 100));
    assert.deepEqual(writes, [], 'written before the camera rested');
    await new Promise((r) => setTimeout(r, 500));
    await sync.flush();
    assert.equal(writes.length, 1);
    assert.equal(await rOf(writes[0]), 7);

    set(8);
    fire('start');
    fire('change');
    fire('end');
    await sync.flush(); // the copy button does not wait for the rest
    assert.equal(writes.length, 2);
    assert.equal(await rOf(writes[1]), 8);
  });
});
