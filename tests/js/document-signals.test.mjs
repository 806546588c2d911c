// The document's signals are declared once (web/state/document.js SIGNALS): emitting or
// subscribing to an undeclared one throws, and every name the page's sources use is declared
// (issue 39: signals were plain strings listed in comments).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { createDocument, SIGNALS } from '../../web/state/document.js';

const web = new URL('../../web/', import.meta.url).pathname;
const sources = (dir) => readdirSync(dir).flatMap((f) => {
  const p = join(dir, f);
  return statSync(p).isDirectory() ? (f === 'vendor' ? [] : sources(p)) : f.endsWith('.js') ? [p] : [];
});

test('a declared signal reaches its subscribers; an undeclared one throws on emit and on subscribe', () => {
  const doc = createDocument({ scene: { patches: [] } });
  const seen = [];
  const off = doc.on('changed', (edit) => seen.push(edit.name));
  assert.equal(doc.apply({ name: 'nothing', run: () => 1 }).ok, true);
  off();
  doc.apply({ name: 'again', run: () => 2 });
  assert.deepEqual(seen, ['nothing']);
  assert.throws(() => doc.on('chnaged', () => {}), /unknown signal "chnaged"/);
  assert.throws(() => doc.emit('drawn-late'), /unknown signal "drawn-late"/);
  const refused = [];
  doc.on('refused', (err) => refused.push(err.message));
  assert.equal(doc.apply({ name: 'bad', run: () => { throw new Error('no'); } }).ok, false);
  assert.deepEqual(refused, ['no']);
});

test('every signal the page emits or subscribes to is declared, and every declared one is used', () => {
  const used = new Set();
  for (const file of sources(web)) {
    const text = readFileSync(file, 'utf8');
    for (const m of text.matchAll(/\b(?:doc|ctx\.doc)\.(?:on|emit)\('([^']+)'/g)) used.add(m[1]);
    for (const m of text.matchAll(/\bemit\('([^']+)'/g)) used.add(m[1]);
  }
  for (const s of used) assert.ok(Object.hasOwn(SIGNALS, s), `${s} is used but not declared`);
  for (const s of Object.keys(SIGNALS)) assert.ok(used.has(s), `${s} is declared but never used`);
});
