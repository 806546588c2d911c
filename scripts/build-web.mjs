#!/usr/bin/env node
// The production page: web/ bundled and minified by esbuild (three.js tree-shaken) into
// build/web/ (served as /app/), the wasm module's files beside their build, rhino3dm's ES
// module and wasm in build/web/rhino3dm/ (the .3dm writer's, fetched on first export only),
// and every text or wasm file precompressed (FILE.br, FILE.gz) for the static server. The
// sources in web/ stay runnable as they are (/web/, no build step).
//   node scripts/build-web.mjs [--wasm-dir build/wasm] [--out build/web]
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { fileURLToPath } from 'node:url';
import * as esbuild from 'esbuild';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? path.resolve(process.argv[i + 1]) : fallback;
};
const OUT = arg('--out', path.join(ROOT, 'build', 'web'));
const WASM = arg('--wasm-dir', process.env.PDESURF_WASM_DIR || path.join(ROOT, 'build', 'wasm'));

fs.rmSync(OUT, { recursive: true, force: true });
fs.mkdirSync(OUT, { recursive: true });

// rhino3dm is not bundled (2.7 MB of wasm and its glue, loaded on first .3dm export): its two
// files are copied to rhino3dm/ beside the bundle, and web/cad/rhino3dm-url.js, which names
// the copy under node_modules/ for the sources, is swapped for one naming that copy.
const RHINO3DM_FILES = ['rhino3dm.module.min.js', 'rhino3dm.wasm'];
const rhino3dmUrl = {
  name: 'rhino3dm-url',
  setup(build) {
    build.onLoad({ filter: /[\\/]web[\\/]cad[\\/]rhino3dm-url\.js$/ }, () => ({
      contents: "export const RHINO3DM_URL = new URL('./rhino3dm/rhino3dm.module.min.js', import.meta.url).href;",
    }));
    // Open CASCADE's wasm build (the STEP reader, web/cad/occt-url.js), copied to occt/ the same way.
    build.onLoad({ filter: /[\\/]web[\\/]cad[\\/]occt-url\.js$/ }, () => ({
      contents: "export const OCCT_URL = new URL('./occt/replicad_single.js', import.meta.url).href;",
    }));
  },
};
const OCCT_FILES = ['replicad_single.js', 'replicad_single.wasm'];

// Three bundles: the page, the solver worker it starts (new URL('./solver-worker.js',
// import.meta.url) resolves beside the page's bundle), and the .3dm writer's worker
// (web/cad/export-3dm.js starts ./rhino-worker.js the same way; the STEP and IGES readers'
// occt-worker.js and iges-worker.js too). The wasm glue
// (/wasm/pdesurf.js) is imported at run time and stays a file of its own. The solver worker
// is one file, sharing no chunk with the page: a cold start's worker then evaluates after one
// request, not after a second round trip for its chunks.
const result = await esbuild.build({
  entryPoints: {
    main: path.join(ROOT, 'web', 'main.js'),
    'rhino-worker': path.join(ROOT, 'web', 'cad', 'rhino-worker.js'),
    'occt-worker': path.join(ROOT, 'web', 'cad', 'occt-worker.js'),
    'iges-worker': path.join(ROOT, 'web', 'cad', 'iges-worker.js'),
  },
  plugins: [rhino3dmUrl],
  outdir: OUT,
  bundle: true,
  format: 'esm',
  splitting: true, // what loads on first use (the link inflater) goes to a chunk of its own
  chunkNames: 'chunk-[hash]',
  minify: true,
  target: 'es2022',
  legalComments: 'linked',
  metafile: true,
  logLevel: 'warning',
});
const workerResult = await esbuild.build({
  entryPoints: { 'solver-worker': path.join(ROOT, 'web', 'solver', 'solver-worker.js') },
  outdir: OUT,
  bundle: true,
  format: 'esm',
  minify: true,
  target: 'es2022',
  legalComments: 'linked',
  metafile: true,
  logLevel: 'warning',
});

// The page: no importmap (everything is bundled). The examples are not preloaded: the worker
// fetches the one it solves ahead, and the page reads the catalogue after its first frame
// (web/main.js); a preload would hold a connection the worker's files wait for.
let html = fs.readFileSync(path.join(ROOT, 'web', 'index.html'), 'utf8');
html = html.replace(/\s*<!--[^>]*-->\s*<script type="importmap">[\s\S]*?<\/script>/, '');
if (html.includes('importmap')) throw new Error('build-web: could not take the importmap out of web/index.html');
// Chunks main.js imports statically (three.js, once other chunks loaded on first use share
// it, e.g. the exporters): preloaded with the page, not one round trip after main.js.
const mainOutput = Object.values(result.metafile.outputs).find((o) => o.entryPoint && o.entryPoint.endsWith('web/main.js'));
const preloads = (mainOutput?.imports || []).filter((i) => i.kind === 'import-statement').map((i) => `\n  <link rel="modulepreload" href="./${path.basename(i.path)}">`);
html = html.replace(/(\n\s*<\/head>)/, `${preloads.join('')}$1`);
html = html.replace('data-worker="./solver/solver-worker.js"', 'data-worker="./solver-worker.js"');
// boot.js and load-check.js inline (the static server allows them by their hashes), and the
// two stylesheets as one: fewer requests before the first frame (the page and its worker share
// six connections), and the worker starts as the page's first bytes are parsed.
function inlineScript(file, attributes = '') {
  const tag = `<script src="./${file}"${attributes}></script>`;
  if (!html.includes(tag)) throw new Error(`build-web: web/index.html has no ${tag}`);
  const code = fs.readFileSync(path.join(ROOT, 'web', file), 'utf8').replace(/^\/\/.*\n/gm, ''); // its comments
  html = html.replace(tag, () => `<script${attributes}>\n${code}</script>`);
}
inlineScript('boot.js', ' data-worker="./solver-worker.js"');
inlineScript('load-check.js');
const STYLES = '<link rel="stylesheet" href="./style.css">\n  <link rel="stylesheet" href="./panel.css">';
if (!html.includes(STYLES)) throw new Error('build-web: web/index.html does not link style.css and panel.css');
html = html.replace(STYLES, '<link rel="stylesheet" href="./style.css">');
fs.writeFileSync(path.join(OUT, 'index.html'), html);
fs.writeFileSync(path.join(OUT, 'style.css'), ['style.css', 'panel.css'].map((f) => fs.readFileSync(path.join(ROOT, 'web', f), 'utf8')).join('\n'));
const RHINO3DM = path.join(ROOT, 'node_modules', 'rhino3dm');
fs.mkdirSync(path.join(OUT, 'rhino3dm'));
for (const f of RHINO3DM_FILES) fs.copyFileSync(path.join(RHINO3DM, f), path.join(OUT, 'rhino3dm', f));
const OCCT = path.join(ROOT, 'node_modules', 'replicad-opencascadejs', 'dist');
fs.mkdirSync(path.join(OUT, 'occt'));
for (const f of OCCT_FILES) fs.copyFileSync(path.join(OCCT, f), path.join(OUT, 'occt', f));

// Precompressed siblings: brotli at its best (built once), gzip for clients without it.
// rhino3dm (fetched on the first .3dm export only) at quality 9: 11 took about 5 s of every
// build for some 10% fewer bytes of its 2.6 MB wasm.
const compress = (file, quality = 11) => {
  const bytes = fs.readFileSync(file);
  fs.writeFileSync(`${file}.br`, zlib.brotliCompressSync(bytes, { params: { [zlib.constants.BROTLI_PARAM_QUALITY]: quality, [zlib.constants.BROTLI_PARAM_SIZE_HINT]: bytes.length } }));
  fs.writeFileSync(`${file}.gz`, zlib.gzipSync(bytes, { level: 9 }));
  return { file: path.relative(ROOT, file), raw: bytes.length, br: fs.statSync(`${file}.br`).size };
};
const sizes = [];
for (const f of fs.readdirSync(OUT)) if (/\.(js|css|html)$/.test(f)) sizes.push(compress(path.join(OUT, f)));
for (const f of ['pdesurf.js', 'pdesurf.wasm']) {
  const file = path.join(WASM, f);
  if (fs.existsSync(file)) sizes.push(compress(file));
  else console.warn(`build-web: ${file} is missing (build the wasm module first)`);
}
// rhino3dm's files apart: they are not part of what the page loads.
const rhino = RHINO3DM_FILES.map((f) => compress(path.join(OUT, 'rhino3dm', f), 9));
// Open CASCADE's 23 MB at brotli quality 5 (a second here; 9 took tens of seconds for a few
// percent): fetched on the first STEP file only.
const occt = OCCT_FILES.map((f) => compress(path.join(OUT, 'occt', f), 5));
const kib = (list, key) => (list.reduce((sum, s) => sum + s[key], 0) / 1024).toFixed(0);
console.log(`build-web: ${path.relative(ROOT, OUT)}/ written; ${sizes.length} files, ${kib(sizes, 'raw')} KiB, ${kib(sizes, 'br')} KiB brotli` +
  ` (${Object.keys(result.metafile.outputs).length + Object.keys(workerResult.metafile.outputs).length} bundle outputs); rhino3dm/ on first .3dm export or opening: ${kib(rhino, 'raw')} KiB, ${kib(rhino, 'br')} KiB brotli; occt/ on first STEP opening: ${kib(occt, 'raw')} KiB, ${kib(occt, 'br')} KiB brotli`);
