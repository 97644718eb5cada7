import { isHalError } from '@hal/types';
import type { Logger } from '@hal/types';
import { afterEach, describe, expect, it } from 'vitest';
import { SimulationHAL } from './simulation-hal.js';
import type { CommunicationEvent } from './events.js';
import { World } from '../world.js';

const hals: SimulationHAL[] = [];
async function ready(hal: SimulationHAL): Promise<SimulationHAL> {
  hals.push(hal);
  await hal.initialize();
  return hal;
}

afterEach(async () => {
  for (const hal of hals.splice(0)) await hal.cleanup();
});

describe('SimulationHAL', () => {
  describe('.fromConfig', () => {
    it('builds a HAL from the shared HALConfig, joining the given world', async () => {
      const world = new World({ map: 'maze' });
      const hal = await ready(
        SimulationHAL.fromConfig({
          mode: 'simulation',
          deviceId: 'sim-7',
          simulator: world,
          robot: { maxSpeedStepsPerS: 512 },
          capabilities: ['vision.camera:v1.0'],
        }),
      );
      expect(hal.world).toBe(world);
      expect(hal.robot.config.maxSpeedStepsPerS).toBe(512);
      const info = hal.getDeviceInfo();
      expect(info.id).toBe('sim-7');
      expect(info.capabilities).toContain('vision.camera:v1.0');
      expect(info.capabilities).not.toContain('vision.range:v1.0');
    });

    it('refuses a physical configuration with INVALID_PARAMETER naming "mode"', () => {
      let error: unknown;
      try {
        SimulationHAL.fromConfig({ mode: 'physical', deviceId: 'x' });
      } catch (e) {
        error = e;
      }
      expect(isHalError(error) && error.code).toBe('INVALID_PARAMETER');
      expect(String(error)).toContain('"mode"');
    });
  });

  describe('#moveForward', () => {
    it('fails with COLLISION and the contact point when the robot drives into an obstacle', async () => {
      const world = new World({
        map: {
          name: 'wall ahead',
          obstacles: [{ kind: 'box', x: 0.3, y: 0, width: 0.1, depth: 1 }],
        },
      });
      const hal = await ready(new SimulationHAL({ world }));
      const result = await hal.locomotion.moveForward(50);
      expect(result.success).toBe(false);
      expect(result.code).toBe('COLLISION');
      const contact = result.details?.['contact'] as { point: { x: number } };
      // where the robot felt it; not what it was (a bump cannot tell)
      expect(contact).toEqual({ point: { x: expect.closeTo(0.25, 6), y: expect.closeTo(0, 6) } });
      const pose = await hal.locomotion.getPose();
      expect(pose.position.x).toBeCloseTo(0.25 - 0.07, 3);
      expect(pose.velocity.linear).toBe(0);
    });

    it('names the device and where it touched something in the COLLISION message', async () => {
      const world = new World({
        map: {
          name: 'wall ahead',
          arena: { width: 1, height: 1 },
          obstacles: [{ kind: 'box', x: 0.3, y: 0, width: 0.1, depth: 1 }],
        },
      });
      const hal = await ready(new SimulationHAL({ world, deviceId: 'cube-7' }));
      const obstacle = await hal.locomotion.moveForward(50);
      expect(obstacle.error).toMatch(/^cube-7 touched something at \(0\.250, 0\.000\) m/);
      const boxed = new World({ map: { name: 'small', arena: { width: 1, height: 1 } } });
      const alone = await ready(new SimulationHAL({ world: boxed, deviceId: 'cube-7' }));
      const edge = await alone.locomotion.moveForward(100);
      expect(edge.error).toMatch(/^cube-7 touched something at /);
    });

    it('reports the contact where its drifted odometry puts it, not where the world has it', async () => {
      const world = new World({ map: { name: 'small', arena: { width: 2, height: 2 } } });
      const hal = await ready(
        new SimulationHAL({ world, bodyError: { odometryNoisePct: 10, seed: 4 } }),
      );
      await hal.locomotion.rotate('left', 30);
      expect((await hal.locomotion.moveForward(60)).success).toBe(true);
      const result = await hal.locomotion.moveForward(60);
      expect(result.code).toBe('COLLISION');
      const felt = (result.details?.['contact'] as { point: { x: number; y: number } }).point;
      const truth = hal.world.robots[0]?.motion?.contact?.point ?? { x: NaN, y: NaN };
      const believed = hal.robot.reportedPose;
      const actual = { x: hal.robot.x, y: hal.robot.y };
      // the same distance from the body in both frames, but not the same place
      expect(Math.hypot(felt.x - believed.x, felt.y - believed.y)).toBeCloseTo(
        Math.hypot(truth.x - actual.x, truth.y - actual.y),
        9,
      );
      expect(Math.hypot(felt.x - truth.x, felt.y - truth.y)).toBeGreaterThan(0.01);
      expect(result.error).not.toMatch(/arena|wall|edge/);
    });

    it('stamps results with the simulated clock: a 10 cm move takes its planned 4121 ms', async () => {
      const hal = await ready(new SimulationHAL());
      const result = await hal.locomotion.moveForward(10);
      expect(result.data?.['leftSteps']).toBe(2172);
      expect(result.executionTime).toBeGreaterThanOrEqual(4120);
      expect(result.executionTime).toBeLessThanOrEqual(4122);
    });
  });

  describe('#moveTo', () => {
    it('goes further than one command allows in equal straight parts and arrives', async () => {
      const hal = await ready(new SimulationHAL());
      const result = await hal.locomotion.moveTo(-2.2, 0.1, 0);
      expect(result.success, JSON.stringify(result)).toBe(true);
      const pose = await hal.locomotion.getPose();
      expect(pose.position.x).toBeCloseTo(-2.2, 2);
      expect(pose.position.y).toBeCloseTo(0.1, 2);
    });

    it('refuses a target outside the workspace with RANGE_EXCEEDED and does not move', async () => {
      const hal = await ready(new SimulationHAL());
      const result = await hal.locomotion.moveTo(80, 0, 0);
      expect(result.code).toBe('RANGE_EXCEEDED');
      expect(hal.robot.leftSteps).toBe(0);
    });

    it("refuses a target beyond the arena's walls with RANGE_EXCEEDED naming the limit, and does not move", async () => {
      const hal = await ready(new SimulationHAL()); // the empty map: a 5 x 5 m arena
      const result = await hal.locomotion.moveTo(10, 10, 0);
      expect(result.code).toBe('RANGE_EXCEEDED');
      expect(result.error).toContain('outside the 5 x 5 m arena');
      expect(result.error).toContain('x within -2.43..2.43 m');
      expect(result.details).toMatchObject({ parameter: 'x', limits: { x: [-2.43, 2.43] } });
      expect([hal.robot.leftSteps, hal.robot.rightSteps]).toEqual([0, 0]);
      // just inside the walls is still a target
      expect((await hal.locomotion.moveTo(2.4, 0, 0)).success).toBe(true);
    });
  });

  describe('#drive', () => {
    it('without a duration returns at once and keeps driving until stop()', async () => {
      const hal = await ready(new SimulationHAL());
      const started = await hal.locomotion.drive(255, 255);
      expect(started.data?.['running']).toBe(true);
      hal.world.advance(2_000_000);
      expect(hal.robot.running).toBe(true);
      const stopped = await hal.locomotion.stop();
      expect(stopped.data?.['stopped']).toBe(true);
      expect((await hal.locomotion.getPose()).position.x).toBeGreaterThan(0.02);
    });

    it('maps power to steps/s as trunc(power / 255 * maxSpeed)', async () => {
      const hal = await ready(new SimulationHAL());
      const result = await hal.locomotion.drive(100, -37);
      expect(result.data).toMatchObject({ leftSps: 401, rightSps: -148 });
    });

    it('stops by itself when the host goes silent for the host timeout', async () => {
      const hal = await ready(new SimulationHAL({ robot: { hostTimeoutMs: 1000 } }));
      await hal.locomotion.drive(200, 200);
      hal.simulateHostSilence(true);
      hal.world.advance(1_500_000);
      expect(hal.robot.running).toBe(false);
      expect(hal.robot.motion?.outcome).toBe('host_timeout');
      expect(hal.safety.getSafetyStatus().errors[0]).toContain('host_timeout');
      expect(hal.safety.isEmergencyStopped()).toBe(false);
    });
  });

  describe('interruptions (manual clock)', () => {
    it('fails a running motion with INTERRUPTED when a new motion replaces it', async () => {
      const hal = await ready(new SimulationHAL({ clock: 'manual' }));
      const first = hal.locomotion.moveForward(10);
      await Promise.resolve();
      hal.world.advance(1_000_000);
      const second = hal.locomotion.rotate('left', 10);
      const result = await first;
      expect(result.code).toBe('INTERRUPTED');
      expect(result.details?.['outcome']).toBe('replaced');
      hal.world.advance(5_000_000);
      expect((await second).success).toBe(true);
    });

    it('fails a running motion with INTERRUPTED on stop() and on an e-stop', async () => {
      const hal = await ready(new SimulationHAL({ clock: 'manual' }));
      const move = hal.locomotion.moveForward(10);
      hal.world.advance(500_000);
      await hal.locomotion.stop();
      expect((await move).details?.['outcome']).toBe('stopped');
      const again = hal.locomotion.moveForward(10);
      hal.world.advance(500_000);
      expect((await hal.safety.emergencyStop('test')).success).toBe(true);
      expect((await again).details?.['outcome']).toBe('estop');
      expect(hal.safety.getSafetyStatus().emergencyStopReason).toBe('test');
    });

    it('fails with TIMEOUT, and stops the robot, when nobody advances the clock', async () => {
      const hal = await ready(new SimulationHAL({ clock: 'manual', manualTimeoutMs: 20 }));
      const result = await hal.locomotion.moveForward(10);
      expect(result.code).toBe('TIMEOUT');
      expect(hal.robot.running).toBe(false);
    });
  });

  describe('realtime clock', () => {
    it('finishes motions driven by the real-time ticker it started', async () => {
      const hal = await ready(new SimulationHAL({ clock: 'realtime', realtimeSpeed: 40 }));
      expect(hal.world.realtimeSpeed).toBe(40);
      const result = await hal.locomotion.moveForward(2);
      expect(result.success).toBe(true);
      await hal.cleanup();
      expect(hal.world.realtimeSpeed).toBe(0);
    });

    it('keeps waiting when the speed is lowered mid-motion (timeouts are in simulated time)', async () => {
      const hal = await ready(new SimulationHAL({ clock: 'realtime', realtimeSpeed: 40 }));
      const move = hal.locomotion.moveForward(1);
      hal.world.startRealtime({ speed: 1 });
      const result = await move;
      expect(result.success, JSON.stringify(result)).toBe(true);
    });

    it('fails with TIMEOUT when the ticker stops and the clock stalls', async () => {
      const hal = await ready(
        new SimulationHAL({ clock: 'realtime', realtimeSpeed: 1, stallTimeoutMs: 30 }),
      );
      hal.world.stopRealtime();
      const result = await hal.locomotion.moveForward(1);
      expect(result.code).toBe('TIMEOUT');
      expect(hal.robot.running).toBe(false);
    });
  });

  describe('vision', () => {
    it('captures a JPEG data URL and reads range sensors marked as simulated', async () => {
      const hal = await ready(new SimulationHAL({ world: new World({ map: 'obstacles' }) }));
      const frame = await hal.vision.captureFrame();
      expect(frame.startsWith('data:image/jpeg;base64,/9j/')).toBe(true);
      const ranges = await hal.vision.getDistanceSensors();
      expect(ranges.source).toBe('simulation');
      expect(ranges.front).toBeCloseTo(1.8 - 0.9 - 0.2 - 0.07, 6);
      await expect(hal.vision.getLineSensors()).rejects.toSatisfy(
        (e: unknown) => isHalError(e) && e.code === 'NOT_IMPLEMENTED',
      );
    });

    it('reports what it lacks honestly when a feature is switched off', async () => {
      const hal = await ready(new SimulationHAL({ features: { camera: false, imu: false } }));
      expect(hal.getDeviceInfo().capabilities).not.toContain('vision.camera:v1.0');
      await expect(hal.vision.captureFrame()).rejects.toSatisfy(
        (e: unknown) => isHalError(e) && e.code === 'NOT_IMPLEMENTED',
      );
      expect((await hal.vision.getIMU()).source).toBe('odometry');
    });
  });

  describe('communication', () => {
    it('emits LED, log and (with a speaker) speech events for a UI', async () => {
      const hal = await ready(new SimulationHAL({ features: { speaker: true } }));
      const seen: CommunicationEvent[] = [];
      hal.events.on('communication', (e) => seen.push(e));
      expect((await hal.communication.setLED(0, 255, 0, 'blink')).success).toBe(true);
      hal.communication.log('hello', 'warn');
      expect((await hal.communication.speak('hi there')).success).toBe(true);
      expect(seen.map((e) => e.type)).toEqual(['led', 'log', 'speak']);
      expect(hal.robot.led).toEqual({ r: 0, g: 255, b: 0, pattern: 'blink' });
      expect(hal.logs).toEqual(['hello']);
    });

    it('records nothing for a refused log call, reports it to the logger and never throws', async () => {
      const warnings: string[] = [];
      const logger: Logger = {
        log: (level, _namespace, message) => {
          if (level === 'warn') warnings.push(message);
        },
      };
      const hal = new SimulationHAL({ logger });
      const seen: CommunicationEvent[] = [];
      hal.events.on('communication', (e) => seen.push(e));
      expect(() => hal.communication.log('too early')).not.toThrow();
      await ready(hal);
      expect(() => hal.communication.log('x', 'bogus' as 'info')).not.toThrow();
      expect(() => hal.communication.log({ toString: null } as unknown as string)).not.toThrow();
      hal.communication.log('kept', 'warn');
      expect(hal.logs).toEqual(['kept']);
      expect(seen).toHaveLength(1);
      expect(warnings).toEqual([
        expect.stringMatching(/^log refused: log: the HAL is not initialised/),
        expect.stringContaining('"level" must be one of'),
        expect.stringContaining('"message"'),
        'kept',
      ]);
    });
  });

  describe('many robots', () => {
    it('drives two HALs in one world without them passing through each other', async () => {
      const world = new World();
      const a = await ready(new SimulationHAL({ world, start: { x: -0.2, y: 0, yaw: 0 } }));
      const b = await ready(new SimulationHAL({ world, start: { x: 0.2, y: 0, yaw: Math.PI } }));
      await b.locomotion.drive(0, 0);
      const result = await a.locomotion.moveForward(40);
      expect(result.code).toBe('COLLISION');
      // a bump does not say whom it touched
      expect(Object.keys(result.details?.['contact'] as object)).toEqual(['point']);
      expect(result.error).toMatch(new RegExp(`^${a.getDeviceInfo().id} touched something at `));
      expect(result.error).not.toContain(b.getDeviceInfo().id);
      expect(a.world.robots.find((r) => r.id === a.robot.id)?.motion?.contact).toMatchObject({
        role: 'robot',
        robotId: b.robot.id,
      });
      expect(b.getDeviceInfo().id).not.toBe(b.robot.id);
    });
  });
});
