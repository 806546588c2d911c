// IGES files are read here (read-iges.js), off the page's thread: a 64 MB file takes seconds to
// parse. Started on the first IGES file opened. Messages: { id, read: bytes, fileName } in;
// { id, scene } or { id, error, code } out.
import { readIges } from './read-iges.js';

self.onmessage = ({ data: { id, read, fileName } }) => {
  try {
    // IGES is ASCII: latin1 reads any byte as one character (a stray byte is not an error here).
    self.postMessage({ id, scene: readIges(new TextDecoder('latin1').decode(read), { fileName }) });
  } catch (err) {
    self.postMessage({ id, error: String(err?.message ?? err), code: err?.code ?? null });
  }
};
