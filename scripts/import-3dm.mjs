#!/usr/bin/env node
// A Rhino .3dm file's surfaces as a scene, from the command line: the page's reader
// (web/cad/read-3dm.js, rhino3dm from npm) under node, since pdesurf's native build has no
// openNURBS. The scene is the one the page opens for the same file (docs/cad-import.md).
//   node scripts/import-3dm.mjs FILE.3dm [-o SCENE.json]      (default: standard output)
// Exit 1 with "import-3dm: FILE: CODE: message" on a bad file; nothing is written then.
import { readFileSync, writeFileSync } from 'node:fs';
import { basename } from 'node:path';
import { read3dm } from '../web/cad/read-3dm.js';

const args = process.argv.slice(2);
const out = args.includes('-o') ? args[args.indexOf('-o') + 1] : null;
const file = args.find((a, k) => a !== '-o' && args[k - 1] !== '-o');
if (!file || (args.includes('-o') && !out) || args.length !== (out ? 3 : 1)) {
  console.error('usage: node scripts/import-3dm.mjs FILE.3dm [-o SCENE.json]');
  process.exit(2);
}
try {
  let bytes;
  try {
    bytes = readFileSync(file);
  } catch (err) {
    throw Object.assign(new Error(`cannot be read (${err.code ?? err.message})`), { code: 'InvalidField' });
  }
  const text = `${JSON.stringify(await read3dm(bytes, { fileName: basename(file) }))}\n`;
  if (out) writeFileSync(out, text);
  else process.stdout.write(text);
} catch (err) {
  console.error(`import-3dm: ${file}: ${err.code ? `${err.code}: ` : ''}${err.message}`);
  process.exit(1);
}
