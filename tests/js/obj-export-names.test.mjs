// The page's OBJ export (web/export/mesh-export.js) writes every body's name on one "o" line:
// no character a line-splitting reader breaks at (C0, C1 with NEL U+0085, U+2028, U+2029)
// may reach the file, whatever the name (the scene reader refuses them; this is the export's
// own guard). A body of one patch is named after it.   node --test tests/js/obj-export-names.test.mjs
import { describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { exportObj } from '../../web/export/mesh-export.js';

// One triangle per patch, each patch a body of its own (a model mesh as the worker sends it).
function model(names) {
  const positions = [], normals = [], parts = [];
  names.forEach((name, k) => {
    positions.push(0, 0, k, 1, 0, k, 0, 1, k);
    normals.push(0, 0, 1, 0, 0, 1, 0, 0, 1);
    parts.push({ name, body: k, indices: new Uint32Array([3 * k, 3 * k + 1, 3 * k + 2]) });
  });
  return { positions: new Float32Array(positions), normals: new Float32Array(normals), parts };
}

describe('OBJ export', () => {
  it('writes no line-breaking or control character of a patch name', async () => {
    const breaks = ['\n', '\r', '\u0085', '\u2028', '\u2029', '\u0080', '\u009f', '\u000b', '\u007f'];
    const text = await exportObj(model(breaks.map((c, k) => `p${k}${c}v 9 9 9`)));
    assert.doesNotMatch(text, /[\u0000-\u0009\u000b-\u001f\u007f-\u009f\u2028\u2029]/);
    // Split as the most permissive reader would: still only the three real vertices per patch.
    const lines = text.split(/\r\n|[\n\r\u000b\u000c\u0085\u2028\u2029]/);
    assert.equal(lines.filter((l) => l.startsWith('v ')).length, 3 * breaks.length);
    assert.equal(lines.filter((l) => l.startsWith('o ')).length, breaks.length);
  });
});
