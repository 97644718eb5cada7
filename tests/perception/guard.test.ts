// The guard over a SimulationHAL: it stops forward motions before what the camera (or the range
// sensors) see ahead, answers OBSTACLE_AHEAD with the distance, and never holds a stop.
import { guardHal } from '@hal/perception';
import type { HardwareAbstractionLayer } from '@hal/types';
import { afterEach, describe, expect, it } from 'vitest';
import { facingWall, hangingCamera, keptLogger } from './guard-fixture.js';

const CAMERA_ONLY = { features: { rangeSensors: false } } as const;
const opened: HardwareAbstractionLayer[] = [];

async function ready<T extends HardwareAbstractionLayer>(hal: T): Promise<T> {
  await hal.initialize();
  opened.push(hal);
  return hal;
}

afterEach(async () => {
  await Promise.all(opened.splice(0).map((hal) => hal.cleanup()));
});

describe('guardHal', () => {
  describe('#moveForward, seeing with the camera', () => {
    it('stops before a wall 0.5 m ahead and answers OBSTACLE_AHEAD with the distance it saw', async () => {
      const { sim, gap } = facingWall(0.5, CAMERA_ONLY);
      const guarded = await ready(guardHal(sim));
      const result = await guarded.locomotion.moveForward(100);
      expect(result.success).toBe(false);
      expect(result.code).toBe('OBSTACLE_AHEAD');
      expect(result.details).toMatchObject({ source: 'camera', when: 'during' });
      expect(result.error).toMatch(
        /^moveForward: stopped after 0\.\d+ m: an obstacle 0\.\d+ m ahead \(camera\); the guard stops 0\.1 m short of what it sees$/,
      );
      const seen = result.details?.['distanceM'] as number;
      expect(gap()).toBeGreaterThan(0.05);
      expect(gap()).toBeLessThan(0.15);
      // what it saw is where the wall is
      expect(Math.abs(seen - gap())).toBeLessThan(0.02);
      expect(result.details?.['travelledM']).toBeCloseTo(0.5 - gap(), 2);
      const status = guarded.status();
      expect(status).toMatchObject({ sees: 'camera', stops: 1, refused: 0, standoffM: 0.1 });
      expect(status.lastStop).toMatchObject({ motion: 'moveForward', source: 'camera' });
    });

    it('refuses at once a motion starting 0.08 m from a wall: nothing moves', async () => {
      const { sim, gap } = facingWall(0.08, CAMERA_ONLY);
      const guarded = await ready(guardHal(sim));
      const before = gap();
      const result = await guarded.locomotion.moveForward(50);
      expect(result.code).toBe('OBSTACLE_AHEAD');
      expect(result.details).toMatchObject({ when: 'before', travelledM: 0, source: 'camera' });
      expect(gap()).toBe(before);
      expect(sim.robot.x).toBe(0);
      expect(guarded.status()).toMatchObject({ stops: 1, refused: 1 });
    });

    it('lets a motion through that ends short of the wall, in one leg with its own result', async () => {
      const { sim, gap } = facingWall(1.0, CAMERA_ONLY);
      const guarded = await ready(guardHal(sim));
      const result = await guarded.locomotion.moveForward(30);
      expect(result.success).toBe(true);
      expect(result.data?.['legs']).toBeUndefined();
      expect(gap()).toBeCloseTo(0.7, 2);
    });

    it('drives in legs toward a far wall and stops within the stand-off of it', async () => {
      const { sim, gap } = facingWall(1.2, CAMERA_ONLY);
      const guarded = await ready(guardHal(sim));
      const result = await guarded.locomotion.moveForward(150);
      expect(result.code).toBe('OBSTACLE_AHEAD');
      expect(gap()).toBeGreaterThan(0.05);
      expect(gap()).toBeLessThan(0.15);
    });
  });

  describe('#moveTo and #drive', () => {
    it('moveTo a point behind a wall: turns to face it, then stops before the wall', async () => {
      const { sim, gap } = facingWall(0.4, {
        ...CAMERA_ONLY,
        start: { x: 0, y: 0, yaw: Math.PI / 2 },
      });
      const guarded = await ready(guardHal(sim));
      const result = await guarded.locomotion.moveTo(1.5, 0, 0);
      expect(result.code).toBe('OBSTACLE_AHEAD');
      expect(Math.abs(sim.robot.yaw)).toBeLessThan(0.05);
      expect(gap()).toBeGreaterThan(0.05);
      expect(gap()).toBeLessThan(0.15);
    });

    it('a timed drive forward stops before the wall', async () => {
      const { sim, gap } = facingWall(0.3, CAMERA_ONLY);
      const guarded = await ready(guardHal(sim));
      const result = await guarded.locomotion.drive(200, 200, 20_000);
      expect(result.code).toBe('OBSTACLE_AHEAD');
      expect(gap()).toBeGreaterThan(0.05);
      expect(gap()).toBeLessThan(0.15);
    });
  });

  describe('senses', () => {
    it('sees with the range sensors where the robot has them', async () => {
      const { sim, gap } = facingWall(0.5);
      const guarded = await ready(guardHal(sim));
      expect(await guarded.senses()).toBe('range');
      const result = await guarded.locomotion.moveForward(100);
      expect(result.code).toBe('OBSTACLE_AHEAD');
      expect(result.details?.['source']).toBe('range');
      expect(gap()).toBeGreaterThan(0.05);
      expect(gap()).toBeLessThan(0.15);
    });

    it('with no camera and no range sensors says once that it cannot guard, and lets motions through', async () => {
      const logger = keptLogger();
      const { sim } = facingWall(undefined, { features: { camera: false, rangeSensors: false } });
      const guarded = await ready(guardHal(sim, { logger }));
      expect((await guarded.locomotion.moveForward(10)).success).toBe(true);
      expect((await guarded.locomotion.moveForward(10)).success).toBe(true);
      const warnings = logger.entries.filter((e) => e.level === 'warn');
      expect(warnings).toHaveLength(1);
      expect(warnings[0]?.message).toMatch(/cannot see.*no camera and no range sensors/);
      expect(guarded.status()).toMatchObject({ sees: 'nothing', unguarded: 2 });
      expect(guarded.status().warning).toMatch(/cannot see/);
    });

    it('without the guard the robot drives into the wall (COLLISION)', async () => {
      const { sim } = facingWall(0.5, CAMERA_ONLY);
      await ready(sim);
      const result = await sim.locomotion.moveForward(100);
      expect(result.code).toBe('COLLISION');
    });
  });

  describe('what it never holds', () => {
    it('stop and the e-stop answer while the guard waits on a camera that never answers', async () => {
      const { sim } = facingWall(0.5, CAMERA_ONLY);
      await ready(sim);
      const { hal: hanging, hang } = hangingCamera(sim);
      const guarded = guardHal(hanging, { lookTimeoutMs: 1000 });
      expect(await guarded.senses()).toBe('camera');
      hang();
      const motion = guarded.locomotion.moveForward(50);
      const stopped = await guarded.locomotion.stop();
      expect(stopped.success).toBe(true);
      // the motion waiting on its look gives up once stopped, having moved nothing
      const estop = await guarded.safety.emergencyStop('test');
      expect(estop.success).toBe(true);
      expect(guarded.safety.isEmergencyStopped()).toBe(true);
      expect(sim.robot.x).toBe(0);
      await guarded.safety.resetEmergencyStop();
      const result = await motion;
      expect(result.code).toBe('INTERRUPTED');
      expect(sim.robot.x).toBe(0);
    });

    it('refuses rather than drive blind when a look times out: TIMEOUT, nothing moved', async () => {
      const { sim } = facingWall(undefined, CAMERA_ONLY);
      await ready(sim);
      const { hal: hanging, hang } = hangingCamera(sim);
      const guarded = guardHal(hanging, { lookTimeoutMs: 200 });
      expect(await guarded.senses()).toBe('camera');
      hang();
      const result = await guarded.locomotion.moveForward(50);
      expect(result.code).toBe('TIMEOUT');
      expect(result.details).toMatchObject({ guard: 'blind' });
      expect(sim.robot.x).toBe(0);
      expect(guarded.status().blindStops).toBe(1);
    });

    it('lets a reverse through unwatched, saying so once', async () => {
      const logger = keptLogger();
      const { sim } = facingWall(0.5, CAMERA_ONLY);
      const guarded = await ready(guardHal(sim, { logger }));
      expect((await guarded.locomotion.moveBackward(5)).success).toBe(true);
      expect((await guarded.locomotion.moveBackward(5)).success).toBe(true);
      expect(logger.entries.filter((e) => /behind/.test(e.message))).toHaveLength(1);
      expect(guarded.status().unguarded).toBe(2);
      const refusing = guardHal(sim, { reverse: 'refuse' });
      expect((await refusing.locomotion.moveBackward(5)).code).toBe('NOT_IMPLEMENTED');
    });

    it('passes a call the HAL refuses as the HAL answers it', async () => {
      const { sim } = facingWall(0.5, CAMERA_ONLY);
      const guarded = await ready(guardHal(sim));
      expect((await guarded.locomotion.moveForward(Number.NaN)).code).toBe('INVALID_PARAMETER');
      await guarded.safety.emergencyStop();
      expect((await guarded.locomotion.moveForward(10)).code).toBe('EMERGENCY_STOPPED');
      await guarded.safety.resetEmergencyStop();
    });
  });

  describe('on a clock that runs in real time', () => {
    it('stops before the wall, looking while each leg runs', async () => {
      const { sim, gap } = facingWall(0.3, { ...CAMERA_ONLY, clock: 'realtime', realtimeSpeed: 4 });
      const guarded = await ready(guardHal(sim));
      const result = await guarded.locomotion.moveForward(60);
      expect(result.code).toBe('OBSTACLE_AHEAD');
      expect(gap()).toBeGreaterThan(0.05);
      expect(gap()).toBeLessThan(0.15);
    });

    it('a drive with no end is watched until the robot is stopped before the wall', async () => {
      const { sim, gap } = facingWall(0.3, { ...CAMERA_ONLY, clock: 'realtime', realtimeSpeed: 4 });
      const guarded = await ready(guardHal(sim));
      const stops = new Promise((resolve) =>
        guarded.onEvent((e) => e.type === 'obstacle' && resolve(e)),
      );
      const started = await guarded.locomotion.drive(255, 255);
      expect(started.success).toBe(true);
      await expect(stops).resolves.toMatchObject({ stop: { motion: 'drive', when: 'during' } });
      // the stop was sent; the wheels are still
      await new Promise((resolve) => setTimeout(resolve, 300));
      expect(gap()).toBeGreaterThan(0.03);
      expect(gap()).toBeLessThan(0.15);
      expect(sim.robot.velocity().linear).toBe(0);
    });
  });
});
