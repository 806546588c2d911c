// JSON.parse with the rules of the core's reader (cpp/scene/json_read.cpp, docs/limits.md):
// nesting at most MAX_JSON_DEPTH levels, checked by a scan before anything is built, and no
// object with the same key twice (JSON.parse keeps the last; refusing keeps the page and
// the CLI from reading one text two ways). Shared by links (parseStrictJson: LinkError in a
// link's words) and scene files (parseJsonText: JsonTextError with the core's error code).
import { LinkError } from './link-error.js';

export const MAX_JSON_DEPTH = 32;

/** A text the strict rules refuse; code is the core's (TooLarge, ParseError), kind says which rule. */
export class JsonTextError extends Error {
  constructor(kind, code, message) {
    super(message);
    this.name = 'JsonTextError';
    this.kind = kind; // 'depth' | 'syntax' | 'duplicate'
    this.code = code;
  }
}

function checkDepth(text) {
  let depth = 0;
  let inString = false;
  for (let i = 0; i < text.length; i++) {
    const c = text.charCodeAt(i);
    if (inString) {
      if (c === 0x5c) i++; // backslash: skip the escaped character
      else if (c === 0x22) inString = false;
    } else if (c === 0x22) {
      inString = true;
    } else if (c === 0x7b || c === 0x5b) {
      if (++depth > MAX_JSON_DEPTH) throw new JsonTextError('depth', 'TooLarge', `nested deeper than ${MAX_JSON_DEPTH} levels`);
    } else if (c === 0x7d || c === 0x5d) {
      depth--;
    }
  }
}

// Keys of every object, compared after unescaping ("a" and "\u0061" are the same key). Runs
// on text JSON.parse accepted, so the scan can be simple.
function checkDuplicateKeys(text) {
  const stack = []; // per open container: a Set of keys for an object, null for an array
  let expectKey = false;
  for (let i = 0; i < text.length; i++) {
    const c = text[i];
    if (c === '"') {
      let j = i + 1;
      while (text[j] !== '"') j += text[j] === '\\' ? 2 : 1;
      const top = stack[stack.length - 1];
      if (expectKey && top) {
        const key = JSON.parse(text.slice(i, j + 1));
        if (top.has(key)) throw new JsonTextError('duplicate', 'ParseError', `the key ${JSON.stringify(key.slice(0, 64))} appears twice in one object`);
        top.add(key);
      }
      expectKey = false;
      i = j;
    } else if (c === '{') {
      stack.push(new Set());
      expectKey = true;
    } else if (c === '[') {
      stack.push(null);
    } else if (c === '}' || c === ']') {
      stack.pop();
    } else if (c === ',') {
      expectKey = stack[stack.length - 1] != null;
    }
  }
}

/** JSON text -> value; throws JsonTextError when too deep, malformed, or a key repeats. */
export function parseJsonText(text) {
  checkDepth(text);
  let value;
  try {
    value = JSON.parse(text);
  } catch (err) {
    throw new JsonTextError('syntax', 'ParseError', `not JSON (${err.message})`);
  }
  checkDuplicateKeys(text);
  return value;
}

const LINK_WORDS = {
  depth: (m) => `the link's content is ${m}`,
  syntax: (m) => `the link is damaged: its content is ${m}`,
  duplicate: (m) => `the link is damaged: ${m}`,
};

/** JSON text -> value; throws LinkError when too deep, malformed, or a key repeats. */
export function parseStrictJson(text) {
  try {
    return parseJsonText(text);
  } catch (err) {
    if (err instanceof JsonTextError) throw new LinkError(LINK_WORDS[err.kind](err.message));
    throw err;
  }
}
