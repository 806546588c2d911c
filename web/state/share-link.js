// "Copy link": encode the page state, put it in the address bar (no history entry,
// no hashchange) and on the clipboard when the browser lets us. The clipboard is
// optional: it is missing on plain http, denied without focus, absent in headless
// tests, so its failure only changes the message.
import { encodeState } from '../link/link-codec.js';
import { writeLinkToHash, urlWithHash } from './hash.js';

// Past this, chat and mail tools and some servers start cutting URLs.
export const LONG_LINK = 8000;
const CLIPBOARD_WAIT_MS = 1500; // a permission prompt nobody answers must not hang the button

function within(promise, ms) {
  return Promise.race([promise, new Promise((_, reject) => setTimeout(() => reject(new Error('timeout')), ms))]);
}

/** state: { scene, grid, camera } -> { link, url, chars, copied, long } */
export async function shareLink(state, clipboard = globalThis.navigator?.clipboard) {
  const link = await encodeState(state);
  writeLinkToHash(link);
  const url = urlWithHash(link);
  let copied = false;
  if (clipboard && typeof clipboard.writeText === 'function') {
    try {
      await within(clipboard.writeText(url), CLIPBOARD_WAIT_MS);
      copied = true;
    } catch {
      copied = false;
    }
  }
  return { link, url, chars: url.length, copied, long: url.length > LONG_LINK };
}

/** The status-line sentence for a shareLink result. */
export function shareMessage({ chars, copied, long }) {
  const where = copied ? 'link copied to the clipboard and shown in the address bar' : 'link in the address bar (copy it from there)';
  const warning = long ? `: over ${LONG_LINK}, which some tools cut` : '';
  return `${where}, ${chars} characters${warning}`;
}
