// base64url (RFC 4648 §5) without padding: the alphabet survives URLs, chats and
// mail clients unescaped. Decoding is strict so a mangled link fails here, early.
import { LinkError } from './link-error.js';

const ALPHABET = /^[A-Za-z0-9_-]*$/;

/** Uint8Array -> base64url text, no '=' padding. */
export function encodeBase64url(bytes) {
  let binary = '';
  // fromCharCode takes arguments: go in slices so a large scene stays under the call limit.
  for (let i = 0; i < bytes.length; i += 0x8000) {
    binary += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
  }
  return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

/** base64url text (no padding) -> Uint8Array; throws LinkError on anything else. */
export function decodeBase64url(text) {
  if (!ALPHABET.test(text)) {
    const bad = text.match(/[^A-Za-z0-9_-]/)[0];
    throw new LinkError(`the link is damaged: ${JSON.stringify(bad)} is not a base64url character`);
  }
  // Four characters carry three bytes; a lone trailing character carries none.
  if (text.length % 4 === 1) throw new LinkError('the link is damaged: its base64url text has an impossible length (truncated?)');
  const padded = text.replace(/-/g, '+').replace(/_/g, '/') + '='.repeat((4 - (text.length % 4)) % 4);
  let binary;
  try {
    binary = atob(padded);
  } catch {
    throw new LinkError('the link is damaged: its base64url text does not decode');
  }
  const out = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) out[i] = binary.charCodeAt(i);
  return out;
}
