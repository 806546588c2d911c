#!/usr/bin/env node
// Recomputes the "bounds" of examples in examples/index.json from the CLI's samples (32×32 of
// every patch, 12 significant digits, as tests/native/examples_test.cpp checks them).
//   node scripts/example-bounds.mjs [--check] [ID ...]      (no ID: every example)
// Writes index.json in place (only the bounds lines change); --check only reports differences.
import { execFileSync } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';

const root = new URL('..', import.meta.url).pathname;
const cli = process.env.PDESURF_CLI || `${root}build/native/pdesurf`;
const args = process.argv.slice(2);
const check = args.includes('--check');
const ids = args.filter((a) => a !== '--check');
const indexPath = `${root}examples/index.json`;
let text = readFileSync(indexPath, 'utf8');
const index = JSON.parse(text);

const fmt = (x) => String(Number(x.toPrecision(12)));
let changed = 0;
for (const entry of index.examples) {
  if (ids.length && !ids.includes(entry.id)) continue;
  const file = `${root}examples/${entry.file}`;
  const scene = JSON.parse(readFileSync(file, 'utf8'));
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (const patch of scene.patches) {
    const out = execFileSync(cli, ['sample', file, '--patch', patch.name, '--grid', '32x32'], { encoding: 'utf8' });
    for (const line of out.trim().split('\n').slice(1)) {
      const p = line.split(',').slice(2).map(Number);
      for (let c = 0; c < 3; ++c) lo[c] = Math.min(lo[c], p[c]), hi[c] = Math.max(hi[c], p[c]);
    }
  }
  const fresh = `"bounds": {"min": [${lo.map(fmt).join(', ')}], "max": [${hi.map(fmt).join(', ')}]}`;
  // The entry's bounds line: the first "bounds" after its "id".
  const at = text.indexOf(`"id": "${entry.id}"`);
  const re = /"bounds": \{[^}]*\}/g;
  re.lastIndex = at;
  const m = re.exec(text);
  // Rounding-level differences (the CLI and the test sample through different code) are kept.
  const near = (a, b) => Math.abs(a - b) <= 1e-10 * Math.max(1, Math.abs(b));
  const same = entry.bounds && [0, 1, 2].every((c) => near(lo[c], entry.bounds.min[c]) && near(hi[c], entry.bounds.max[c]));
  if (same) continue;
  ++changed;
  console.log(`${entry.id}: ${m[0]}\n${' '.repeat(entry.id.length + 2)}${fresh}`);
  text = text.slice(0, m.index) + fresh + text.slice(m.index + m[0].length);
}
if (!check && changed) writeFileSync(indexPath, text);
console.log(`${changed} bounds ${check ? 'differ' : 'updated'}`);
if (check && changed) process.exit(1);
