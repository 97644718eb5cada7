import { SimulationHAL } from '@hal/simulation';
import type { HardwareAbstractionLayer } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { createToolExecutor } from './executor.js';
import { callTimeoutMs } from './timeouts.js';

async function simulated(): Promise<SimulationHAL> {
  const hal = new SimulationHAL();
  await hal.initialize();
  return hal;
}

const x = async (hal: HardwareAbstractionLayer) => (await hal.locomotion.getPose()).position.x;

describe('createToolExecutor', () => {
  it('answers an unknown tool with UNKNOWN_TOOL and the list of tools, without throwing', async () => {
    const run = createToolExecutor(await simulated());
    const result = await run.execute({ name: 'fly', arguments: '{}' });
    expect(result).toMatchObject({ isError: true, code: 'UNKNOWN_TOOL' });
    expect(result.content[0]).toMatchObject({
      type: 'text',
      text: expect.stringContaining('move_forward'),
    });
  });

  it('answers malformed JSON and non-object arguments with BAD_ARGUMENTS, and nothing moves', async () => {
    const hal = await simulated();
    const run = createToolExecutor(hal);
    for (const args of ['{"distanceCm": 10', '[10]', '10', 'null']) {
      const result = await run.execute({ name: 'move_forward', arguments: args });
      expect(result, args).toMatchObject({ isError: true, code: 'BAD_ARGUMENTS' });
    }
    expect(await x(hal)).toBe(0);
  });

  it("refuses arguments outside the robot's limits with the HAL's code and message, and nothing moves", async () => {
    const hal = await simulated();
    const run = createToolExecutor(hal);
    const result = await run.execute({ name: 'move_forward', arguments: { distanceCm: 500 } });
    expect(result).toMatchObject({ isError: true, code: 'RANGE_EXCEEDED' });
    expect(result.content[0]).toMatchObject({ text: expect.stringContaining('at most 188.4') });
    const missing = await run.execute({ name: 'rotate', arguments: { direction: 'left' } });
    expect(missing).toMatchObject({ isError: true, code: 'INVALID_PARAMETER' });
    expect(await x(hal)).toBe(0);
  });

  it('runs a motion and answers its result as JSON text and structured data', async () => {
    const hal = await simulated();
    const result = await createToolExecutor(hal).execute({
      name: 'move_forward',
      arguments: '{"distanceCm":20}',
    });
    expect(result.isError).toBe(false);
    expect(result.structured).toMatchObject({ success: true, mode: 'simulation' });
    expect(JSON.parse((result.content[0] as { text: string }).text)).toMatchObject({
      success: true,
    });
    expect(await x(hal)).toBeCloseTo(0.2, 2);
  });

  it('answers a read with its value, and a HAL failure as an error result with its code', async () => {
    const hal = await simulated();
    const run = createToolExecutor(hal);
    expect(
      (await run.execute({ name: 'get_pose', arguments: undefined })).structured,
    ).toMatchObject({
      position: { x: 0, y: 0 },
    });
    expect((await run.execute({ name: 'is_emergency_stopped', arguments: '' })).structured).toEqual(
      {
        emergencyStopped: false,
      },
    );
    await hal.cleanup();
    expect(await run.execute({ name: 'get_pose', arguments: {} })).toMatchObject({
      isError: true,
      code: 'NOT_READY',
    });
  });

  it('returns a camera frame as JPEG image content', async () => {
    const result = await createToolExecutor(await simulated()).execute({
      name: 'capture_frame',
      arguments: {},
    });
    const image = result.content.find((c) => c.type === 'image');
    expect(image).toMatchObject({ type: 'image', mimeType: 'image/jpeg' });
    const bytes = Buffer.from((image as { data: string }).data, 'base64');
    expect([bytes[0], bytes[1]]).toEqual([0xff, 0xd8]);
    expect(result.structured).toEqual({ frame: 'image/jpeg', bytes: expect.any(Number) });
  });
});

describe('timeouts', () => {
  function stalled(sim: SimulationHAL, stops: string[]): HardwareAbstractionLayer {
    const never = () => new Promise<never>(() => undefined);
    return {
      mode: 'simulation',
      locomotion: {
        ...sim.locomotion,
        getPose: () => sim.locomotion.getPose(),
        moveForward: never,
        stop: async () => {
          stops.push('stop');
          return sim.locomotion.stop();
        },
      },
      vision: { ...sim.vision, captureFrame: never },
      communication: sim.communication,
      safety: sim.safety,
      initialize: () => sim.initialize(),
      cleanup: () => sim.cleanup(),
      isReady: () => true,
      getDeviceInfo: () => sim.getDeviceInfo(),
    };
  }

  it('answers TIMEOUT when a read does not answer in time', async () => {
    const run = createToolExecutor(stalled(await simulated(), []), { timeoutMs: 50 });
    const started = Date.now();
    const result = await run.execute({ name: 'capture_frame', arguments: {} });
    expect(result).toMatchObject({ isError: true, code: 'TIMEOUT' });
    expect(Date.now() - started).toBeLessThan(5_000);
  });

  it('stops the wheels of a motion that does not finish in time', async () => {
    const stops: string[] = [];
    const run = createToolExecutor(stalled(await simulated(), stops), { timeoutMs: 50 });
    const result = await run.execute({ name: 'move_forward', arguments: { distanceCm: 1 } });
    expect(result).toMatchObject({ isError: true, code: 'TIMEOUT' });
    expect(stops).toEqual(['stop']);
  });

  it("gives a motion the base timeout plus twice its profile's duration", () => {
    expect(callTimeoutMs(10_000, undefined)).toBe(10_000);
    expect(callTimeoutMs(10_000, 40_000)).toBe(90_000);
    expect(callTimeoutMs(10_000, Infinity)).toBe(10_000);
  });
});
