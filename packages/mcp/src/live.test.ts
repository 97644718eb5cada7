// What a client is told without asking, with the SDK's own client over an in-memory pair:
// progress during a 30 cm move (on the real-time clock, as a robot moves), ending at the total;
// robot://events and robot://state updates when the e-stop is pressed from elsewhere (another
// handle on the same HAL); the robot's log at the level the client set.
import { Client } from '@modelcontextprotocol/sdk/client/index.js';
import { InMemoryTransport } from '@modelcontextprotocol/sdk/inMemory.js';
import {
  LoggingMessageNotificationSchema,
  ResourceUpdatedNotificationSchema,
} from '@modelcontextprotocol/sdk/types.js';
import type { LoggingMessageNotification, Progress } from '@modelcontextprotocol/sdk/types.js';
import { SimulationHAL } from '@hal/simulation';
import type { SimulationHALOptions } from '@hal/simulation';
import { createToolExecutor } from '@hal/tools';
import { afterEach, describe, expect, it } from 'vitest';
import type { RobotEvent } from './events.js';
import { createRobotMcpServer } from './server.js';

let sim: SimulationHAL | undefined;
let client: Client | undefined;
afterEach(async () => {
  await client?.close();
  await sim?.cleanup();
  client = undefined;
  sim = undefined;
});

interface Heard {
  logs: LoggingMessageNotification['params'][];
  updated: string[];
  /** Resolves at the next update of `uri`. */
  next(uri: string): Promise<void>;
}

async function connect(
  options: SimulationHALOptions = {},
): Promise<{ c: Client; hal: SimulationHAL; heard: Heard }> {
  const hal = new SimulationHAL(options);
  sim = hal;
  await hal.initialize();
  const server = createRobotMcpServer(
    hal,
    createToolExecutor(hal),
    {},
    {
      eventSources: {
        logs: (listener) =>
          hal.events.on('communication', (e) => {
            if (e.type === 'log') listener({ level: e.level, message: e.message });
          }),
      },
    },
  );
  const [clientSide, serverSide] = InMemoryTransport.createLinkedPair();
  await server.connect(serverSide);
  const c = new Client({ name: 'hal-live-test', version: '1.0.0' });
  client = c;
  const waiting: Array<{ uri: string; resolve: () => void }> = [];
  const heard: Heard = {
    logs: [],
    updated: [],
    next: (uri) => new Promise((resolve) => waiting.push({ uri, resolve })),
  };
  c.setNotificationHandler(LoggingMessageNotificationSchema, (n) => {
    heard.logs.push(n.params);
  });
  c.setNotificationHandler(ResourceUpdatedNotificationSchema, (n) => {
    heard.updated.push(n.params.uri);
    for (const w of waiting.splice(0)) {
      if (w.uri === n.params.uri) w.resolve();
      else waiting.push(w);
    }
  });
  await c.connect(clientSide);
  return { c, hal, heard };
}

const readJson = async (c: Client, uri: string) =>
  JSON.parse(((await c.readResource({ uri })).contents[0] as { text: string }).text) as Record<
    string,
    unknown
  >;

describe('progress, events and the log over MCP', () => {
  it('reports progress during a 30 cm move, each larger than the last, ending at the total', async () => {
    const { c, hal } = await connect({ clock: 'realtime', realtimeSpeed: 2 });
    const reports: Progress[] = [];
    const result = await c.callTool(
      { name: 'move_forward', arguments: { distanceCm: 30 } },
      undefined,
      { onprogress: (p) => reports.push(p) },
    );
    expect(result.isError).toBe(false);
    expect((await hal.locomotion.getPose()).position.x).toBeGreaterThan(0.25);
    // some arrived while it moved, and the last is the whole distance
    expect(reports.length).toBeGreaterThan(1);
    expect(reports[0]?.progress).toBeLessThan(0.3);
    expect(reports.at(-1)).toMatchObject({ progress: 0.3, total: 0.3 });
    expect(reports.every((r) => r.total === 0.3)).toBe(true);
    for (let i = 1; i < reports.length; i++) {
      expect(reports[i]!.progress).toBeGreaterThan(reports[i - 1]!.progress);
    }
    expect(reports.at(-1)?.message).toBe('0.3 of 0.3 m travelled');
  });

  it('reports the angle of a turn in degrees', async () => {
    const { c } = await connect();
    const reports: Progress[] = [];
    await c.callTool(
      { name: 'rotate', arguments: { direction: 'right', degrees: 90 } },
      undefined,
      { onprogress: (p) => reports.push(p) },
    );
    expect(reports.at(-1)).toMatchObject({ progress: 90, total: 90 });
  });

  it('sends robot://events and robot://state updates when the e-stop is pressed elsewhere', async () => {
    const { c, hal, heard } = await connect();
    await c.subscribeResource({ uri: 'robot://events' });
    await c.subscribeResource({ uri: 'robot://state' });
    const event = heard.next('robot://events');
    const state = heard.next('robot://state');
    // another handle on the same robot: not a call through the MCP server
    await hal.safety.emergencyStop('pressed by the operator');
    await event;
    await state;
    const { events } = (await readJson(c, 'robot://events')) as { events: RobotEvent[] };
    expect(events.at(-1)).toMatchObject({
      type: 'emergency_stop',
      by: 'elsewhere',
      reason: 'pressed by the operator',
    });
    expect(await readJson(c, 'robot://state')).toMatchObject({
      safety: { emergencyStopped: true },
    });
    // the log has it too
    expect(heard.logs).toContainEqual(
      expect.objectContaining({ level: 'warning', data: expect.stringMatching(/elsewhere/) }),
    );

    // a reset through the server is the client's own
    const reset = heard.next('robot://events');
    await c.callTool({ name: 'reset_emergency_stop', arguments: {} });
    await reset;
    const after = (await readJson(c, 'robot://events')) as { events: RobotEvent[] };
    expect(after.events.at(-1)).toMatchObject({ type: 'reset', by: 'mcp-client' });
  });

  it('names the e-stop of an MCP client its own, with its reason', async () => {
    const { c, heard } = await connect();
    await c.subscribeResource({ uri: 'robot://events' });
    const event = heard.next('robot://events');
    await c.callTool({ name: 'emergency_stop', arguments: { reason: 'the agent saw smoke' } });
    await event;
    const { events } = (await readJson(c, 'robot://events')) as { events: RobotEvent[] };
    expect(events.at(-1)).toMatchObject({
      type: 'emergency_stop',
      by: 'mcp-client',
      reason: 'the agent saw smoke',
    });
  });

  it('refuses to subscribe to a resource that has no updates', async () => {
    const { c } = await connect();
    await expect(c.subscribeResource({ uri: 'robot://map' })).rejects.toThrow(
      /cannot be subscribed to/,
    );
  });

  it("sends the robot's log at the level the client set", async () => {
    const { c, hal, heard } = await connect();
    await c.setLoggingLevel('warning');
    hal.communication.log('an info line', 'info');
    hal.communication.log('a warning line', 'warn');
    // a request answered after the lines were logged: every notification before it has arrived
    await c.callTool({ name: 'get_pose', arguments: {} });
    const lines = heard.logs.filter((l) => l.logger === 'robot');
    expect(lines).toEqual([{ level: 'warning', logger: 'robot', data: 'a warning line' }]);

    await c.setLoggingLevel('debug');
    hal.communication.log('another info line', 'info');
    await c.callTool({ name: 'get_pose', arguments: {} });
    expect(heard.logs.filter((l) => l.logger === 'robot').map((l) => l.data)).toEqual([
      'a warning line',
      'another info line',
    ]);
  });
});
