// The @hal/agent README's example, run as written against the fake endpoint (only the address
// and the model change, and console.log goes to a list).
import { readFileSync } from 'node:fs';
import * as agent from '@hal/agent';
import * as simulation from '@hal/simulation';
import { fencedBlocks, runDocExample } from '@hal/types/testing';
import { describe, expect, it } from 'vitest';
import { call, serve } from './fixtures.js';

const readme = readFileSync(new URL('../../packages/agent/README.md', import.meta.url), 'utf8');
const blocks = fencedBlocks(readme, 'ts');

describe('the @hal/agent README', () => {
  it('runs its example: the model drives 30 cm and says where the robot is', async () => {
    expect(blocks).toHaveLength(1);
    const s = await serve([
      { content: null, toolCalls: [call('move_forward', { distanceCm: 30 })] },
      { content: null, toolCalls: [call('get_pose')] },
      { content: 'I am at x -1.5 m, y 0 m.' },
    ]);
    let body = blocks[0]!.replaceAll('console.log(', 'log(');
    for (const [from, to] of [
      ["'http://127.0.0.1:11434/v1'", JSON.stringify(s.baseUrl)],
      ["'qwen2.5vl:7b'", "'fake-model'"],
    ] as const) {
      expect(body).toContain(from);
      body = body.replaceAll(from, to);
    }
    const logged: unknown[][] = [];
    await runDocExample(
      body,
      { '@hal/agent': agent, '@hal/simulation': simulation },
      { log: (...values: unknown[]) => logged.push(values) },
    );
    expect(logged.at(-1)).toEqual(['completed', 'I am at x -1.5 m, y 0 m.']);
    expect(logged.slice(0, -1).flat()).toEqual(
      expect.arrayContaining(['step_started', 'tool_call', 'tool_result', 'done']),
    );
    expect(s.requests).toHaveLength(3);
    // The pose the model read is where the 30 cm move ended.
    const pose = JSON.parse(String(s.requests[2]!.body.messages!.at(-1)!.content)) as {
      position: { x: number };
    };
    expect(pose.position.x).toBeCloseTo(-1.5, 2);
  });
});
