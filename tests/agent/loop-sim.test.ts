// The agent loop against a fake OpenAI-compatible endpoint over real HTTP on 127.0.0.1, driving
// SimulationHAL through the @hal/tools executor: several steps to a goal, camera frames as
// images, malformed arguments the model recovers from, and a refusal.
import { runAgent } from '@hal/agent';
import { SimulationHAL, World } from '@hal/simulation';
import { describe, expect, it } from 'vitest';
import { call, endpoint, recorder, serve } from './fixtures.js';

async function simulator(): Promise<SimulationHAL> {
  // The obstacles map: the robot starts at (-1.8, 0) facing +x; the way to (-1.5, 0.3) is clear.
  const hal = new SimulationHAL({ world: new World({ map: 'obstacles', seed: 1 }) });
  await hal.initialize();
  return hal;
}

describe('runAgent on SimulationHAL', () => {
  it('runs the tool calls of several steps on the HAL until the model says it is done', async () => {
    const s = await serve([
      { content: 'Where am I?', toolCalls: [call('get_pose')] },
      { content: null, toolCalls: [call('move_forward', { distanceCm: 30 })] },
      { content: null, toolCalls: [call('rotate', { direction: 'left', degrees: 90 })] },
      {
        content: null,
        toolCalls: [call('move_forward', { distanceCm: 30 }), call('capture_frame')],
      },
      { content: 'I am at (-1.5, 0.3), facing +y.' },
    ]);
    const hal = await simulator();
    const { events, onEvent } = recorder();
    const outcome = await runAgent({
      goal: 'Drive to x -1.5 m, y 0.3 m.',
      hal,
      endpoint: endpoint(s),
      caps: { maxSteps: 10, maxMs: 30_000 },
      onEvent,
    });
    expect(outcome).toMatchObject({
      reason: 'completed',
      steps: 5,
      text: 'I am at (-1.5, 0.3), facing +y.',
    });
    const pose = await hal.locomotion.getPose();
    expect(pose.position.x).toBeCloseTo(-1.5, 2);
    expect(pose.position.y).toBeCloseTo(0.3, 2);
    await hal.cleanup();

    // The endpoint got the HAL's tools in OpenAI format, the key and the model.
    const first = s.requests[0]!;
    expect(first.headers['authorization']).toBe('Bearer sk-test');
    expect(first.body.model).toBe('test-tool-model');
    const names = first.body.tools?.map((t) => t.function.name) ?? [];
    expect(names).toEqual(expect.arrayContaining(['move_forward', 'rotate', 'get_pose', 'stop']));
    expect(first.body.messages?.map((m) => m.role)).toEqual(['system', 'user']);

    // Each tool result went back as a tool message answering its call; the frame as an image in
    // a user message after the turn's tool messages.
    const last = s.requests[4]!.body.messages!;
    const roles = last.map((m) => m.role);
    expect(roles.slice(-4)).toEqual(['assistant', 'tool', 'tool', 'user']);
    const moved = JSON.parse(String(last.at(-3)?.content)) as { success: boolean };
    expect(moved.success).toBe(true);
    const image = last.at(-1)?.content as { type: string; image_url?: { url: string } }[];
    expect(image.find((p) => p.type === 'image_url')?.image_url?.url).toMatch(
      /^data:image\/jpeg;base64,\/9j\//,
    );

    // The events tell the story in order.
    expect(events.filter((e) => e.type === 'step_started')).toHaveLength(5);
    expect(events.filter((e) => e.type === 'tool_call').map((e) => e.name)).toEqual([
      'get_pose',
      'move_forward',
      'rotate',
      'move_forward',
      'capture_frame',
    ]);
    const results = events.filter((e) => e.type === 'tool_result');
    expect(results.every((e) => !e.isError)).toBe(true);
    expect(results.at(-1)).toMatchObject({ name: 'capture_frame', image: true });
    expect(events[0]).toMatchObject({ type: 'step_started', step: 1 });
    expect(events.at(-1)).toMatchObject({ type: 'done', reason: 'completed', steps: 5 });
  });

  it('feeds malformed arguments back as an error the model recovers from, and nothing moves', async () => {
    const s = await serve([
      { content: null, toolCalls: [{ name: 'move_forward', arguments: '{"distanceCm": 20' }] },
      { content: null, toolCalls: [call('move_forward', { distanceCm: 'far' })] },
      { content: null, toolCalls: [call('fly', { altitude: 3 })] },
      { content: null, toolCalls: [call('move_forward', { distanceCm: 20 })] },
      { content: 'Moved 20 cm.' },
    ]);
    const hal = await simulator();
    const { events, onEvent } = recorder();
    const outcome = await runAgent({
      goal: 'Move forward 20 cm.',
      hal,
      endpoint: endpoint(s),
      onEvent,
    });
    expect(outcome.reason).toBe('completed');
    const results = events.filter((e) => e.type === 'tool_result');
    expect(results.map((e) => e.isError)).toEqual([true, true, true, false]);
    expect(results[0]?.code).toBe('BAD_ARGUMENTS');
    expect(results[2]?.code).toBe('UNKNOWN_TOOL');
    // The model saw each error as the answer to its call.
    const second = s.requests[1]!.body.messages!.at(-1)!;
    expect(second).toMatchObject({ role: 'tool', tool_call_id: 'call_1_0' });
    expect(String(second.content)).toContain('BAD_ARGUMENTS');
    // Only the corrected call moved the robot: 20 cm, not more.
    expect((await hal.locomotion.getPose()).position.x).toBeCloseTo(-1.6, 2);
    await hal.cleanup();
  });

  it('ends with reason refused when the model refuses, and stops the robot', async () => {
    const s = await serve([{ refusal: 'I will not drive the robot into people.' }]);
    const hal = await simulator();
    const { events, onEvent } = recorder();
    const outcome = await runAgent({
      goal: 'Drive into the crowd.',
      hal,
      endpoint: endpoint(s),
      onEvent,
    });
    expect(outcome).toMatchObject({
      reason: 'refused',
      steps: 1,
      text: 'I will not drive the robot into people.',
    });
    expect(events.filter((e) => e.type === 'tool_call').map((e) => e.name)).toEqual(['stop']);
    expect((await hal.locomotion.getPose()).position.x).toBeCloseTo(-1.8, 3);
    await hal.cleanup();
  });
});
