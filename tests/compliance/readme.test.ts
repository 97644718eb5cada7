// The example of packages/compliance/README.md, run as written against a real nats-server (only
// the server address changes), so it cannot rot.
import { readFileSync } from 'node:fs';
import * as compliance from '@hal/compliance';
import * as nats from '@hal/nats';
import * as simulation from '@hal/simulation';
import * as transport from '@nats-io/transport-node';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startNatsServer, stopAllNatsServers } from '../nats/nats-server.js';
import type { NatsServer } from '../nats/nats-server.js';

let server: NatsServer;
beforeAll(async () => {
  server = await startNatsServer();
}, 20_000);
afterAll(stopAllNatsServers);

const MODULES: Record<string, Record<string, unknown>> = {
  '@hal/compliance': compliance,
  '@hal/nats': nats,
  '@hal/simulation': simulation,
  '@nats-io/transport-node': transport,
};

describe('the @hal/compliance README', () => {
  it('runs its example and prints what it says', { timeout: 60_000 }, async () => {
    const text = readFileSync(
      new URL('../../packages/compliance/README.md', import.meta.url),
      'utf8',
    );
    const block = /```ts\n([\s\S]*?)```/.exec(text)?.[1] ?? '';
    const printed = /prints\n\n```text\n([\s\S]*?)```/.exec(text)?.[1] ?? '';
    const names: string[] = [];
    const values: unknown[] = [];
    const body = block
      .replace(/^import \{([^}]*)\} from '([^']+)';$/gm, (_all, list: string, from: string) => {
        for (const name of list
          .split(',')
          .map((n) => n.trim())
          .filter((n) => n !== '')) {
          names.push(name);
          values.push(MODULES[from]?.[name]);
        }
        return '';
      })
      .replaceAll('nats://127.0.0.1:4222', server.url)
      .replaceAll('console.log(', 'log(');
    expect(body).not.toMatch(/^import /m);
    const lines: string[] = [];
    const log = (...parts: unknown[]) => lines.push(parts.map(String).join(' '));
    const AsyncFunction = Object.getPrototypeOf(async () => undefined).constructor as new (
      ...args: string[]
    ) => (...args: unknown[]) => Promise<void>;
    await new AsyncFunction(...names, 'log', body)(...values, log);
    expect(`${lines.join('\n')}\n`).toBe(printed);
  });
});
