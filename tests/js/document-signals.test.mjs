// The document's signals are declared once (web/state/document.js SIGNALS): emitting or
// subscribing to an undeclared one throws, and every name the page's sources use is declared
// (issue 39: signals were plain strings listed in comments).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { createDocument, SIGNALS, EDIT_TYPES } from '../../web/state/document.js';
import { edits } from '../../web/state/edits.js';
import { buildEdits } from '../../web/state/build-edits.js';

const web = new URL('../../web/', import.meta.url).pathname;
const sources = (dir) => readdirSync(dir).flatMap((f) => {
  const p = join(dir, f);
  return statSync(p).isDirectory() ? (f === 'vendor' ? [] : sources(p)) : f.endsWith('.js') ? [p] : [];
});

test('a declared signal reaches its subscribers; an undeclared one throws on emit and on subscribe', () => {
  const doc = createDocument({ scene: { patches: [] } });
  const seen = [];
  const off = doc.on('changed', (edit) => seen.push(edit.name));
  assert.equal(doc.apply(edits.controlNet(() => 1)).ok, true);
  off();
  doc.apply(edits.controlNet(() => 2));
  assert.deepEqual(seen, ['edit the control net']);
  assert.throws(() => doc.on('chnaged', () => {}), /unknown signal "chnaged"/);
  assert.throws(() => doc.emit('drawn-late'), /unknown signal "drawn-late"/);
  const refused = [];
  doc.on('refused', (err) => refused.push(err.message));
  assert.equal(doc.apply(edits.controlNet(() => { throw new Error('no'); })).ok, false);
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

test('the grid and the parameters change through the door only, refused by name when out of range', async () => {
  const { createSceneState } = await import('../../web/state/scene-state.js');
  const state = createSceneState();
  state.scene = { format: 'pdesurf-scene', version: 4, parameters: { r: { value: 1, min: 0, max: 2 } }, patches: [] };
  const doc = createDocument(state);
  const changed = [];
  doc.on('changed', (edit) => changed.push(edit.name));
  assert.equal(doc.apply(edits.setGrid({ nu: 32, nv: 48 })).ok, true);
  assert.deepEqual(state.grid, { nu: 32, nv: 48 });
  const bad = doc.apply(edits.setGrid({ nu: 0, nv: 48 }));
  assert.equal(bad.ok, false);
  assert.match(bad.error.message, /the grid's nu must be a whole number from 1 to 2048, not 0/);
  assert.deepEqual(state.grid, { nu: 32, nv: 48 });
  assert.equal(doc.apply(edits.setParameter('r', 1.5)).ok, true);
  assert.equal(state.scene.parameters.r.value, 1.5);
  assert.match(doc.apply(edits.setParameter('q', 1)).error.message, /there is no parameter "q"/);
  assert.match(doc.apply(edits.setParameter('r', NaN)).error.message, /must be a finite number/);
  assert.equal(state.scene.parameters.r.value, 1.5);
  assert.deepEqual(changed, ['change the grid', 'change a parameter']);
});

test('every edit comes from the catalogue: each factory\'s type is declared, each declared type has a factory, others are refused', () => {
  const made = new Set();
  const args = Array(5).fill(() => {}); // nothing runs: the factories only make edits
  for (const make of [...Object.values(edits), ...Object.values(buildEdits)]) {
    const e = make(...args);
    assert.ok(EDIT_TYPES.has(e.type), `${e.type} is not declared`);
    assert.equal(typeof e.run, 'function');
    assert.equal(typeof e.name, 'string');
    made.add(e.type);
  }
  assert.deepEqual([...EDIT_TYPES].filter((t) => !made.has(t)), []);
  const doc = createDocument({ scene: { patches: [] } });
  assert.throws(() => doc.apply({ name: 'change a parameter', run: () => {} }), /an edit of unknown type undefined/);
  assert.throws(() => doc.apply({ type: 'teleport', name: 'x', run: () => {} }), /unknown type "teleport"/);
  // No feature writes an edit by hand: every door call takes a factory's edit.
  for (const file of sources(web)) {
    const text = readFileSync(file, 'utf8');
    assert.ok(!/\.apply\(\{/.test(text), `${file} hands the door an edit it made itself`);
  }
});
