// The examples of packages/nats/README.md and docs/nats.md, run as written against a real
// nats-server (only the server address changes), so they cannot rot.
import { readFileSync } from 'node:fs';
import * as nats from '@hal/nats';
import * as simulation from '@hal/simulation';
import * as types from '@hal/types';
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
  [...readFileSync(new URL(path, import.meta.url), 'utf8').matchAll(/```ts\n([\s\S]*?)```/g)].map(
    (m) => m[1] ?? '',
  );

const MODULES: Record<string, Record<string, unknown>> = {
  '@hal/nats': nats,
  '@hal/simulation': simulation,
  '@hal/types': types,
  '@nats-io/transport-node': transport,
};

/** Runs a block: its imports bound from the real modules, console.log routed to `log`. */
async function run(block: string, log: (...values: unknown[]) => void): Promise<void> {
  const names: string[] = [];
  const values: unknown[] = [];
  let body = block.replace(
    /^import \{([^}]*)\} from '([^']+)';$/gm,
    (_all, list: string, from: string) => {
      const module = MODULES[from];
      if (module === undefined)
        throw new Error(`the example imports ${from}, unknown to this test`);
      for (const name of list
        .split(',')
        .map((n) => n.trim())
        .filter((n) => n !== '')) {
        names.push(name);
        values.push(module[name]);
      }
      return '';
    },
  );
  expect(body).not.toMatch(/^import /m);
  const url = body.includes('user:') ? secured.url : server.url;
  body = body.replaceAll('nats://127.0.0.1:4222', url).replaceAll('console.log(', 'log(');
  const AsyncFunction = Object.getPrototypeOf(async () => undefined).constructor as new (
    ...args: string[]
  ) => (...values: unknown[]) => Promise<void>;
  await new AsyncFunction(...names, 'log', body)(...values, log);
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
