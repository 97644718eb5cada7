// Events through the real `hal mcp` process and the SDK's client. In the simulator with a box
// ahead, a collision (the guard off) or the guard's stop is an event once the motion answers.
// The emulated cube behind a UDP proxy that stops passing datagrams and passes them again: the
// client subscribed to robot://events is told of the link lost and back, and its log, at the
// level it set (error), has the loss and not the return (info).
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { Client } from '@modelcontextprotocol/sdk/client/index.js';
import { StdioClientTransport } from '@modelcontextprotocol/sdk/client/stdio.js';
import {
  LoggingMessageNotificationSchema,
  ResourceUpdatedNotificationSchema,
} from '@modelcontextprotocol/sdk/types.js';
import type { LoggingMessageNotification } from '@modelcontextprotocol/sdk/types.js';
import type { RobotEvent } from '@hal/mcp';
import { afterAll, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import { startFaultProxy } from '../physical/fault-proxy.js';
import { serverCommand } from './client.js';

afterAll(stopAllEmulators);

const KEY = '00112233445566778899aabbccddeeff';

async function events(client: Client): Promise<RobotEvent[]> {
  const read = await client.readResource({ uri: 'robot://events' });
  return (JSON.parse((read.contents[0] as { text: string }).text) as { events: RobotEvent[] })
    .events;
}

/** Runs `hal mcp` in a world with a box 30 cm ahead, with `args`; `work` drives it. */
async function boxAhead(args: string[], work: (client: Client) => Promise<void>): Promise<void> {
  const dir = mkdtempSync(join(tmpdir(), 'hal-mcp-events-'));
  const world = join(dir, 'box-ahead.json');
  writeFileSync(
    world,
    JSON.stringify({
      map: 'empty',
      start: { x: 0, y: 0, yawDeg: 0 },
      objects: [{ name: 'box', kind: 'box', colour: 'red', x: 0.3, y: 0 }],
    }),
  );
  const client = new Client({ name: 'hal-events-test', version: '1.0.0' });
  await client.connect(
    new StdioClientTransport({ ...serverCommand(['--world', world, ...args]), stderr: 'ignore' }),
  );
  try {
    await client.subscribeResource({ uri: 'robot://events' });
    await work(client);
  } finally {
    await client.close();
    rmSync(dir, { recursive: true, force: true });
  }
}

describe('hal mcp --sim: a box ahead', () => {
  it('without the guard, the collision is an event with where the robot touched', async () => {
    await boxAhead(['--no-guard'], async (client) => {
      const moved = await client.callTool({ name: 'move_forward', arguments: { distanceCm: 60 } });
      expect(moved.isError).toBe(true);
      expect(JSON.stringify(moved.content)).toContain('COLLISION');
      const collision = (await events(client)).find((e) => e.type === 'collision');
      expect(collision?.message).toMatch(
        /^The robot touched a \w+ at \(0\.\d{3}, -?0\.\d{3}\) m and stopped$/,
      );
      expect(collision?.details).toHaveProperty('contact.point');
    });
  });

  it('with the guard, its stop before the box is an event, and there is no collision', async () => {
    await boxAhead([], async (client) => {
      const moved = await client.callTool({ name: 'move_forward', arguments: { distanceCm: 60 } });
      expect(moved.isError).toBe(true);
      expect(JSON.stringify(moved.content)).toContain('OBSTACLE_AHEAD');
      const seen = await events(client);
      expect(seen.map((e) => e.type)).toEqual(['guard_stop']);
      expect(seen[0]?.message).toMatch(
        /^The guard (stopped the robot|refused a motion): something/,
      );
    });
  });
});

describe('hal mcp --udp: the link lost and back, as events and in the log', () => {
  it('tells a subscribed client, and logs at the level it set', async () => {
    const emulator = await startEmulator({ key: KEY, pty: false, hostTimeoutMs: 10_000 });
    const proxy = await startFaultProxy({
      robotPort: emulator.udpPort,
      seed: 1,
      toRobot: {},
      toHost: {},
    });
    const client = new Client({ name: 'hal-events-test', version: '1.0.0' });
    const logs: LoggingMessageNotification['params'][] = [];
    let updated: () => void = () => undefined;
    client.setNotificationHandler(LoggingMessageNotificationSchema, (n) => {
      logs.push(n.params);
    });
    client.setNotificationHandler(ResourceUpdatedNotificationSchema, () => updated());
    /** Resolves once robot://events holds an event of `type`. */
    const eventOf = async (type: RobotEvent['type']) => {
      for (;;) {
        const update = new Promise<void>((resolve) => (updated = resolve));
        const found = (await events(client)).find((e) => e.type === type);
        if (found !== undefined) return found;
        await update;
      }
    };
    await client.connect(
      new StdioClientTransport({
        ...serverCommand(['--udp', `127.0.0.1:${proxy.port}`]),
        env: { ...(process.env as Record<string, string>), HAL_KEY: KEY },
        stderr: 'ignore',
      }),
    );
    try {
      await client.setLoggingLevel('error');
      const fromNow = logs.length; // what came before the level was set is not filtered
      await client.subscribeResource({ uri: 'robot://events' });
      proxy.setFaults({ toRobot: { drop: 1 }, toHost: { drop: 1 } });
      expect(await eventOf('link_lost')).toMatchObject({
        message: 'The link to the robot is lost; reconnecting',
      });
      proxy.setFaults({ toRobot: {}, toHost: {} });
      expect(await eventOf('link_back')).toMatchObject({
        message: 'The link to the robot is back',
      });
      // a request answered after both: every log line sent before it has arrived
      await client.readResource({ uri: 'robot://state' });
      // the loss (error) was sent, the return (info) and everything else below error was not
      const after = logs.slice(fromNow);
      expect(after).toContainEqual({
        level: 'error',
        logger: 'events',
        data: 'The link to the robot is lost; reconnecting',
      });
      expect(after.filter((l) => l.level !== 'error')).toEqual([]);
    } finally {
      await client.close();
      await proxy.close();
      await emulator.stop();
    }
  }, 60_000);
});
