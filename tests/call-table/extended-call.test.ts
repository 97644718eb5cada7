// A call added to the table reaches every consumer that takes a table, with no other edit: the
// tools, the WebSocket server and RemoteHAL, the NATS gateway and NatsHAL (through a real
// nats-server), HybridHAL and the fleet's commands.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { z } from 'zod';
import { fleetCommandSchema, parseFleetCommand, runFleetCommand } from '@hal/fleet';
import { HybridHAL } from '@hal/hybrid';
import { NatsHAL, serveHalOnNats } from '@hal/nats';
import { RemoteHAL } from '@hal/remote';
import { serveHal } from '@hal/remote/server';
import { SimulationHAL } from '@hal/simulation';
import { createToolExecutor, halTools } from '@hal/tools';
import { HAL_CALL_TABLE, successResult } from '@hal/types';
import type { CallSpec, CallTable, HALToolResult, HardwareAbstractionLayer } from '@hal/types';
import { startNatsServer, stopAllNatsServers } from '../nats/nats-server.js';
import type { NatsServer } from '../nats/nats-server.js';

/** A motion no HAL has today: wiggle in place `times` times. */
const WIGGLE: CallSpec = {
  name: 'wiggle',
  subsystem: 'locomotion',
  method: 'wiggle',
  kind: 'motion',
  lane: 'queue',
  controllerOnly: true,
  cached: false,
  params: ['times'],
  paramsSchema: () =>
    z.object({ times: z.number().int().min(1).max(5).describe('How many wiggles, 1..5') }),
  data: z.looseObject({ wiggled: z.number() }),
  tool: { name: 'wiggle', summary: 'Wiggle in place.' },
};
const TABLE: CallTable = [...HAL_CALL_TABLE, WIGGLE];

type Wiggly = HardwareAbstractionLayer & {
  locomotion: { wiggle(times: number): Promise<HALToolResult> };
};

/** A simulated robot that can wiggle, recording how often it was asked to. */
function wigglingRobot(): { hal: SimulationHAL; wiggles: number[] } {
  const hal = new SimulationHAL();
  const wiggles: number[] = [];
  Object.assign(hal.locomotion, {
    wiggle: (times: number) => {
      wiggles.push(times);
      return Promise.resolve(successResult(hal.mode, Date.now(), { wiggled: times }));
    },
  });
  return { hal, wiggles };
}

const wiggle = (hal: HardwareAbstractionLayer, times: unknown) =>
  (hal as Wiggly).locomotion.wiggle(times as number);

let nats: NatsServer;
beforeAll(async () => {
  nats = await startNatsServer();
}, 20_000);
afterAll(async () => {
  await stopAllNatsServers();
});

describe('a call added to the call table', () => {
  it('becomes a tool that the executor runs, with its schema as the tool parameters', async () => {
    const { hal, wiggles } = wigglingRobot();
    await hal.initialize();
    try {
      const tools = halTools(hal, { calls: TABLE });
      const tool = tools.find((t) => t.name === 'wiggle');
      expect(tool).toMatchObject({ call: 'wiggle', motion: true });
      expect(tool?.inputSchema.properties).toHaveProperty('times');
      const executor = createToolExecutor(hal, { tools, calls: TABLE });
      const done = await executor.execute({ name: 'wiggle', arguments: { times: 2 } });
      expect(done.isError).toBe(false);
      const refused = await executor.execute({ name: 'wiggle', arguments: { times: 9 } });
      expect(refused.isError).toBe(true);
      expect(wiggles).toEqual([2]);
    } finally {
      await hal.cleanup();
    }
  });

  it('is served by serveHal and forwarded by RemoteHAL', async () => {
    const { hal, wiggles } = wigglingRobot();
    await hal.initialize();
    const server = await serveHal(hal, { port: 0, calls: TABLE });
    const remote = new RemoteHAL({ url: server.url, calls: TABLE });
    try {
      await remote.initialize();
      const result = await wiggle(remote, 3);
      expect(result).toMatchObject({ success: true, data: { wiggled: 3 } });
      expect(wiggles).toEqual([3]);
      // controller-only, as the table says: a watching client is refused by the server
      const watcher = new RemoteHAL({ url: server.url, calls: TABLE, control: 'watch' });
      await watcher.initialize();
      try {
        expect(await wiggle(watcher, 1)).toMatchObject({ success: false, code: 'NOT_CONTROLLER' });
      } finally {
        await watcher.cleanup();
      }
      expect(wiggles).toEqual([3]);
    } finally {
      await remote.cleanup();
      await server.close();
      await hal.cleanup();
    }
  });

  it('crosses NATS: the gateway serves it and NatsHAL forwards it', async () => {
    const { hal, wiggles } = wigglingRobot();
    await hal.initialize();
    const gateway = await serveHalOnNats(hal, {
      servers: nats.url,
      deviceId: 'wiggler',
      stateRateHz: 0,
      calls: TABLE,
    });
    const client = new NatsHAL({ servers: nats.url, deviceId: 'wiggler', calls: TABLE });
    try {
      await client.initialize();
      expect(await wiggle(client, 4)).toMatchObject({ success: true, data: { wiggled: 4 } });
      expect(wiggles).toEqual([4]);
    } finally {
      await client.cleanup();
      await gateway.close();
      await hal.cleanup();
    }
  });

  it('runs on both robots of a HybridHAL, validated once by its boundary', async () => {
    const physical = wigglingRobot();
    const twin = wigglingRobot();
    const hybrid = new HybridHAL({ physical: physical.hal, twin: twin.hal, calls: TABLE });
    await hybrid.initialize();
    try {
      const result = await wiggle(hybrid, 2);
      expect(result).toMatchObject({ success: true, mode: 'hybrid', data: { wiggled: 2 } });
      expect(physical.wiggles).toEqual([2]);
      expect(twin.wiggles).toEqual([2]);
      expect(await wiggle(hybrid, 0)).toMatchObject({ success: false, code: 'RANGE_EXCEEDED' });
      expect(physical.wiggles).toEqual([2]);
    } finally {
      await hybrid.cleanup();
    }
  });

  it('is a fleet command, checked for its shape and run through the HAL', async () => {
    const { hal, wiggles } = wigglingRobot();
    await hal.initialize();
    try {
      const command = parseFleetCommand({ kind: 'wiggle', times: 5 }, fleetCommandSchema(TABLE));
      expect(await runFleetCommand(hal, command, TABLE)).toMatchObject({ success: true });
      expect(wiggles).toEqual([5]);
      expect(() =>
        parseFleetCommand({ kind: 'wiggle', times: 'x' }, fleetCommandSchema(TABLE)),
      ).toThrow(/times/);
      expect(() => parseFleetCommand({ kind: 'wiggle', times: 1 })).toThrow(/not a fleet command/);
    } finally {
      await hal.cleanup();
    }
  });
});
