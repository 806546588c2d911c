// Raw deflate through the platform's CompressionStream / DecompressionStream (both
// browsers and Node ≥ 20). Inflation is capped while it runs: the input is fed in
// small slices and the output counted as it is read, so a small hostile link cannot
// make the page allocate (or spend time on) more than the cap before it is refused.
import { LinkError } from './link-error.js';

// Deflate expands at most ~1032:1, so one slice inflates to at most ~0.5 MiB before
// the reader gets to count it.
const INPUT_SLICE = 512;

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

// Writes the input slice by slice, each after the previous one was taken in, so the
// stream never holds more than one slice's output ahead of the reader.
async function feed(writer, bytes) {
  try {
    for (let i = 0; i < bytes.length; i += INPUT_SLICE) {
      await writer.ready;
      await writer.write(bytes.subarray(i, i + INPUT_SLICE));
    }
    await writer.close();
  } catch {
    // The reader sees the same failure (or cancelled on purpose) and reports it.
  }
}

/**
 * Raw deflate Uint8Array -> Uint8Array of at most `maxBytes`; throws LinkError for a
 * broken stream or one that inflates past the cap (stopped as soon as it does).
 */
export async function inflateRawCapped(bytes, maxBytes) {
  const ds = new DecompressionStream('deflate-raw');
  const writer = ds.writable.getWriter();
  const reader = ds.readable.getReader();
  const feeding = feed(writer, bytes);
  const chunks = [];
  let total = 0;
  try {
    for (;;) {
      let step;
      try {
        step = await reader.read();
      } catch (err) {
        // Both cut-off and corrupted streams end up here; the platform's wording varies.
        throw new LinkError(`the link is truncated or damaged: its compressed data is broken (${err && err.message ? err.message : err})`);
      }
      if (step.done) break;
      total += step.value.byteLength;
      if (total > maxBytes) {
        await reader.cancel().catch(() => {});
        await writer.abort().catch(() => {});
        throw new LinkError(`the link inflates to more than ${maxBytes} bytes; refused`);
      }
      chunks.push(step.value);
    }
  } finally {
    await feeding;
  }
  return join(chunks, total);
}
