// Writes the seed inputs of one fuzz target into a directory, one file each (docs/testing.md):
//   node tests/fuzz/seeds.mjs scene|link OUTDIR
// scene: examples/*.json (but the two models of many patches, seconds each under the fuzz
//        build's sanitizers: tests/fixtures/models/ has small ones instead),
//        tests/fixtures/v1/*.json (version-1 scenes) and every file under tests/hostile/scenes/
//        but those only the CAD export is about.
// link:  every link of tests/links/links.json, every file under tests/hostile/links/ as it is
//        (and, when it is a links.json-style fixture file, each of its links), and a
//        version-1 link of each example (so mutations start from links that open).
// Globbed at run time: whatever exists then is used. The regression corpus
// (tests/fuzz/corpus/<target>/) is not copied here; scripts/lib/fuzz.sh reads it directly.
import { deflateRawSync } from 'node:zlib';
import { existsSync, mkdirSync, readFileSync, readdirSync, statSync, writeFileSync } from 'node:fs';
import { basename, join, relative } from 'node:path';

const root = new URL('../../', import.meta.url).pathname;
const [target, outDir] = process.argv.slice(2);
if (!['scene', 'link'].includes(target) || !outDir) {
  console.error('usage: node tests/fuzz/seeds.mjs scene|link OUTDIR');
  process.exit(2);
}
mkdirSync(outDir, { recursive: true });

function filesUnder(dir) {
  if (!existsSync(dir)) return [];
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    return statSync(path).isDirectory() ? filesUnder(path) : [path];
  });
}
const safe = (s) => s.replace(/[^A-Za-z0-9._-]+/g, '_');
let count = 0;
const write = (name, bytes) => {
  writeFileSync(join(outDir, `seed-${safe(name)}`), bytes);
  count++;
};
const examples = readdirSync(join(root, 'examples'))
  .filter((f) => f.endsWith('.json') && f !== 'index.json')
  .map((f) => join(root, 'examples', f));

if (target === 'scene') {
  const heavy = new Set(['you2004-fig8c.json', 'you2004-fig8d.json']);
  for (const f of examples) if (!heavy.has(basename(f))) write(basename(f), readFileSync(f));
  for (const f of filesUnder(join(root, 'tests/fixtures/models'))) write(`models-${basename(f)}`, readFileSync(f));
  for (const f of filesUnder(join(root, 'tests/fixtures/v1'))) write(`v1-${basename(f)}`, readFileSync(f));
  // Not the scenes that only the CAD export refuses (command "cad" in scenes.json): the fuzz
  // target never exports, and their heavy expressions made each run over 10 s under ASan.
  const manifest = join(root, 'tests/hostile/scenes.json');
  const cadOnly = new Set(existsSync(manifest) ? JSON.parse(readFileSync(manifest, 'utf8')).scenes.filter((x) => x.command === 'cad').map((x) => basename(x.file)) : []);
  for (const f of filesUnder(join(root, 'tests/hostile/scenes'))) if (!cadOnly.has(basename(f))) write(`hostile-${relative(root, f)}`, readFileSync(f));
} else {
  const fixtureLinks = (text) => {
    try {
      const doc = JSON.parse(text);
      return Array.isArray(doc?.fixtures) ? doc.fixtures.filter((x) => typeof x?.link === 'string') : [];
    } catch {
      return [];
    }
  };
  for (const x of fixtureLinks(readFileSync(join(root, 'tests/links/links.json'), 'utf8'))) write(`links-${x.name}`, x.link);
  for (const f of filesUnder(join(root, 'tests/hostile/links'))) {
    const bytes = readFileSync(f);
    write(`hostile-${relative(root, f)}`, bytes);
    for (const x of fixtureLinks(bytes.toString('utf8'))) write(`hostile-${basename(f)}-${x.name ?? 'link'}`, x.link);
  }
  for (const f of examples) {
    const state = JSON.stringify({ scene: JSON.parse(readFileSync(f, 'utf8')) });
    write(`example-${basename(f, '.json')}`, `s=1.${deflateRawSync(Buffer.from(state), { level: 9 }).toString('base64url')}`);
  }
}
console.log(`${count} ${target} seeds in ${outDir}`);
