// The examples of packages/nats/README.md and docs/nats.md, run as written against a real
// nats-server (only the server address changes), so they cannot rot.
import { readFileSync } from 'node:fs';
import * as nats from '@hal/nats';
import * as simulation from '@hal/simulation';
import * as types from '@hal/types';
import { fencedBlocks, runDocExample } from '@hal/types/testing';
import type { ExampleModules } from '@hal/types/testing';
import * as transport from '@nats-io/transport-node';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startNatsServer, stopAllNatsServers } from './nats-server.js';
import type { NatsServer } from './nats-server.js';

let server: NatsServer;
let secured: NatsServer;
beforeAll(async () => {
  server = await startNatsServer();
  secured = await startNatsServer({ auth: { user: 'fleet-ops', password: 'the-right-one' } });
}, 20_000);
afterAll(stopAllNatsServers);

const blocks = (path: string) =>
  fencedBlocks(readFileSync(new URL(path, import.meta.url), 'utf8'), 'ts');

const MODULES: ExampleModules = {
  '@hal/nats': nats,
  '@hal/simulation': simulation,
  '@hal/types': types,
  '@nats-io/transport-node': transport,
};

/** Runs a block against this test's servers, console.log routed to `log`. */
async function run(block: string, log: (...values: unknown[]) => void): Promise<void> {
  const url = block.includes('user:') ? secured.url : server.url;
  const code = block.replaceAll('nats://127.0.0.1:4222', url).replaceAll('console.log(', 'log(');
  await runDocExample(code, MODULES, { log });
}

describe('the package README example', () => {
  it(
    'drives a simulated robot through NATS and prints the result',
    { timeout: 20_000 },
    async () => {
      const [example] = blocks('../../packages/nats/README.md');
      const lines: unknown[][] = [];
      await run(example ?? '', (...values) => lines.push(values));
      expect(lines).toHaveLength(1);
      expect(lines[0]?.[0]).toBe(true);
      expect(lines[0]?.[1]).toBe('simulation');
      expect(lines[0]?.[2]).toBeCloseTo(0.1, 3);
    },
  );
});

describe('the docs/nats.md examples', () => {
  it(
    'run as written, each printing the text the docs show after it',
    { timeout: 30_000 },
    async () => {
      const text = readFileSync(new URL('../../docs/nats.md', import.meta.url), 'utf8');
      const pairs = [
        ...text.matchAll(/```ts\n([\s\S]*?)```\n\nprints[^`]*```text\n([\s\S]*?)```/g),
      ];
      expect(pairs.length).toBe(3);
      for (const [, code = '', printed = ''] of pairs) {
        const lines: string[] = [];
        await run(code, (...values) => lines.push(values.map(String).join(' ')));
        expect(lines).toEqual(printed.trimEnd().split('\n'));
      }
    },
  );
});
