// The page's OBJ export (web/export/mesh-export.js) writes every patch name on one "o" line:
// no character a line-splitting reader breaks at (C0, C1 with NEL U+0085, U+2028, U+2029)
// may reach the file, whatever the name (the scene reader refuses them; this is the export's
// own guard).   node --test tests/js/obj-export-names.test.mjs
import { describe, it } from 'node:test';
import assert from 'node:assert/strict';
import * as THREE from 'three';
import { exportObj } from '../../web/export/mesh-export.js';

function triangle(name) {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute([0, 0, 0, 1, 0, 0, 0, 1, 0], 3));
  g.setAttribute('normal', new THREE.Float32BufferAttribute([0, 0, 1, 0, 0, 1, 0, 0, 1], 3));
  g.setAttribute('uv', new THREE.Float32BufferAttribute([0, 0, 1, 0, 0, 1], 2));
  g.setIndex([0, 1, 2]);
  const m = new THREE.Mesh(g, new THREE.MeshStandardMaterial({ color: 0x888888 }));
  m.name = name;
  return m;
}

describe('OBJ export', () => {
  it('writes no line-breaking or control character of a patch name', async () => {
    const group = new THREE.Group();
    const breaks = ['\n', '\r', '\u0085', '\u2028', '\u2029', '\u0080', '\u009f', '\u000b', '\u007f'];
    for (const [k, c] of breaks.entries()) group.add(triangle(`p${k}${c}v 9 9 9`));
    const text = await exportObj(group);
    assert.doesNotMatch(text, /[\u0000-\u0009\u000b-\u001f\u007f-\u009f\u2028\u2029]/);
    // Split as the most permissive reader would: still only the three real vertices per patch.
    const lines = text.split(/\r\n|[\n\r\u000b\u000c\u0085\u2028\u2029]/);
    assert.equal(lines.filter((l) => l.startsWith('v ')).length, 3 * breaks.length);
    assert.equal(lines.filter((l) => l.startsWith('o ')).length, breaks.length);
  });
});
