#!/usr/bin/env node
// Writes tests/hostile/expressions/*.json (scenes), *.txt (the same as share links) and
// expressions.json: surfaces whose expressions explode when differentiated as trees (issue 17,
// item 2), each met by a blend by reference. Each is solved ("ok") or refused with TooLarge,
// the same by the CLI and the wasm module, within the time and memory of docs/limits.md
// (tests/cli/hostile-expressions.test.mjs, tests/js/hostile-expressions.test.mjs).
// Deterministic; run again after adding a case.   node tests/hostile/make-expressions.mjs
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { fileURLToPath } from 'node:url';

const HERE = path.dirname(fileURLToPath(import.meta.url));
const OUT = path.join(HERE, 'expressions');
const link = (state) => `s=1.${zlib.deflateRawSync(Buffer.from(JSON.stringify(state)), { level: 9 }).toString('base64url')}`;

const times = (f, n) => Array.from({ length: n }, f);
const product = (n) => times(() => 't', n).join('*');
const curve = (tau = '0.5 + 0.1*sin(v)') => ({ t: tau, replaces: 't0' });

// A plane annulus (its inner border at radius 2.2 is met at t0) and the hostile surface "bump",
// a ring from radius 1 to 2 whose height z is the expression under test.
const plane = { name: 'plane', kind: 'surface', v_range: [0, '2*pi'], t_range: [0, 1], x: '(2.2 + t)*cos(v)', y: '(2.2 + t)*sin(v)', z: '0' };
const bump = (z) => ({ name: 'bump', kind: 'surface', v_range: [0, '2*pi'], t_range: [0, 1], x: '(1 + t)*cos(v)', y: '(1 + t)*sin(v)', z });
const blend = (name, at, continuity) => ({
  name, kind: 'pde', v_range: [0, '2*pi'],
  ends: { u0: { surface: 'plane', at: 't0', continuity: 'tangency' }, u1: { surface: 'bump', at, continuity } },
});
const scene = (title, patches) => ({ format: 'pdesurf-scene', version: 3, title, patches });
const one = (title, z, at, continuity = 'curvature') => scene(title, [blend('blend', at, continuity), plane, bump(z)]);

// tau near the expression limit (1000 characters): a sum of small waves.
let tau = '0.5';
for (let k = 1; tau.length < 960; k++) tau += ` + 0.001*sin(${k}*v)`;

// name, scene, verdict ("ok" or "TooLarge"), why
const cases = [
  ['product-300-curve', one('z = 1 + t*t*...*t (300 factors), met along a curve, curvature', `1 + ${product(300)}`, curve()), 'ok',
    'was minutes and GBs (or bad_alloc): S_t and S_tt of a 300-factor product as trees'],
  ['product-300-iso', one('z = 1 + t*t*...*t (300 factors), met at t1, curvature', `1 + ${product(300)}`, 't1'), 'ok',
    'was accepted after 20 s'],
  ['product-450-curve', one('z = t*...*t (450 factors), along a curve', product(450), curve()), 'ok',
    'the longest product that fits the expression limit'],
  ['powers-product', one('z = t^2*t^3*...*t^120, along a curve', times((_, i) => `t^${i + 2}`, 120).join('*').slice(0, 990).replace(/\*[^*]*$/, ''), curve()), 'ok',
    'a product of over a hundred distinct powers'],
  ['nested-functions', one('z = sin(cos(sin(...(t)...))), 30 levels, along a curve', 'sin(cos('.repeat(15) + 't' + '))'.repeat(15), curve()), 'ok',
    'each chain rule multiplies the tree; the graph grows by a few nodes per level'],
  ['tower', one('z = (1 + 0.01*t)^(1 + 0.01*t)^... (30 levels), along a curve', times(() => "(1 + 0.01*t)", 30).join('^'), curve()), 'ok',
    'a power tower: a^b differentiates through exp(b log a) at every level'],
  ['tau-near-limit', one('tau(v) of 960 characters into a 100-factor product', `1 + ${product(100)}`, curve(tau)), 'ok',
    'every t of S, S_t and S_tt replaced by a tau near the expression limit'],
  ['many-blends', scene('20 blends at t1 of one 300-factor surface, curvature, each over a twentieth of v',
    [...times((_, k) => ({ ...blend(`blend${k}`, 't1', 'curvature'), v_range: [`${k}*pi/10`, `${k + 1}*pi/10`] }), 20), plane, bump(`1 + ${product(300)}`)]), 'ok',
    'each blend on the same surface adds its derivation to the scene\'s budget'],
  ['31-surfaces-on-curves', scene('31 surfaces of 450 factors, each met along a curve with curvature', times((_, k) => [
    { ...blend(`blend${k}`, curve(), 'curvature'), ends: { u0: { surface: 'plane', at: 't0', continuity: 'tangency' }, u1: { surface: `bump${k}`, at: curve(), continuity: 'curvature' } } },
    { ...bump(product(450)), name: `bump${k}` }], 31).flat().concat([plane])), 'TooLarge',
    'each alone is solved; their derivations together are over the scene\'s budget'],
  ['trimmed-power-60', one('z = (v+1)*t*...*t (60 factors), trimmed along a curve, tangency', `(v + 1)*${product(60)}`, curve(), 'tangency'), 'ok',
    'was 21 s to draw: the trimmed surface\'s pointwise derivatives as trees'],
  ['trimmed-power-60-g2', one('the same with curvature', `(v + 1)*${product(60)}`, curve()), 'ok',
    'was 163 s with curvature'],
];

fs.mkdirSync(OUT, { recursive: true });
const manifest = { format: 'pdesurf-hostile-expressions', version: 1, grid: 64, cases: [] };
for (const [name, s, verdict, why] of cases) {
  for (const p of s.patches) for (const k of ['x', 'y', 'z']) if (p[k] && p[k].length > 1000) throw new Error(`${name}: ${k} is over 1000 characters`);
  fs.writeFileSync(path.join(OUT, `${name}.json`), JSON.stringify(s, null, 1) + '\n');
  fs.writeFileSync(path.join(OUT, `${name}.txt`), link({ scene: s }));
  manifest.cases.push({ name, scene: `expressions/${name}.json`, link: `expressions/${name}.txt`, verdict, why });
}
fs.writeFileSync(path.join(HERE, 'expressions.json'), JSON.stringify(manifest, null, 2) + '\n');
console.log(`${cases.length} cases written`);
