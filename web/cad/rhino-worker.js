// rhino3dm runs here, not on the page: its embind glue builds its functions with new Function,
// which the page's CSP refuses. The static server sends this script a policy of its own that
// allows eval (scripts/static-server.mjs); a worker has no DOM and sees only what it is sent.
// Messages in: { id, surfaces, tolerance, title, breps, archive } (write a .3dm file) or
// { id, read: bytes, fileName } (a .3dm file as a scene, web/cad/read-3dm.js); out: { id, bytes },
// { id, scene } or { id, error, code }.
import { write3dm } from './write-3dm.js';
import { read3dm } from './read-3dm.js';

self.onmessage = async ({ data }) => {
  const { id } = data;
  try {
    if (data.read) {
      self.postMessage({ id, scene: await read3dm(data.read, { fileName: data.fileName }) });
      return;
    }
    const { surfaces, tolerance, title, breps, archive } = data;
    const bytes = await write3dm(surfaces, { tolerance, title, breps, archive });
    self.postMessage({ id, bytes }, [bytes.buffer]);
  } catch (err) {
    self.postMessage({ id, error: String(err?.message ?? err), code: err?.code ?? null });
  }
};
