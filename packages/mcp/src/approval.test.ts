// A person in the loop, with the SDK's own client over an in-memory pair: a motion is asked about
// by elicitation, in words; declined, unanswered or with no one to ask, nothing moves and the
// result says which; accepted, it moves. Stops are never held; a skill is asked about once.
import { Client } from '@modelcontextprotocol/sdk/client/index.js';
import { InMemoryTransport } from '@modelcontextprotocol/sdk/inMemory.js';
import {
  ElicitRequestSchema,
  LoggingMessageNotificationSchema,
} from '@modelcontextprotocol/sdk/types.js';
import type { ElicitResult, LoggingMessageNotification } from '@modelcontextprotocol/sdk/types.js';
import { SimulationHAL } from '@hal/simulation';
import { createToolExecutor } from '@hal/tools';
import type { AgentTool, ToolResult } from '@hal/tools';
import { afterEach, describe, expect, it } from 'vitest';
import { approveOverMcp } from './approval.js';
import type { ApprovalPolicy } from './approval-policy.js';
import { createRobotMcpServer } from './server.js';
import type { OfferedTools } from './server.js';

let sim: SimulationHAL | undefined;
let client: Client | undefined;
afterEach(async () => {
  await client?.close();
  await sim?.cleanup();
  client = undefined;
  sim = undefined;
});

/** What the person answers, and the questions they were asked. */
interface Person {
  answer?: (message: string) => Promise<ElicitResult>;
  asked: string[];
}

interface Connected {
  client: Client;
  sim: SimulationHAL;
  logs: LoggingMessageNotification['params'][];
}

async function connect(
  policy: ApprovalPolicy,
  person: Person | undefined,
  offer: (hal: SimulationHAL) => OfferedTools = (hal) =>
    createToolExecutor(hal, { leash: { approve: approveOverMcp } }),
  approvalTimeoutMs?: number,
): Promise<Connected> {
  sim = new SimulationHAL();
  await sim.initialize();
  const server = createRobotMcpServer(
    sim,
    offer(sim),
    {},
    {
      approve: policy,
      ...(approvalTimeoutMs === undefined ? {} : { approvalTimeoutMs }),
    },
  );
  const [clientSide, serverSide] = InMemoryTransport.createLinkedPair();
  await server.connect(serverSide);
  client = new Client(
    { name: 'hal-approval-test', version: '1.0.0' },
    person === undefined ? {} : { capabilities: { elicitation: { form: {} } } },
  );
  const logs: Connected['logs'] = [];
  client.setNotificationHandler(LoggingMessageNotificationSchema, (n) => {
    logs.push(n.params);
  });
  if (person !== undefined) {
    client.setRequestHandler(ElicitRequestSchema, async (request) => {
      person.asked.push(request.params.message);
      return person.answer?.(request.params.message) ?? new Promise<ElicitResult>(() => undefined);
    });
  }
  await client.connect(clientSide);
  return { client, sim, logs };
}

const x = async (hal: SimulationHAL) => (await hal.locomotion.getPose()).position.x;
const textOf = (result: Awaited<ReturnType<Client['callTool']>>) =>
  (result.content as Array<{ text?: string }>).map((c) => c.text ?? '').join('\n');

describe('approval by elicitation (--approve)', () => {
  it('asks in words; a decline moves nothing, an accept moves', async () => {
    const person: Person = { asked: [], answer: async () => ({ action: 'decline' }) };
    const { client: c, sim: hal } = await connect('motion', person);

    const declined = await c.callTool({ name: 'move_forward', arguments: { distanceCm: 30 } });
    expect(declined.isError).toBe(true);
    expect(textOf(declined)).toMatch(/DENIED/);
    expect(textOf(declined)).toMatch(/the user declined/);
    expect(await x(hal)).toBe(0);
    expect(person.asked[0]).toMatch(
      /^Allow the robot to move_forward: drive 0\.30 m forward at \d\.\d\d m\/s\?$/,
    );

    person.answer = async () => ({ action: 'cancel' });
    const cancelled = await c.callTool({
      name: 'rotate',
      arguments: { direction: 'left', degrees: 90 },
    });
    expect(textOf(cancelled)).toMatch(/cancelled/);
    expect(person.asked[1]).toMatch(/turn 90° left \(counter-clockwise\) on the spot/);
    expect((await hal.locomotion.getPose()).rotation.yaw).toBe(0);

    person.answer = async () => ({ action: 'accept', content: {} });
    const accepted = await c.callTool({ name: 'move_forward', arguments: { distanceCm: 30 } });
    expect(accepted.isError).toBe(false);
    expect(await x(hal)).toBeGreaterThan(0.25);
  });

  it('takes no answer within the timeout as no: nothing moves', async () => {
    const person: Person = { asked: [] }; // never answers
    const { client: c, sim: hal } = await connect('motion', person, undefined, 50);
    const result = await c.callTool({ name: 'move_forward', arguments: { distanceCm: 30 } });
    expect(result.isError).toBe(true);
    expect(textOf(result)).toMatch(/no answer within 0\.05 s/);
    expect(person.asked).toHaveLength(1);
    expect(await x(hal)).toBe(0);
  });

  it('withdraws the open question when a stop comes: nothing moves after it', async () => {
    let asked!: () => void;
    const question = new Promise<void>((resolve) => (asked = resolve));
    const person: Person = {
      asked: [],
      answer: () => {
        asked();
        return new Promise<ElicitResult>(() => undefined); // the person is away
      },
    };
    const { client: c, sim: hal } = await connect('motion', person);
    const moving = c.callTool({ name: 'move_forward', arguments: { distanceCm: 30 } });
    await question;
    expect((await c.callTool({ name: 'stop', arguments: {} })).isError).toBe(false);
    const result = await moving;
    expect(result.isError).toBe(true);
    expect(textOf(result)).toMatch(/a stop came while the question was open/);
    expect(await x(hal)).toBe(0);
  });

  it('withdraws the open question when the e-stop is pressed elsewhere', async () => {
    let asked!: () => void;
    const question = new Promise<void>((resolve) => (asked = resolve));
    const person: Person = {
      asked: [],
      answer: () => {
        asked();
        return new Promise<ElicitResult>(() => undefined);
      },
    };
    const { client: c, sim: hal } = await connect('motion', person);
    const moving = c.callTool({ name: 'move_forward', arguments: { distanceCm: 30 } });
    await question;
    // another handle on the same robot, not a call through the server
    await hal.safety.emergencyStop('pressed by the operator');
    const result = await moving;
    expect(textOf(result)).toMatch(/a stop came while the question was open/);
    expect(await x(hal)).toBe(0);
  });

  it('never holds stop and emergency_stop, nor asks about reads', async () => {
    const person: Person = { asked: [], answer: async () => ({ action: 'decline' }) };
    const { client: c, sim: hal } = await connect('motion', person);
    expect((await c.callTool({ name: 'stop', arguments: {} })).isError).toBe(false);
    expect((await c.callTool({ name: 'get_pose', arguments: {} })).isError).toBe(false);
    const estop = await c.callTool({ name: 'emergency_stop', arguments: { reason: 'test' } });
    expect(estop.isError).toBe(false);
    expect(hal.safety.isEmergencyStopped()).toBe(true);
    expect(person.asked).toEqual([]);
  });

  it('under over:DISTANCE asks only about a longer motion', async () => {
    const person: Person = { asked: [], answer: async () => ({ action: 'decline' }) };
    const { client: c, sim: hal } = await connect({ overM: 0.2 }, person);
    const short = await c.callTool({ name: 'move_forward', arguments: { distanceCm: 10 } });
    expect(short.isError).toBe(false);
    const turn = await c.callTool({
      name: 'rotate',
      arguments: { direction: 'left', degrees: 45 },
    });
    expect(turn.isError).toBe(false);
    expect(person.asked).toEqual([]);
    const before = await x(hal);
    const long = await c.callTool({ name: 'move_forward', arguments: { distanceCm: 30 } });
    expect(long.isError).toBe(true);
    expect(person.asked).toHaveLength(1);
    expect(await x(hal)).toBe(before);
  });

  it('refuses every motion, and says so at the start, to a client that cannot be asked', async () => {
    const { client: c, sim: hal, logs } = await connect('motion', undefined);
    const result = await c.callTool({ name: 'move_forward', arguments: { distanceCm: 30 } });
    expect(result.isError).toBe(true);
    expect(textOf(result)).toMatch(/did not declare the elicitation capability/);
    expect(await x(hal)).toBe(0);
    expect(logs).toContainEqual(
      expect.objectContaining({
        level: 'error',
        data: expect.stringMatching(/did not declare elicitation/),
      }),
    );
  });

  it('with none, says once that no one approves, and asks nothing', async () => {
    const person: Person = { asked: [], answer: async () => ({ action: 'decline' }) };
    const { client: c, logs } = await connect('none', person);
    expect(
      (await c.callTool({ name: 'move_forward', arguments: { distanceCm: 10 } })).isError,
    ).toBe(false);
    expect(
      (await c.callTool({ name: 'move_forward', arguments: { distanceCm: 10 } })).isError,
    ).toBe(false);
    expect(person.asked).toEqual([]);
    expect(logs.filter((l) => String(l.data).includes('No one approves'))).toHaveLength(1);
  });

  it('asks about a skill once, before it starts, and not again for its own motions', async () => {
    const person: Person = { asked: [], answer: async () => ({ action: 'accept', content: {} }) };
    const MOVE: AgentTool = {
      name: 'move',
      description: 'Drive straight, cm.',
      inputSchema: { type: 'object', properties: { cm: { type: 'number' } }, required: ['cm'] },
      motion: true,
    };
    const skills = (hal: SimulationHAL): OfferedTools => {
      const primitives = createToolExecutor(hal, { leash: { approve: approveOverMcp } });
      return {
        tools: [MOVE, ...primitives.tools],
        execute: async (call): Promise<ToolResult> => {
          if (call.name !== 'move') return primitives.execute(call);
          const cm = (call.arguments as { cm: number }).cm;
          // in two legs, as a skill's motions are
          await primitives.execute({ name: 'move_forward', arguments: { distanceCm: cm / 2 } });
          return primitives.execute({ name: 'move_forward', arguments: { distanceCm: cm / 2 } });
        },
      };
    };
    const { client: c, sim: hal } = await connect('motion', person, skills);
    const moved = await c.callTool({ name: 'move', arguments: { cm: 30 } });
    expect(moved.isError).toBe(false);
    expect(person.asked).toEqual(['Allow the robot to move: drive 0.30 m forward?']);
    expect(await x(hal)).toBeGreaterThan(0.25);

    person.answer = async () => ({ action: 'decline' });
    const before = await x(hal);
    const declined = await c.callTool({ name: 'move', arguments: { cm: 30 } });
    expect(declined.isError).toBe(true);
    expect(textOf(declined)).toMatch(/move: denied: the user declined/);
    expect(await x(hal)).toBe(before);
  });

  it('the hook refuses outside an MCP tool call', async () => {
    sim = new SimulationHAL();
    await sim.initialize();
    const executor = createToolExecutor(sim, { leash: { approve: approveOverMcp } });
    const result = await executor.execute({ name: 'move_forward', arguments: { distanceCm: 10 } });
    expect(result.code).toBe('DENIED');
    expect(await x(sim)).toBe(0);
  });
});
