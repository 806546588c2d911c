// Shareable links: "s=<link version>.<payload>" in the URL hash. One decoder per
// link version stays in DECODERS for good, so every link ever shared keeps opening;
// new links are always written in the latest version.
import { LinkError } from './link-error.js';
import { encodeV1, decodeV1 } from './link-v1.js';

export { LinkError };

export const LINK_VERSION = 1;
const ENCODERS = { 1: encodeV1 };
const DECODERS = { 1: decodeV1 };

// Way above any valid link (1 MiB of JSON deflates to less than this) and far below
// what would hurt: longer text is refused before any decoding work.
const MAX_LINK_CHARS = 2 << 20;

/** The page state { scene, grid?, camera? } -> "s=1.<base64url>". */
export async function encodeState(state) {
  return `s=${LINK_VERSION}.${await ENCODERS[LINK_VERSION](state)}`;
}

/** The "s=…" value out of a full URL, a "#…" hash or the bare fragment. */
function stateField(text) {
  if (typeof text !== 'string') throw new LinkError('the link is not text');
  if (text.length > MAX_LINK_CHARS) throw new LinkError(`the link is too long (${text.length} characters)`);
  const hash = text.includes('#') ? text.slice(text.indexOf('#') + 1) : text;
  // Chats and mail wrap long links: whitespace is never part of one. ASCII whitespace only,
  // as the CLI (cli/link_codec.cpp) drops.
  const parts = hash.replace(/[ \t\n\r\f\v]+/g, '').split('&');
  const field = parts.find((p) => p.startsWith('s='));
  if (field === undefined) throw new LinkError('the link holds no page state ("s=…")');
  let value = field.slice(2);
  // Some tools percent-encode what they copy; base64url itself never contains '%'. The CLI
  // decodes the same way (cli/link_codec.cpp).
  if (value.includes('%')) {
    try {
      value = decodeURIComponent(value);
    } catch {
      throw new LinkError('the link is damaged: bad percent-encoding');
    }
  }
  return value;
}

/** A link (URL, "#…" or "s=…") -> { scene, grid?, camera? }; throws LinkError. */
export async function decodeFragment(text) {
  const value = stateField(text);
  // The version is written without leading zeros: "01" is not "1" (nor to the CLI).
  const m = /^(0|[1-9][0-9]{0,5})\.(.*)$/s.exec(value);
  if (!m) throw new LinkError('the link is damaged: expected "s=<version>.<data>"');
  const version = Number(m[1]);
  const decode = Object.hasOwn(DECODERS, version) ? DECODERS[version] : null;
  if (!decode) {
    const known = Object.keys(DECODERS).join(', ');
    throw new LinkError(`unknown link version ${version} (this page reads version ${known}); a newer page may open it`);
  }
  if (m[2] === '') throw new LinkError('the link is damaged: it carries no data');
  return decode(m[2]);
}
