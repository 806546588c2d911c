// The address bar follows the page state: each request encodes { scene, grid, camera }
// into "#s=1.…" with history.replaceState (no history entry per slider step).
// Encoding is async (CompressionStream), so at most one encode runs; requests made
// meanwhile collapse into one, and the newest state wins.
import { encodeState } from '../link/link-codec.js';
import { writeLinkToHash, clearHash } from './hash.js';

export const CAMERA_REST_MS = 500; // an orbit updates the link once the view rests

/**
 * snapshot() -> { scene, grid, camera } or null (nothing to link yet), taken when a
 * request is made; onWritten(url) after each hash write; onError(err) when encoding fails
 * (a scene too large for a link, err.code 'TooLarge', first empties the hash: it must not
 * keep naming an older scene).
 */
export function createHashSync({ snapshot, onWritten, onError }) {
  let epoch = 0; // bumped by cancel(): an encode started before it must not write
  let running = null; // the encode in flight
  let pending = null; // the newest state waiting for it
  let timer = 0;

  async function encode(state, myEpoch) {
    try {
      const link = await encodeState(state);
      if (myEpoch !== epoch) return;
      writeLinkToHash(link);
      onWritten(location.href);
    } catch (err) {
      if (myEpoch !== epoch) return;
      if (err?.code === 'TooLarge') clearHash();
      onError(err);
    }
  }

  function pump() {
    if (running || !pending) return;
    const state = pending;
    pending = null;
    running = encode(state, epoch).finally(() => {
      running = null;
      pump();
    });
  }

  function request() {
    clearTimeout(timer);
    timer = 0;
    const state = snapshot();
    if (!state) return;
    pending = state;
    pump();
  }

  function requestSoon() {
    clearTimeout(timer);
    timer = setTimeout(request, CAMERA_REST_MS);
  }

  return {
    request,
    requestSoon,

    /** Another scene opens: drop waiting and in-flight work (it would write a stale hash). */
    cancel() {
      epoch++;
      pending = null;
      clearTimeout(timer);
      timer = 0;
    },

    /** Resolves once the hash holds the newest state (a resting camera included). */
    async flush() {
      if (timer) request();
      while (running) await running;
    },

    /**
     * Only a user's orbit, pan or zoom counts: fit() and setCamera() also fire "change",
     * but outside start/end; a click that moves nothing changes nothing.
     */
    watchCamera(controls) {
      let active = false;
      let moved = false;
      controls.addEventListener('start', () => {
        active = true;
        moved = false;
      });
      controls.addEventListener('change', () => {
        if (!active) return;
        moved = true;
        requestSoon();
      });
      controls.addEventListener('end', () => {
        active = false;
        if (moved) requestSoon();
      });
    },
  };
}
