// The package README's example and the docs' example messages, run as written.
import { readFileSync } from 'node:fs';
import * as remote from '@hal/remote';
import { decodeMessage } from '@hal/remote';
import * as server from '@hal/remote/server';
import * as simulation from '@hal/simulation';
import { fencedBlocks, runDocExample } from '@hal/types/testing';
import { describe, expect, it } from 'vitest';

const readme = readFileSync(new URL('../../packages/remote/README.md', import.meta.url), 'utf8');
const docs = readFileSync(new URL('../../docs/remote.md', import.meta.url), 'utf8');
const blocks = fencedBlocks;

describe('the @hal/remote README', () => {
  it('serves a simulator and drives it 10 cm through RemoteHAL, printing the result and x', async () => {
    const [block] = blocks(readme, 'ts');
    const logged: unknown[][] = [];
    await runDocExample(
      block!.replaceAll('console.log(', 'log('),
      { '@hal/remote': remote, '@hal/remote/server': server, '@hal/simulation': simulation },
      { log: (...values: unknown[]) => logged.push(values) },
    );
    expect(logged).toHaveLength(1);
    expect(logged[0]?.[0]).toBe(true);
    expect(logged[0]?.[1]).toBeCloseTo(0.1, 3);
  });
});

describe('docs/remote.md', () => {
  it('shows example messages that decode as the protocol says', () => {
    const lines = blocks(docs, 'json')
      .join('')
      .split(/\n(?=\{"hal_major")/)
      .map((l) => l.replace(/\n\s*/g, ''))
      .filter((l) => l.length > 0);
    expect(lines).toHaveLength(2);
    const [call, reply] = lines.map((l) => decodeMessage(l));
    expect(call).toMatchObject({
      schema: 'hal.remote.call',
      envelope: { payload: { call: 'moveForward' } },
    });
    expect(reply).toMatchObject({
      schema: 'hal.remote.reply',
      envelope: { payload: { id: '7', ok: true } },
    });
  });
});
