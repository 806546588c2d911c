// Benchmark (not a test): the whole CAD export of a model as a user runs it, `pdesurf export`
// to STEP and to IGES (solve, certified fit of every patch, joins, topology, the file), on one
// thread and on the machine's (--jobs default), interleaved, median of 5 wall times.
// Usage: node scripts/bench-cad-export.mjs build/native/pdesurf [example-id …]
import { spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync, statSync } from 'node:fs';
import { availableParallelism, tmpdir } from 'node:os';
import { join } from 'node:path';

const [cli, ...ids] = process.argv.slice(2);
const root = new URL('../', import.meta.url).pathname;
const dir = mkdtempSync(join(tmpdir(), 'pdesurf-bench-cad-'));
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

function run(id, ext, jobs) {
  const file = join(dir, `${id}.${ext}`);
  const args = ['export', join(root, 'examples', `${id}.json`), '-o', file, ...(jobs ? ['--jobs', String(jobs)] : [])];
  const t0 = performance.now();
  const r = spawnSync(cli, args, { encoding: 'utf8' });
  const ms = performance.now() - t0;
  if (r.status !== 0) throw new Error(`${id}.${ext}: ${r.stderr}`);
  return { ms, bytes: statSync(file).size };
}

console.log(`CAD export through the CLI, whole command [ms, median of 5], ${availableParallelism()} hardware threads`);
console.log(`${'scene'.padEnd(18)} ${'format'.padEnd(6)} ${'1 thread'.padStart(9)} ${'default'.padStart(9)} ${'ratio'.padStart(6)} ${'MB'.padStart(6)}`);
for (const id of ids.length ? ids : ['you2004-fig8d', 'bottle-solid', 'you2004-fig4a']) {
  for (const ext of ['step', 'igs']) {
    const one = [], all = [];
    let bytes = 0;
    for (let k = 0; k < 5; ++k) {
      one.push(run(id, ext, 1).ms);
      const r = run(id, ext, 0);
      all.push(r.ms), (bytes = r.bytes);
    }
    const a = median(one), b = median(all);
    console.log(`${id.padEnd(18)} ${ext.padEnd(6)} ${a.toFixed(0).padStart(9)} ${b.toFixed(0).padStart(9)} ${(a / b).toFixed(2).padStart(6)} ${(bytes / 1e6).toFixed(1).padStart(6)}`);
  }
}
rmSync(dir, { recursive: true, force: true });
