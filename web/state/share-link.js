// "Copy link": the address bar already holds the page state (web/state/hash-sync.js),
// so the button only copies it. The clipboard is optional: it is missing on plain
// http, denied without focus, absent in headless tests, so its failure only changes
// the message.

// Past this, chat and mail tools and some servers start cutting URLs.
export const LONG_LINK = 8000;
const CLIPBOARD_WAIT_MS = 1500; // a permission prompt nobody answers must not hang the button

function within(promise, ms) {
  return Promise.race([promise, new Promise((_, reject) => setTimeout(() => reject(new Error('timeout')), ms))]);
}

/** url -> { url, chars, copied, long } */
export async function copyLink(url, clipboard = globalThis.navigator?.clipboard) {
  let copied = false;
  if (clipboard && typeof clipboard.writeText === 'function') {
    try {
      await within(clipboard.writeText(url), CLIPBOARD_WAIT_MS);
      copied = true;
    } catch {
      copied = false;
    }
  }
  return { url, chars: url.length, copied, long: url.length > LONG_LINK };
}

/** The warning for a link of `chars` characters, or '' when it is short enough. */
export function longLinkWarning(chars) {
  return chars > LONG_LINK ? `the link has ${chars} characters, over ${LONG_LINK}, which some tools cut` : '';
}

/** The status-line sentence for a copyLink result. */
export function shareMessage({ chars, copied, long }) {
  const where = copied ? 'link copied to the clipboard' : 'the link is in the address bar (copy it from there)';
  const warning = long ? `: over ${LONG_LINK}, which some tools cut` : '';
  return `${where}, ${chars} characters${warning}`;
}
