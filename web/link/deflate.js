// Raw deflate: written through the platform's CompressionStream (browsers and Node ≥ 20),
// read through pako. Inflation is capped while it runs: the output is counted chunk by
// chunk, so a small hostile link cannot make the page allocate (or spend time on) more
// than the cap before it is refused.
import { Inflate } from 'pako';
import { LinkError } from './link-error.js';

async function collect(readable) {
  const chunks = [];
  let total = 0;
  const reader = readable.getReader();
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    chunks.push(value);
    total += value.byteLength;
  }
  return join(chunks, total);
}

function join(chunks, total) {
  const out = new Uint8Array(total);
  let at = 0;
  for (const c of chunks) {
    out.set(c, at);
    at += c.byteLength;
  }
  return out;
}

/** Uint8Array -> raw deflate Uint8Array. */
export async function deflateRaw(bytes) {
  const cs = new CompressionStream('deflate-raw');
  const writer = cs.writable.getWriter();
  const written = writer.write(bytes).then(() => writer.close());
  const [out] = await Promise.all([collect(cs.readable), written]);
  return out;
}

/**
 * Raw deflate Uint8Array -> Uint8Array of at most `maxBytes`; throws LinkError for a
 * broken or truncated stream, one that inflates past the cap (stopped as soon as it does),
 * or bytes after the end of the stream (a second stream or junk would make one link mean
 * two things). pako (zlib's inflate) rather than DecompressionStream, which ignores
 * trailing bytes: the same rules as the CLI's zlib (cli/link_codec.cpp).
 */
export async function inflateRawCapped(bytes, maxBytes) {
  const inflator = new Inflate({ raw: true, chunkSize: 1 << 16 });
  const chunks = [];
  let total = 0;
  const overCap = new LinkError(`the link inflates to more than ${maxBytes} bytes; refused`);
  inflator.onData = (chunk) => {
    total += chunk.byteLength;
    if (total > maxBytes) throw overCap; // stops inflate() where it is
    chunks.push(chunk.slice());
  };
  inflator.push(bytes, true);
  if (inflator.err) throw new LinkError(`the link is truncated or damaged: its compressed data is broken (${inflator.msg || inflator.err})`);
  if (!inflator.ended) throw new LinkError('the link is truncated or damaged: its compressed data is broken (it ends early)');
  const trailing = inflator.strm.avail_in;
  if (trailing > 0) throw new LinkError(`the link is damaged: ${trailing} bytes after the end of its compressed data`);
  return join(chunks, total);
}
