// A person in the loop through the real `hal mcp` process over stdio, with the SDK's own client
// as the person's: `--approve motion` asks before a motion, by elicitation, in words; declined,
// nothing moves; accepted, it moves, with progress toward the total; a stop is never asked
// about; and `--approve over:DISTANCE` lets a shorter motion through unasked.
import { Client } from '@modelcontextprotocol/sdk/client/index.js';
import { StdioClientTransport } from '@modelcontextprotocol/sdk/client/stdio.js';
import { ElicitRequestSchema } from '@modelcontextprotocol/sdk/types.js';
import type { ElicitResult, Progress } from '@modelcontextprotocol/sdk/types.js';
import { afterEach, describe, expect, it } from 'vitest';
import { callTool, serverCommand } from './client.js';

let client: Client | undefined;
afterEach(async () => {
  await client?.close();
  client = undefined;
});

/** A client whose user answers every question with `answers`' next, and remembers the questions. */
async function connect(
  args: string[],
  answers: Array<ElicitResult['action']>,
): Promise<{ c: Client; asked: string[] }> {
  const asked: string[] = [];
  client = new Client(
    { name: 'hal-approval-test', version: '1.0.0' },
    { capabilities: { elicitation: { form: {} } } },
  );
  client.setRequestHandler(ElicitRequestSchema, async (request) => {
    asked.push(request.params.message);
    const action = answers.shift() ?? 'decline';
    return action === 'accept' ? { action, content: {} } : { action };
  });
  await client.connect(new StdioClientTransport({ ...serverCommand(args), stderr: 'ignore' }));
  return { c: client, asked };
}

/**
 * Progress toward `total`: each report of that total and larger than the last, none beyond it.
 * (The server's last report is the total, sent before the result; the SDK's client may drop it
 * when it reads both at once, modelcontextprotocol/typescript-sdk#2580, so it is not required
 * here: live.test.ts in @hal/mcp checks it over a transport that delivers one message at a time.)
 */
function expectProgressTo(reports: Progress[], total: number): void {
  for (const [i, report] of reports.entries()) {
    expect(report.total).toBe(total);
    expect(report.progress).toBeLessThanOrEqual(total);
    if (i > 0) expect(report.progress).toBeGreaterThan(reports[i - 1]!.progress);
  }
}

const xOf = async (c: Client) =>
  ((await callTool(c, 'get_pose')).json['position'] as { x: number }).x;

describe('hal mcp --approve over stdio (the server process, the SDK client)', () => {
  it('asks before a motion: declined nothing moves, accepted it moves with progress toward the total', async () => {
    const { c, asked } = await connect(['--approve', 'motion'], ['decline', 'accept']);

    const declined = await callTool(c, 'move_forward', { distanceCm: 30 });
    expect(declined.isError).toBe(true);
    expect(declined.json).toMatchObject({ code: 'DENIED' });
    expect(declined.text).toMatch(/the user declined/);
    expect(asked).toHaveLength(1);
    expect(asked[0]).toMatch(/^Allow the robot to move_forward: drive 0\.30 m forward at /);
    expect(await xOf(c)).toBe(0);

    const reports: Progress[] = [];
    const accepted = await c.callTool(
      { name: 'move_forward', arguments: { distanceCm: 30 } },
      undefined,
      { onprogress: (p) => reports.push(p) },
    );
    expect(accepted.isError).toBe(false);
    expect(asked).toHaveLength(2);
    expect(await xOf(c)).toBeCloseTo(0.3, 2);
    expectProgressTo(reports, 0.3);

    // the stop is never held for a question
    expect((await callTool(c, 'stop')).isError).toBe(false);
    expect(asked).toHaveLength(2);
  });

  it('asks about a skill once, not again for the motions it makes, and reports its progress', async () => {
    const { c, asked } = await connect(
      ['--tools', 'skills', '--approve', 'motion'],
      ['accept', 'decline'],
    );
    const reports: Progress[] = [];
    const moved = await c.callTool({ name: 'move', arguments: { cm: 20 } }, undefined, {
      onprogress: (p) => reports.push(p),
    });
    expect(moved.isError, JSON.stringify(moved.content)).toBe(false);
    expectProgressTo(reports, 0.2);
    expect(asked).toEqual(['Allow the robot to move: drive 0.20 m forward?']);

    const turned = await c.callTool({ name: 'turn', arguments: { degrees: 90 } });
    expect(turned.isError).toBe(true);
    expect(JSON.stringify(turned.content)).toMatch(/turn: denied: the user declined/);
    expect(asked).toHaveLength(2);
    const state = JSON.parse(
      ((await c.readResource({ uri: 'robot://state' })).contents[0] as { text: string }).text,
    ) as { pose: { position: { x: number }; rotation: { yaw: number } } };
    expect(state.pose.position.x).toBeCloseTo(0.2, 2);
    expect(state.pose.rotation.yaw).toBeCloseTo(0, 3);
  });

  it('over:DISTANCE asks only about a longer motion', async () => {
    const { c, asked } = await connect(['--approve', 'over:20cm'], ['decline']);
    expect((await callTool(c, 'move_forward', { distanceCm: 10 })).isError).toBe(false);
    expect(asked).toEqual([]);
    const long = await callTool(c, 'move_forward', { distanceCm: 30 });
    expect(long.isError).toBe(true);
    expect(asked).toHaveLength(1);
    expect(await xOf(c)).toBeCloseTo(0.1, 2);
  });
});
