// The example of packages/compliance/README.md, run as written against a real nats-server (only
// the server address changes), so it cannot rot.
import { readFileSync } from 'node:fs';
import * as compliance from '@hal/compliance';
import * as nats from '@hal/nats';
import * as simulation from '@hal/simulation';
import { runDocExample } from '@hal/types/testing';
import type { ExampleModules } from '@hal/types/testing';
import * as transport from '@nats-io/transport-node';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startNatsServer, stopAllNatsServers } from '../nats/nats-server.js';
import type { NatsServer } from '../nats/nats-server.js';

let server: NatsServer;
beforeAll(async () => {
  server = await startNatsServer();
}, 20_000);
afterAll(stopAllNatsServers);

const MODULES: ExampleModules = {
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
    const code = block
      .replaceAll('nats://127.0.0.1:4222', server.url)
      .replaceAll('console.log(', 'log(');
    const lines: string[] = [];
    const log = (...parts: unknown[]) => lines.push(parts.map(String).join(' '));
    await runDocExample(code, MODULES, { log });
    expect(`${lines.join('\n')}\n`).toBe(printed);
  });
});
