#!/usr/bin/env node
// Writes tests/hostile/links/*.txt and links.json: hostile and edge-case links, each with the
// verdict both link codecs (web/link/ and cli/link_codec.cpp) must reach. Deterministic; run
// again after adding a case (existing files come out byte-identical).
//   node tests/hostile/make-links.mjs
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { fileURLToPath } from 'node:url';

const HERE = path.dirname(fileURLToPath(import.meta.url));
const b64 = (buf) => Buffer.from(buf).toString('base64url');
const deflate = (text) => zlib.deflateRawSync(Buffer.from(text), { level: 9 });
const link = (payload) => `s=1.${b64(payload)}`;
const scene = JSON.parse(fs.readFileSync(path.join(HERE, '..', '..', 'examples', 'zhang-vase-fig2a.json'), 'utf8'));
const good = JSON.stringify({ scene });
const nest = (depth) => '['.repeat(depth) + ']'.repeat(depth);

// verdict: "open" (both decode it and the scene parses) or "refuse" (both refuse).
const cases = [
  ['good', link(deflate(good)), 'open', 'a plain version-1 link'],
  ['good-wrapped', `https://example.org/web/#${link(deflate(good)).replace(/(.{60})/g, '$1\n  ')}`, 'open', 'whitespace from a mail client is dropped'],
  ['good-more-fields', `#x=1&${link(deflate(good))}&y=2`, 'open', 'the s= field among others'],
  ['version-leading-zero', `s=01.${b64(deflate(good))}`, 'refuse', 'the version is exactly "1"'],
  ['version-space', `s=1 .${b64(deflate(good))}`, 'open', 'whitespace anywhere is dropped, so "1 ." is "1."'],
  ['percent-encoded', `s=1%2E${b64(deflate(good))}`, 'open', 'percent-encoding (here of the dot) is decoded by both'],
  ['percent-broken', `s=1%ZZ.${b64(deflate(good))}`, 'refuse', 'a broken percent-escape'],
  ['percent-version', `s=%301.${b64(deflate(good))}`, 'refuse', 'a percent-encoded "0" makes the version "01"'],
  ['trailing-garbage', link(Buffer.concat([deflate(good), Buffer.from('junk')])), 'refuse', 'bytes after the end of the deflate stream'],
  ['second-stream', link(Buffer.concat([deflate(good), deflate(good)])), 'refuse', 'a second deflate stream after the first'],
  ['deep-1000', link(deflate(`{"scene": {"format": ${nest(1000)}}}`)), 'refuse', '1,000 nested arrays: refused before anything is built'],
  ['deep-30000', link(deflate(`{"scene": {"format": ${nest(30000)}}}`)), 'refuse', '30,000 nested arrays'],
  ['deep-100000', link(deflate(nest(100000))), 'refuse', '100,000 nested arrays'],
  ['depth-33', link(deflate(`{"scene": {"x": ${nest(31)}}}`)), 'refuse', 'one level over the limit of 32'],
  ['duplicate-key-state', link(deflate(`{"scene": ${JSON.stringify(scene)}, "scene": {}}`)), 'refuse', 'a key twice: readers would disagree on which wins'],
  ['duplicate-key-scene', link(deflate(good.replace('"version":2', '"version":2,"version":2'))), 'refuse', 'a key twice inside the scene'],
  ['newline-in-title', link(deflate(JSON.stringify({ scene: { ...scene, title: 'a\nv 1 2 3' } }))), 'refuse', 'a control character in a one-line field'],
  ['not-json', link(deflate('not json')), 'refuse', 'content that is not JSON'],
  ['no-scene', link(deflate('{"grid": {"nu": 8, "nv": 8}}')), 'refuse', 'no scene'],
  ['empty-data', 's=1.', 'refuse', 'no data'],
  ['bad-base64', 's=1.ab$c', 'refuse', 'a character outside base64url'],
  // Issue 38 #13: the page solved these (its JSON has one kind of number) and decode-link refused them.
  ['scene-version-2.0', link(deflate(good.replace('"version":2', '"version":2.0'))), 'open', 'a scene version written 2.0 is version 2, as JSON and the page read it'],
  ['scene-version-2e0', link(deflate(good.replace('"version":2', '"version":2e0'))), 'open', 'a scene version written 2e0 is version 2'],
  ['scene-version-2.5', link(deflate(good.replace('"version":2', '"version":2.5'))), 'refuse', 'a scene version 2.5 is none'],
];

const manifest = { format: 'pdesurf-hostile-links', version: 1, links: [] };
fs.mkdirSync(path.join(HERE, 'links'), { recursive: true });
for (const [name, text, verdict, why] of cases) {
  fs.writeFileSync(path.join(HERE, 'links', `${name}.txt`), text);
  manifest.links.push({ name, file: `links/${name}.txt`, verdict, why });
}
fs.writeFileSync(path.join(HERE, 'links.json'), JSON.stringify(manifest, null, 2) + '\n');
console.log(`${cases.length} links written`);
