// node tests/browser/run.mjs [node --test arguments and files]: the browser tests with one
// Chromium for all of them. It launches Debian's Chromium once (playwright's launchServer)
// and runs `node --test` with PDESURF_BROWSER_WS set; each file's startHarness() connects
// to it and opens a fresh browser context of its own (no cookies, storage or cache shared
// between files), instead of launching a Chromium per file. Without file arguments: every
// file of tests/browser/. `node --test tests/browser/FILE` still works on its own (the
// harness then launches a browser itself). scripts/test, row browser.
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { CHROMIUM, ARGS } from './harness.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
if (!args.some((a) => !a.startsWith('-'))) args.push(here);

const env = { ...process.env };
let server = null;
if (fs.existsSync(CHROMIUM)) { // else the tests report themselves skipped (harness.mjs)
  const { chromium } = await import('playwright-core');
  server = await chromium.launchServer({ executablePath: CHROMIUM, args: ARGS, headless: true });
  env.PDESURF_BROWSER_WS = server.wsEndpoint();
}
const child = spawn(process.execPath, ['--test', ...args], { stdio: 'inherit', env });
for (const sig of ['SIGINT', 'SIGTERM']) process.on(sig, () => child.kill(sig));
const code = await new Promise((resolve) => child.on('exit', (c) => resolve(c ?? 1)));
await server?.close();
process.exit(code);
