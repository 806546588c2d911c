// The exported files' names (web/export/file-names.js) and the PNG's size with its limits
// (web/export/png-size.js): pure functions, checked here without a browser.
//   node --test tests/js/export-names-sizes.test.mjs
import { describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { exportBaseName, pngFileName, slugOf } from '../../web/export/file-names.js';
import { pngSize, MAX_PNG_PIXELS } from '../../web/export/png-size.js';

describe('export file names', () => {
  it('use the example id, else a slug of the title, else "scene"', () => {
    assert.equal(exportBaseName({ exampleId: 'you2004-fig2a', title: 'whatever' }), 'you2004-fig2a');
    assert.equal(exportBaseName({ exampleId: null, title: 'Cône & plane: <b> = 1' }), 'cone-plane-b-1');
    assert.equal(exportBaseName({ exampleId: null, title: '  ***  ' }), 'scene');
    assert.equal(exportBaseName({ exampleId: null, title: 42 }), 'scene');
    assert.equal(exportBaseName({}), 'scene');
  });

  it('never name a path or a hidden file', () => {
    assert.equal(exportBaseName({ exampleId: '../../etc/passwd' }), 'etc-passwd');
    assert.equal(exportBaseName({ exampleId: '.hidden' }), 'hidden');
    assert.equal(exportBaseName({ title: '../x/.y' }), 'x-y');
    assert.ok(slugOf('a'.repeat(500)).length <= 64);
  });

  it('say the PNG scale above 1×', () => {
    assert.equal(pngFileName('f', 1), 'f.png');
    assert.equal(pngFileName('f', 2), 'f@2x.png');
    assert.equal(pngFileName('f', 4), 'f@4x.png');
    assert.equal(pngFileName('f', 8192 / 3000), 'f@2.73x.png');
  });
});

describe('PNG size', () => {
  it('is the drawing buffer times the scale when it fits', () => {
    assert.deepEqual(pngSize(675, 800, 4, 8192), { width: 2700, height: 3200, scale: 4, clamped: false, limit: null });
  });

  it('is reduced, keeping the aspect, to the GPU\'s side limit', () => {
    const s = pngSize(3000, 1000, 4, 8192);
    assert.equal(s.clamped, true);
    assert.ok(s.width <= 8192 && s.width >= 8191, s.width);
    assert.equal(s.height, Math.floor(1000 * 8192 / 3000));
    assert.match(s.limit, /8192 pixels a side/);
  });

  it('is reduced to the pixel cap', () => {
    const s = pngSize(8000, 8000, 4, 65536);
    assert.equal(s.clamped, true);
    assert.ok(s.width * s.height <= MAX_PNG_PIXELS);
    assert.equal(s.width, 8192);
    assert.match(s.limit, /8192² pixels/);
  });
});
