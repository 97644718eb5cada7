// The WebSocket door as a browser meets it, in headless Chromium: a page served from this machine
// (as the demo is) gets the hello from `hal serve --sim --ws-port` without a token; a page from
// another site (evil.example, resolved to 127.0.0.1 by Chromium's host rules, so the test needs no
// network) is refused, also through a DNS-rebound name; `--allow-origin` lets that site in.
import { createServer } from 'node:http';
import type { Server } from 'node:http';
import type { AddressInfo } from 'node:net';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { chromium } from 'playwright-core';
import type { BrowserContext, Page } from 'playwright-core';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import { requireChromium } from '../e2e/chromium.js';
import { startServe, stopAllServes, untilMatches } from './serve-command.js';

let pages: Server;
let pagePort: number;
let context: BrowserContext;
let page: Page;
let profile: string;

beforeAll(async () => {
  // one blank page, whatever the name it is reached by
  pages = createServer((_req, res) => {
    res.writeHead(200, { 'content-type': 'text/html' }).end('<!doctype html><title>page</title>');
  });
  await new Promise<void>((resolve) => pages.listen(0, '127.0.0.1', resolve));
  pagePort = (pages.address() as AddressInfo).port;
  profile = mkdtempSync(join(tmpdir(), 'door-profile-'));
  context = await chromium.launchPersistentContext(profile, {
    executablePath: requireChromium(),
    headless: true,
    args: [
      '--headless',
      '--no-sandbox',
      '--disable-gpu',
      '--disable-background-networking',
      '--no-first-run',
      '--host-resolver-rules=MAP evil.example 127.0.0.1',
    ],
  });
  page = context.pages()[0] ?? (await context.newPage());
}, 60_000);

afterEach(stopAllServes);

afterAll(async () => {
  await context?.close();
  rmSync(profile, { recursive: true, force: true });
  await new Promise<void>((resolve) => pages?.close(() => resolve()));
});

/**
 * Opens `pageUrl` and, from it, a WebSocket to `wsUrl`, as any page's script can: resolves with
 * the schema of the server's first message, or `closed CODE` when the socket closed without one.
 */
async function connectFrom(pageUrl: string, wsUrl: string): Promise<string> {
  await page.goto(pageUrl, { timeout: 15_000 });
  return page.evaluate(
    (url) =>
      new Promise<string>((resolve) => {
        const socket = new WebSocket(url);
        const timer = setTimeout(() => resolve('no answer within 10000 ms'), 10_000);
        socket.onmessage = (event) => {
          clearTimeout(timer);
          resolve((JSON.parse(String(event.data)) as { schema: string }).schema);
          socket.close();
        };
        socket.onclose = (event) => {
          clearTimeout(timer);
          resolve(`closed ${event.code}`);
        };
      }),
    wsUrl,
  );
}

describe('hal serve --ws-port without a token, from pages in Chromium', () => {
  it("lets in a page served from this machine, and refuses another site's page and a rebound name", async () => {
    let stderr = '';
    const url = await startServe(['--sim'], {}, { onStderr: (text) => (stderr += text) });
    const port = new URL(url).port;
    for (const local of [`http://localhost:${pagePort}/`, `http://127.0.0.1:${pagePort}/`]) {
      expect(await connectFrom(local, url), local).toBe('hal.remote.hello');
    }
    expect(await connectFrom(`http://evil.example:${pagePort}/`, url)).toBe('closed 1006');
    await untilMatches(() => stderr, /HTTP 403\): Origin "http:\/\/evil\.example:\d+"/);
    // the page of the rebound name, talking to the server through that name
    expect(await connectFrom(`http://evil.example:${pagePort}/`, `ws://evil.example:${port}`)).toBe(
      'closed 1006',
    );
    await untilMatches(() => stderr, /HTTP 403\): Host "evil\.example:\d+" is not a loopback name/);
  });

  it('lets in the site named by --allow-origin', async () => {
    const site = `http://evil.example:${pagePort}`;
    const url = await startServe(['--sim', '--allow-origin', site]);
    expect(await connectFrom(`${site}/`, url)).toBe('hal.remote.hello');
  });
});
