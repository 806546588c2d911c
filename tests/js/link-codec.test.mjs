// web/link/: the shareable-link codec. Round trips, every way a link is refused, and
// a real inflate bomb that must be stopped quickly without inflating it.
import { describe, it } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { encodeState, decodeFragment, LinkError, LINK_VERSION } from '../../web/link/link-codec.js';
import { encodeBase64url, decodeBase64url } from '../../web/link/base64url.js';
import { deflateRaw, inflateRawCapped } from '../../web/link/deflate.js';
import { MAX_INFLATED_BYTES } from '../../web/link/link-v1.js';

const SCENE = JSON.parse(fs.readFileSync(new URL('../../examples/you2004-fig2a.json', import.meta.url), 'utf8'));
const CAMERA = { position: [1, -2.5, 3], target: [0, 0, 0.75] };

// Link text from any JSON value or raw text, bypassing encodeState's checks.
async function rawLink(value, version = 1) {
  const text = typeof value === 'string' ? value : JSON.stringify(value);
  return `s=${version}.${encodeBase64url(await deflateRaw(new TextEncoder().encode(text)))}`;
}
const refuses = (promise, pattern) => assert.rejects(promise, (err) => {
  assert.ok(err instanceof LinkError, `not a LinkError: ${err}`);
  assert.match(err.message, pattern);
  return true;
});

describe('base64url', () => {
  it('round-trips every byte value without padding', () => {
    for (const n of [0, 1, 2, 3, 4, 255, 256, 70000]) {
      const bytes = Uint8Array.from({ length: n }, (_, i) => (i * 37 + n) & 0xff);
      const text = encodeBase64url(bytes);
      assert.match(text, /^[A-Za-z0-9_-]*$/);
      assert.deepEqual(decodeBase64url(text), bytes);
    }
  });
  it('refuses other characters and impossible lengths', () => {
    assert.throws(() => decodeBase64url('ab+c'), LinkError);
    assert.throws(() => decodeBase64url('abc='), LinkError);
    assert.throws(() => decodeBase64url('abcde'), /impossible length/);
  });
});

describe('link codec', () => {
  it('round-trips the page state and writes the current link version', async () => {
    const state = { scene: SCENE, grid: { nu: 32, nv: 100 }, camera: CAMERA };
    const link = await encodeState(state);
    assert.ok(link.startsWith(`s=${LINK_VERSION}.`));
    assert.match(link.slice(4), /^[A-Za-z0-9_-]+$/);
    assert.ok(link.length < JSON.stringify(SCENE).length * 0.75, 'the link is not compressed');
    assert.deepEqual(await decodeFragment(link), state);
  });

  it('accepts a full URL, a hash and the bare fragment, other hash fields and line breaks', async () => {
    const link = await encodeState({ scene: SCENE });
    for (const text of [link, `#${link}`, `https://example.org/web/?q=1#${link}`, `#example=x&${link}`,
      `${link.slice(0, 300)}\n  ${link.slice(300)}`, link.replace('s=1.', 's=1%2E')]) {
      assert.deepEqual(await decodeFragment(text), { scene: SCENE }, text.slice(0, 40));
    }
  });

  it('keeps non-ASCII and markup characters as they are', async () => {
    const scene = { ...SCENE, title: '∂²X/∂u² “ü” <img src=x onerror=alert(1)> \u{1F600}' };
    assert.equal((await decodeFragment(await encodeState({ scene }))).scene.title, scene.title);
  });

  it('drops a malformed grid or camera instead of refusing the link', async () => {
    const link = await rawLink({ scene: SCENE, grid: { nu: 1e9, nv: 3 }, camera: { position: [1, 2], target: 'x' }, extra: 1 });
    assert.deepEqual(await decodeFragment(link), { scene: SCENE });
  });

  it('refuses a scene too large to link', async () => {
    const scene = { title: 'x'.repeat(MAX_INFLATED_BYTES) };
    await refuses(encodeState({ scene }), /too large/);
    await refuses(encodeState({}), /no scene/);
  });

  it('refuses each kind of damage with its own message', async () => {
    const good = await encodeState({ scene: SCENE });
    await refuses(decodeFragment('#example=a'), /no page state/);
    await refuses(decodeFragment('s=x.abc'), /expected "s=<version>.<data>"/);
    await refuses(decodeFragment(good.replace('s=1.', 's=9.')), /unknown link version 9/);
    await refuses(decodeFragment(good.replace('s=1.', 's=0.')), /unknown link version 0/);
    await refuses(decodeFragment('s=1.'), /no data/);
    await refuses(decodeFragment('s=1.abc*def'), /not a base64url character/);
    await refuses(decodeFragment('s=1.abcde'), /impossible length/);
    await refuses(decodeFragment('s=1.%E0%A4%A'), /percent-encoding/);
    await refuses(decodeFragment(good.slice(0, 200)), /compressed data is broken/);
    await refuses(decodeFragment('s=1.AAAAAAAA'), /compressed data is broken/);
    await refuses(decodeFragment(await rawLink('not json')), /not JSON/);
    await refuses(decodeFragment(`s=1.${encodeBase64url(await deflateRaw(Uint8Array.of(0xff, 0xfe, 0x7b)))}`), /not UTF-8/);
    await refuses(decodeFragment(await rawLink([{ scene: {} }])), /not a JSON object/);
    await refuses(decodeFragment(await rawLink('null')), /not a JSON object/);
    await refuses(decodeFragment(await rawLink({ grid: {} })), /holds no scene/);
    await refuses(decodeFragment(await rawLink({ scene: [1] })), /scene is not a JSON object/);
    await refuses(decodeFragment(`s=1.${'A'.repeat(3 << 20)}`), /too long/);
    await refuses(decodeFragment(42), /not text/);
  });

  it('accepts an inflated size up to 1 MiB and refuses one byte more', async () => {
    const frame = JSON.stringify({ scene: {}, pad: '' }).length;
    const exact = { scene: {}, pad: 'y'.repeat(MAX_INFLATED_BYTES - frame) };
    assert.equal((await decodeFragment(await rawLink(exact))).scene.constructor, Object);
    const over = { scene: {}, pad: 'y'.repeat(MAX_INFLATED_BYTES - frame + 1) };
    await refuses(decodeFragment(await rawLink(over)), /inflates to more than 1048576 bytes/);
  });

  it('stops an inflate bomb (50 MB of zeros in a few tens of kB) fast, without inflating it', async () => {
    // Deflated in slices: one 50 MB buffer would be what the test is about to avoid.
    const cs = new CompressionStream('deflate-raw');
    const writer = cs.writable.getWriter();
    const zeros = new Uint8Array(1 << 20);
    const writing = (async () => {
      for (let i = 0; i < 50; i++) await writer.write(zeros);
      await writer.close();
    })();
    const parts = [];
    for await (const c of cs.readable) parts.push(c);
    await writing;
    const bomb = new Uint8Array(await new Blob(parts).arrayBuffer());
    assert.ok(bomb.length < 100_000, `bomb is ${bomb.length} bytes`);

    const rss0 = process.memoryUsage().rss;
    const t0 = performance.now();
    await refuses(decodeFragment(`s=1.${encodeBase64url(bomb)}`), /inflates to more than/);
    const ms = performance.now() - t0;
    assert.ok(ms < 500, `took ${ms.toFixed(0)} ms`);
    const grew = process.memoryUsage().rss - rss0;
    assert.ok(grew < 40e6, `memory grew by ${(grew / 1e6).toFixed(1)} MB`);
    // The capped inflater alone: stopped just past the cap, the rest never produced.
    await assert.rejects(inflateRawCapped(bomb, 1000), /more than 1000 bytes/);
  });
});
