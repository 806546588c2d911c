// What the static server sends for a file: the precompressed sibling (FILE.br, FILE.gz, made
// by scripts/build-web.mjs) when the client accepts it and it is not older than the file;
// else, for small text files, a compressed copy made once and kept in memory; else the file.
import fs from 'node:fs';
import { Readable } from 'node:stream';
import zlib from 'node:zlib';

const COMPRESSIBLE = new Set(['.js', '.mjs', '.json', '.html', '.css', '.svg', '.wasm', '.md']);
const ON_THE_FLY_MAX = 1 << 20; // larger files are precompressed at build time or sent as they are
const memory = new Map(); // `${real}|${mtime}|${encoding}` -> Buffer

function accepted(req) {
  const header = String(req.headers['accept-encoding'] || '');
  const list = header.split(',').map((s) => s.trim().split(';')[0]);
  return ['br', 'gzip'].filter((e) => list.includes(e));
}

const SUFFIX = { br: '.br', gzip: '.gz' };

/**
 * { encoding (or null), size, open() -> readable stream } for the file at `real` with stat
 * `st` and extension `ext`.
 */
export async function encodedBody(req, real, st, ext) {
  const plain = { encoding: null, size: st.size, open: () => fs.createReadStream(real, { start: 0, end: Math.max(0, st.size - 1) }) };
  if (!COMPRESSIBLE.has(ext) || st.size === 0) return plain;
  for (const enc of accepted(req)) {
    const sibling = real + SUFFIX[enc];
    const s = await fs.promises.stat(sibling).catch(() => null);
    if (s?.isFile() && s.mtimeMs >= st.mtimeMs) {
      return { encoding: enc, size: s.size, open: () => fs.createReadStream(sibling, { start: 0, end: s.size - 1 }) };
    }
  }
  const enc = accepted(req)[0];
  if (!enc || st.size > ON_THE_FLY_MAX) return plain;
  const key = `${real}|${st.mtimeMs}|${st.size}|${enc}`;
  let body = memory.get(key);
  if (!body) {
    const bytes = await fs.promises.readFile(real);
    if (bytes.length !== st.size) return plain; // changed while read: send it plain this time
    body = enc === 'br'
      ? zlib.brotliCompressSync(bytes, { params: { [zlib.constants.BROTLI_PARAM_QUALITY]: 5 } })
      : zlib.gzipSync(bytes, { level: 6 });
    if (memory.size > 512) memory.clear();
    memory.set(key, body);
  }
  return { encoding: enc, size: body.length, open: () => Readable.from([body]) };
}
