import { SimulationHAL } from '@hal/simulation';
import { describe, expect, it } from 'vitest';
import { createToolExecutor } from './executor.js';
import type { Leash } from './leash.js';

async function leashed(leash: Leash, now?: () => number) {
  const hal = new SimulationHAL();
  await hal.initialize();
  const run = createToolExecutor(hal, { leash, ...(now === undefined ? {} : { now }) });
  const x = async () => (await hal.locomotion.getPose()).position.x;
  return { hal, run, x };
}

describe('the leash', () => {
  it('denies a call the approval hook denies, with its reason, and nothing moves', async () => {
    const { run, x } = await leashed({ approve: () => ({ allow: false, reason: 'not now' }) });
    const result = await run.execute({ name: 'move_forward', arguments: { distanceCm: 10 } });
    expect(result).toMatchObject({ isError: true, code: 'DENIED' });
    expect(result.content[0]).toMatchObject({ text: expect.stringContaining('not now') });
    expect(await x()).toBe(0);
  });

  it('denies a call when the approval hook throws, and nothing moves', async () => {
    const { run, x } = await leashed({
      approve: () => {
        throw new Error('hook broke');
      },
    });
    const result = await run.execute({ name: 'move_forward', arguments: { distanceCm: 10 } });
    expect(result).toMatchObject({ isError: true, code: 'DENIED' });
    expect(result.content[0]).toMatchObject({ text: expect.stringContaining('hook broke') });
    expect(await x()).toBe(0);
  });

  it('runs the arguments the approval hook changed, validated again', async () => {
    const asked: unknown[] = [];
    const { run, x } = await leashed({
      approve: ({ tool, args }) => {
        asked.push([tool.name, args]);
        return { allow: true, args: { distanceCm: 5 } };
      },
    });
    await run.execute({ name: 'move_forward', arguments: { distanceCm: 50 } });
    expect(asked).toEqual([['move_forward', { distanceCm: 50 }]]);
    expect(await x()).toBeCloseTo(0.05, 2);
    const bad = await leashed({ approve: () => ({ allow: true, args: { distanceCm: -1 } }) });
    expect(
      await bad.run.execute({ name: 'move_forward', arguments: { distanceCm: 5 } }),
    ).toMatchObject({
      code: 'RANGE_EXCEEDED',
    });
  });

  it('caps the distance of one call: straight moves, moveTo from the current pose, and endless drives', async () => {
    const { run, x } = await leashed({ maxDistanceM: 0.3 });
    expect(
      await run.execute({ name: 'move_forward', arguments: { distanceCm: 50 } }),
    ).toMatchObject({ code: 'LEASH_DISTANCE' });
    expect(
      (await run.execute({ name: 'move_forward', arguments: { distanceCm: 20 } })).isError,
    ).toBe(false);
    expect(await x()).toBeCloseTo(0.2, 2);
    // 0.2 m done; a point 0.45 m away from here is refused, one 0.25 m away is not
    expect(
      await run.execute({ name: 'move_to', arguments: { x: 0.65, y: 0, z: 0 } }),
    ).toMatchObject({ code: 'LEASH_DISTANCE' });
    expect(
      (await run.execute({ name: 'move_to', arguments: { x: 0.45, y: 0, z: 0 } })).isError,
    ).toBe(false);
    expect(
      await run.execute({ name: 'drive', arguments: { left: 100, right: 100 } }),
    ).toMatchObject({ code: 'LEASH_DISTANCE' });
  });

  it('caps the speed of one call', async () => {
    const { run } = await leashed({ maxSpeedMPerS: 0.02 });
    expect(
      await run.execute({ name: 'move_to', arguments: { x: 0.1, y: 0, z: 0, speed: 0.04 } }),
    ).toMatchObject({ code: 'LEASH_SPEED' });
    expect(await run.execute({ name: 'move_forward', arguments: { distanceCm: 5 } })).toMatchObject(
      { code: 'LEASH_SPEED' },
    );
    expect(
      (await run.execute({ name: 'move_to', arguments: { x: 0.05, y: 0, z: 0, speed: 0.02 } }))
        .isError,
    ).toBe(false);
    expect(
      await run.execute({ name: 'drive', arguments: { left: 255, right: 255, durationMs: 100 } }),
    ).toMatchObject({ code: 'LEASH_SPEED' });
    expect(
      (await run.execute({ name: 'drive', arguments: { left: 100, right: 100, durationMs: 100 } }))
        .isError,
    ).toBe(false);
  });

  it('refuses a motion that would end outside the geofence, from the current pose', async () => {
    const { run, x, hal } = await leashed({
      geofence: { minX: -0.5, maxX: 0.5, minY: -0.5, maxY: 0.5 },
    });
    expect(
      (await run.execute({ name: 'move_forward', arguments: { distanceCm: 40 } })).isError,
    ).toBe(false);
    const out = await run.execute({ name: 'move_forward', arguments: { distanceCm: 20 } });
    expect(out).toMatchObject({ code: 'LEASH_GEOFENCE' });
    expect(out.content[0]).toMatchObject({ text: expect.stringContaining('(0.6, 0)') });
    expect(await x()).toBeCloseTo(0.4, 2);
    expect(await run.execute({ name: 'move_to', arguments: { x: 0, y: 0.8, z: 0 } })).toMatchObject(
      { code: 'LEASH_GEOFENCE' },
    );
    expect(
      await run.execute({ name: 'drive', arguments: { left: 100, right: 100 } }),
    ).toMatchObject({ code: 'LEASH_GEOFENCE' });
    // turning around in place and driving back in are allowed
    expect(
      (await run.execute({ name: 'rotate', arguments: { direction: 'left', degrees: 180 } }))
        .isError,
    ).toBe(false);
    expect(
      (await run.execute({ name: 'move_forward', arguments: { distanceCm: 60 } })).isError,
    ).toBe(false);
    expect((await hal.locomotion.getPose()).position.x).toBeCloseTo(-0.2, 1);
  });

  it('plans a drive back behind the robot, and points a straight drive over the speed cap to move_to', async () => {
    const { run, x } = await leashed({
      geofence: { minX: -0.3, maxX: 0.5, minY: -0.5, maxY: 0.5 },
    });
    const out = await run.execute({ name: 'move_backward', arguments: { distanceCm: 40 } });
    expect(out).toMatchObject({ code: 'LEASH_GEOFENCE' });
    expect(out.content[0]).toMatchObject({ text: expect.stringContaining('(-0.4, 0)') });
    expect(await x()).toBe(0);
    expect(
      (await run.execute({ name: 'move_backward', arguments: { distanceCm: 20 } })).isError,
    ).toBe(false);
    expect(await x()).toBeCloseTo(-0.2, 2);
    const slow = await leashed({ maxSpeedMPerS: 0.02 });
    const back = await slow.run.execute({ name: 'move_backward', arguments: { distanceCm: 5 } });
    expect(back).toMatchObject({ code: 'LEASH_SPEED' });
    expect(back.content[0]).toMatchObject({
      text: expect.stringContaining('use move_to with a speed'),
    });
    const point = await slow.run.execute({
      name: 'move_to',
      arguments: { x: 0.1, y: 0, z: 0, speed: 0.04 },
    });
    expect(point).toMatchObject({ code: 'LEASH_SPEED' });
    expect(point.content[0]).not.toMatchObject({ text: expect.stringContaining('use move_to') });
  });

  it('limits the rate of calls, and lets calls through again once the window has passed', async () => {
    let now = 0;
    const { run } = await leashed({ rateLimit: { calls: 2, perMs: 1000 } }, () => now);
    expect((await run.execute({ name: 'get_pose', arguments: {} })).isError).toBe(false);
    expect((await run.execute({ name: 'get_pose', arguments: {} })).isError).toBe(false);
    expect(await run.execute({ name: 'get_pose', arguments: {} })).toMatchObject({
      code: 'LEASH_RATE_LIMIT',
    });
    expect((await run.execute({ name: 'stop', arguments: {} })).isError).toBe(false);
    now = 1000;
    expect((await run.execute({ name: 'get_pose', arguments: {} })).isError).toBe(false);
  });

  it('never blocks stop or emergency_stop: no approval asked, no rate limit, any arguments', async () => {
    const asked: string[] = [];
    const { run, hal } = await leashed({
      approve: ({ tool }) => {
        asked.push(tool.name);
        return { allow: false, reason: 'no' };
      },
      rateLimit: { calls: 1, perMs: 60_000 },
      maxDistanceM: 0,
      geofence: { minX: 5, maxX: 6, minY: 5, maxY: 6 },
    });
    await run.execute({ name: 'get_pose', arguments: {} });
    expect((await run.execute({ name: 'stop', arguments: '{oops' })).isError).toBe(false);
    const estop = await run.execute({ name: 'emergency_stop', arguments: '{not json' });
    expect(estop.isError).toBe(false);
    expect(hal.safety.isEmergencyStopped()).toBe(true);
    expect(asked).toEqual(['get_pose']); // asked for the read, never for the stops
  });

  it('passes any reason to the emergency stop, and stops even when the HAL refuses the reason', async () => {
    const { run, hal } = await leashed({});
    expect(
      (await run.execute({ name: 'emergency_stop', arguments: { reason: 'cliff ahead' } })).isError,
    ).toBe(false);
    expect(hal.safety.getSafetyStatus().emergencyStopReason ?? '').toContain('cliff ahead');
    await hal.safety.resetEmergencyStop();
    const long = await run.execute({
      name: 'emergency_stop',
      arguments: { reason: 'x'.repeat(5000) },
    });
    expect(long.isError).toBe(false);
    expect(hal.safety.isEmergencyStopped()).toBe(true);
    await hal.safety.resetEmergencyStop();
    expect((await run.execute({ name: 'emergency_stop', arguments: { reason: 42 } })).isError).toBe(
      false,
    );
    expect(hal.safety.isEmergencyStopped()).toBe(true);
  });
});
