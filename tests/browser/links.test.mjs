// Shareable links in the page: "copy link" round trip into a fresh page (same
// surfaces, parameter, grid and camera), the stored links of tests/links/ (hostile
// ones show their message and the default example is drawn), markup in a link stays
// text, a link's scene that does not solve, a pasted link, and the long-link warning.
//   node --test tests/browser/
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { skip, startHarness, REPO, exampleIndex, hooks, solvedAfter, shoot, viewStats, sameChecksum } from './harness.mjs';
import { encodeState } from '../../web/link/link-codec.js';

const FIXTURES = JSON.parse(fs.readFileSync(path.join(REPO, 'tests', 'links', 'links.json'), 'utf8')).fixtures;
const fixture = (name) => FIXTURES.find((f) => f.name === name);
const hashOf = (link) => (link.includes('#') ? link.slice(link.indexOf('#')) : `#${link}`);
const scene = (id) => JSON.parse(fs.readFileSync(path.join(REPO, 'examples', `${id}.json`), 'utf8'));
const near = (a, b) => a.every((x, i) => Math.abs(x - b[i]) <= 1e-6 * Math.max(1, Math.abs(b[i])));

describe('shared links', { skip }, () => {
  let h;
  before(async () => {
    h = await startHarness();
  });
  after(async () => {
    await h?.close();
  });

  it('copy link carries a changed parameter, the grid and the view into a fresh page', async () => {
    const page = await h.open('/web/#example=you2004-fig2a');
    let now = await hooks(page);
    await page.locator('#panel [data-param="r0"] input').fill('2.2');
    now = await solvedAfter(page, now.solveCount);
    await page.locator('#panel .lil-gui:has(> .children [data-grid]) > .title').click(); // the Grid folder starts closed
    await page.locator('#panel [data-grid="nu"] input').fill('48');
    now = await solvedAfter(page, now.solveCount);
    // Orbit the view so the camera in the link is not the fitted one.
    const canvas = await page.locator('#viewport canvas').boundingBox();
    await page.mouse.move(canvas.x + canvas.width / 2, canvas.y + canvas.height / 2);
    await page.mouse.down();
    await page.mouse.move(canvas.x + canvas.width / 2 + 120, canvas.y + canvas.height / 2 + 40, { steps: 6 });
    await page.mouse.up();
    assert.equal(now.lastError, null);

    await page.locator('#panel [data-share="copy"] button').click();
    await page.waitForFunction(() => window.__pdesurf.lastLink, null, { timeout: 10_000 });
    const source = await hooks(page);
    assert.equal(source.lastLink, page.url(), 'the address bar does not hold the link');
    assert.match(new URL(page.url()).hash, /^#s=1\.[A-Za-z0-9_-]+$/);
    const chars = source.lastLink.length;
    assert.equal(await page.locator('#panel [data-share="length"] input').inputValue(), `${chars} characters`);
    assert.match(await page.locator('#status').textContent(), new RegExp(`${chars} characters`));
    const sourceShot = await shoot(page, 'link-source.png');

    const opened = await h.open(source.lastLink);
    const got = await hooks(opened);
    assert.equal(got.lastError, null, got.lastError);
    assert.equal(got.exampleId, null);
    assert.ok(sameChecksum(got.checksum, source.checksum), `checksum ${got.checksum}, expected ${source.checksum}`);
    assert.equal(got.vertexCount, source.vertexCount);
    assert.equal(await opened.locator('#panel [data-param="r0"] input').inputValue(), '2.2');
    assert.equal(await opened.locator('#panel [data-grid="nu"] input').inputValue(), '48');
    assert.ok(near(got.camera.position, source.camera.position) && near(got.camera.target, source.camera.target),
      `camera ${JSON.stringify(got.camera)}, expected ${JSON.stringify(source.camera)}`);
    assert.match(await opened.locator('#scene-title').textContent(), /\(shared link\)$/);
    const openedShot = await shoot(opened, 'link-opened.png');
    const [a, b] = [await viewStats(page, sourceShot), await viewStats(opened, openedShot)];
    assert.ok(Math.abs(a.fraction - b.fraction) < 0.01, `the views differ: ${JSON.stringify([a, b])}`);
    await page.close();
    await opened.close();
  });

  for (const name of ['bomb', 'unknown-version', 'truncated', 'bad-base64', 'no-scene']) {
    it(`stored link "${name}": says what is wrong and draws the default example`, async () => {
      const f = fixture(name);
      const t0 = Date.now();
      const page = await h.open(`/web/${hashOf(f.link)}`);
      const got = await hooks(page);
      assert.ok(Date.now() - t0 < 15_000, 'opening took too long');
      assert.equal(got.lastError, null);
      assert.equal(got.exampleId, exampleIndex()[0].id);
      assert.ok(got.notice && got.notice.includes(f.error), `notice: ${got.notice}`);
      const status = page.locator('#status');
      assert.ok((await status.textContent()).includes(f.error));
      assert.match(await status.getAttribute('class'), /error/);
      const img = await shoot(page, `link-${name}.png`);
      assert.ok((await viewStats(page, img)).fraction > 0.03, 'the default example is not drawn');
      await page.close();
    });
  }

  it('opens stored good links; their strings stay text', async () => {
    for (const name of ['v1-you2004-fig2a', 'v1-link-v2-scene-you2004-fig3d', 'v1-full-url-modified']) {
      const f = fixture(name);
      const page = await h.open(`/web/${hashOf(f.link)}`);
      const got = await hooks(page);
      assert.equal(got.lastError, null, `${name}: ${got.lastError}`);
      assert.equal(got.notice, null);
      assert.equal(await page.locator('#scene-title').textContent(), `${f.expect.title} (shared link)`);
      for (const [param, value] of Object.entries(f.expect.parameters)) {
        assert.equal(Number(await page.locator(`#panel [data-param="${param}"] input`).inputValue()), value, `${name}: ${param}`);
      }
      if (f.expect.camera) assert.ok(near(got.camera.position, f.expect.camera.position), `${name}: camera`);
      assert.equal(await page.evaluate(() => document.querySelectorAll('#title-bar *').length), 2, 'markup in the title');
      // Version-1 scenes have term arrays, not expressions: no function fields.
      const v2 = name.includes('v2-scene');
      assert.equal((await page.locator('#panel [data-expr]').count()) > 0, v2, `${name}: function fields`);
      if (name === 'v1-full-url-modified') await shoot(page, 'link-markup-title.png');
      await page.close();
    }
  });

  it('a link whose scene does not solve says so and draws the default example', async () => {
    const broken = scene('you2004-fig2a');
    broken.patches[0].boundary.x.u0[0] = 'r0*cso(v)';
    const page = await h.open(`/web/#${await encodeState({ scene: broken })}`);
    const got = await hooks(page);
    assert.equal(got.exampleId, exampleIndex()[0].id);
    assert.match(got.notice, /cannot open the link: .*unknown function 'cso'/);
    assert.ok(got.checksum > 0);
    await page.close();
  });

  it('a link pasted into the address bar of an open page opens it', async () => {
    const page = await h.open('/web/#example=you2004-fig2a');
    const before = await hooks(page);
    const f = fixture('v1-link-v2-scene-you2004-fig3d');
    await page.evaluate((hash) => { location.hash = hash; }, hashOf(f.link));
    await page.waitForFunction(() => window.__pdesurf.exampleId === null, null, { timeout: 20_000 });
    const now = await solvedAfter(page, before.solveCount);
    assert.equal(now.lastError, null);
    assert.notEqual(now.checksum, before.checksum);
    await page.close();
  });

  it('warns when a link is longer than 8000 characters', async () => {
    const big = scene('you2004-fig2a');
    // Incompressible text, so the link stays long after deflate; the scene format caps a
    // description at 2000 characters and a label at 200, so spread it over unused parameters.
    let x = 12345;
    const noise = (n) => Array.from({ length: n }, () => String.fromCharCode(33 + ((x = (x * 1103515245 + 12345) >>> 0) % 90))).join('');
    big.description = noise(1900);
    for (let i = 0; i < 40; i++) big.parameters[`q${i}`] = { value: 0, min: -1, max: 1, label: noise(190) };
    const page = await h.open(`/web/#${await encodeState({ scene: big })}`);
    assert.equal((await hooks(page)).notice, null);
    // Shown live, before any copy.
    assert.match(await page.locator('#panel [data-share="length"] input').inputValue(), /> 8000/);
    assert.match(await page.locator('#status').textContent(), /over 8000/);
    await shoot(page, 'link-long-live.png');
    await page.locator('#panel [data-share="copy"] button').click();
    await page.waitForFunction(() => window.__pdesurf.lastLink, null, { timeout: 10_000 });
    const chars = (await hooks(page)).lastLink.length;
    assert.ok(chars > 8000, `only ${chars} characters`);
    assert.match(await page.locator('#status').getAttribute('class'), /warn/);
    assert.match(await page.locator('#status').textContent(), /over 8000/);
    assert.match(await page.locator('#panel [data-share="length"] input').inputValue(), /> 8000/);
    await shoot(page, 'link-long.png');
    await page.close();
  });

  it('logged no console error, page error or failed request', () => {
    assert.deepEqual(h.problems, []);
  });
});
