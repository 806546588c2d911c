// The page's way to read an IGES file (read-iges.js in iges-worker.js): the worker starts on the
// first IGES file opened and stays for the next ones. Its URL is relative: beside this file in
// web/cad/, beside the bundle's chunks in build/web/ (scripts/build-web.mjs).
import { createWorkerClient } from './worker-client.js';

const request = createWorkerClient(() => new Worker(new URL('./iges-worker.js', import.meta.url), { type: 'module' }), 'the IGES reader');

/** An IGES file's bytes (an ArrayBuffer, handed over) as a scene, off the page's thread. */
export async function importIges(bytes, fileName) {
  return (await request({ read: bytes, fileName }, [bytes])).scene;
}
