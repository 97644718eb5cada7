import { PhysicalHAL } from '@hal/physical';
import { SimulationHAL } from '@hal/simulation';
import { HalError, HALToolResultSchema, isHalError, SafetyStatusSchema } from '@hal/types';
import type { HALToolResult } from '@hal/types';
import { describeHalContract } from '@hal/types/testing';
import { describe, expect, it, vi } from 'vitest';
import type { DivergenceEvent } from './hybrid-hal.js';
import { HybridHAL } from './hybrid-hal.js';
import { mergeSafetyStatus } from './safety.js';
import { hybridRig } from './testing.fixture.js';

describeHalContract('HybridHAL over the mock robot and a simulated twin', {
  create: () => hybridRig().hal,
  timeoutMs: 20_000,
});

function expectValid(result: HALToolResult): void {
  expect(HALToolResultSchema.safeParse(result).success, JSON.stringify(result)).toBe(true);
}

describe('HybridHAL', () => {
  describe('#moveForward', () => {
    it('returns the physical result stamped hybrid, with the twin summary and the divergence', async () => {
      const { hal, robot, twin } = hybridRig();
      await hal.initialize();
      const result = await hal.locomotion.moveForward(10);
      expectValid(result);
      expect(result).toMatchObject({ success: true, mode: 'hybrid' });
      expect(result.data).toMatchObject({
        leftSteps: 2172,
        rightSteps: 2172,
        twin: { success: true },
        divergence: { exceeded: false },
      });
      expect(robot.position).toEqual({ left: 2172, right: 2172 });
      expect((await twin.locomotion.getPose()).position.x).toBeCloseTo(0.1, 3);
      expect((await hal.locomotion.getPose()).position.x).toBeCloseTo(0.1, 3);
      expect(hal.getDivergence()?.positionM).toBeLessThan(0.001);
      await hal.cleanup();
    });

    it('succeeds when the twin fails, reporting the twin failure and the divergence it causes', async () => {
      // the twin believes one command may make at most 1000 steps: it refuses a 10 cm move
      const { hal } = hybridRig({ twin: { robot: { maxStepsPerCommand: 1000 } } });
      const events: DivergenceEvent[] = [];
      hal.onDivergence((event) => events.push(event));
      await hal.initialize();
      const result = await hal.locomotion.moveForward(10);
      expectValid(result);
      expect(result.success).toBe(true);
      expect(result.data?.['twin']).toEqual({ success: false, code: 'RANGE_EXCEEDED' });
      expect(result.data?.['divergence']).toMatchObject({ exceeded: true });
      expect(hal.getDivergence()?.positionM).toBeCloseTo(0.1, 3);
      expect(events).toHaveLength(1);
      expect(events[0]).toMatchObject({ call: 'moveForward', twin: { x: 0, y: 0 } });
      expect(events[0]?.physical.x).toBeCloseTo(0.1, 3);
      await hal.cleanup();
    });

    it('fails with the physical code when the physical move fails, even though the twin succeeded', async () => {
      const { hal, robot } = hybridRig();
      await hal.initialize();
      const moving = hal.locomotion.moveForward(50);
      await vi.waitFor(() => expect(robot.motionsStarted).toBe(1), { timeout: 5000 });
      const stopped = await hal.locomotion.stop();
      const result = await moving;
      expectValid(result);
      expect(stopped.success).toBe(true);
      expect(result).toMatchObject({ success: false, code: 'INTERRUPTED', mode: 'hybrid' });
      expect(result.data).toMatchObject({
        twin: { success: true },
        divergence: { exceeded: true },
      });
      await hal.cleanup();
    });
  });

  describe('validation', () => {
    it('refuses bad parameters once, before either robot is asked', async () => {
      const { hal, robot } = hybridRig();
      await hal.initialize();
      const before = robot.requests.length;
      const result = await hal.locomotion.rotate('left', Number.NaN);
      expect(result).toMatchObject({ success: false, code: 'INVALID_PARAMETER', mode: 'hybrid' });
      expect(result.error).toContain('"degrees"');
      expect(robot.requests.slice(before).filter((r) => r['cmd'] === 'rotate_deg')).toEqual([]);
      await hal.cleanup();
    });
  });

  describe('divergence', () => {
    it('compares what each robot did from where it started, so a twin may start elsewhere', async () => {
      const { hal } = hybridRig({ twin: { start: { x: 1, y: -1, yaw: Math.PI / 2 } } });
      await hal.initialize();
      await hal.locomotion.rotate('left', 45);
      await hal.locomotion.moveForward(8);
      const result = await hal.locomotion.moveTo(0.02, 0.1, 0);
      expect(result.success, JSON.stringify(result)).toBe(true);
      expect(hal.getDivergence()?.positionM).toBeLessThan(0.001);
      expect(hal.getDivergence()?.yawRad).toBeLessThan(0.001);
      await hal.cleanup();
    });

    it('reports a twin with larger wheels as exceeded after a timed drive, until unsubscribed', async () => {
      const { hal } = hybridRig({
        twin: { robot: { wheelDiameterCm: 6.6 } },
        hybrid: { twinGeometry: 'own' },
      });
      const listener = vi.fn<(event: DivergenceEvent) => void>();
      const unsubscribe = hal.onDivergence(listener);
      await hal.initialize();
      const result = await hal.locomotion.drive(255, 255, 5000);
      expect(result.success, JSON.stringify(result)).toBe(true);
      expect(result.data?.['divergence']).toMatchObject({ exceeded: true });
      expect(listener).toHaveBeenCalledTimes(1);
      unsubscribe();
      await hal.locomotion.stop();
      expect(listener).toHaveBeenCalledTimes(1);
      expect(await hal.measureDivergence()).toMatchObject({ exceeded: true });
      await hal.cleanup();
    });

    it('logs a listener that throws and still returns the result', async () => {
      const log = vi.fn();
      const { hal } = hybridRig({
        twin: { robot: { wheelDiameterCm: 6.6 } },
        hybrid: { logger: { log }, twinGeometry: 'own' },
      });
      hal.onDivergence(() => {
        throw new Error('listener broke');
      });
      await hal.initialize();
      expect((await hal.locomotion.drive(255, 255, 5000)).success).toBe(true);
      expect(log).toHaveBeenCalledWith('error', 'hal:hybrid', 'a divergence listener threw', {
        error: 'listener broke',
      });
      await hal.cleanup();
    });

    it('refuses a negative tolerance when it is made', () => {
      const { physical, twin } = hybridRig();
      expect(
        () => new HybridHAL({ physical, twin, divergence: { positionToleranceM: -1 } }),
      ).toThrow(/"positionToleranceM" must be a finite number >= 0/);
    });
  });

  describe('safety', () => {
    it('e-stops and latches both robots, and resets both', async () => {
      const { hal, physical, twin } = hybridRig();
      await hal.initialize();
      const stopped = await hal.safety.emergencyStop('test');
      expect(stopped).toMatchObject({
        success: true,
        mode: 'hybrid',
        data: { twin: { success: true } },
      });
      expect([physical.safety.isEmergencyStopped(), twin.safety.isEmergencyStopped()]).toEqual([
        true,
        true,
      ]);
      expect(hal.safety.getSafetyStatus()).toMatchObject({
        emergencyStopped: true,
        emergencyStopReason: 'test',
      });
      expect((await hal.locomotion.moveForward(1)).code).toBe('EMERGENCY_STOPPED');
      expect((await hal.safety.resetEmergencyStop()).success).toBe(true);
      expect([
        hal.safety.isEmergencyStopped(),
        physical.safety.isEmergencyStopped(),
        twin.safety.isEmergencyStopped(),
      ]).toEqual([false, false, false]);
      await hal.cleanup();
    });

    it("is emergency-stopped while only the twin is, and lists the twin's errors prefixed", async () => {
      const { hal, twin } = hybridRig();
      await hal.initialize();
      expect(() => twin.robot.moveSteps(50_000, 50_000)).toThrow(/step/); // more than one command allows: the twin trips and latches
      expect(hal.safety.isEmergencyStopped()).toBe(true);
      const status = SafetyStatusSchema.parse(hal.safety.getSafetyStatus());
      expect(status.errors.some((e) => e.startsWith('twin: last trip: step_limit'))).toBe(true);
      expect((await hal.locomotion.moveForward(1)).code).toBe('EMERGENCY_STOPPED');
      expect((await hal.safety.resetEmergencyStop()).success).toBe(true);
      expect(hal.safety.isEmergencyStopped()).toBe(false);
      await hal.cleanup();
    });

    it('merges two safety statuses: physical battery, both error lists', () => {
      expect(
        mergeSafetyStatus(
          { emergencyStopped: false, batteryLevel: 80, temperature: 30, errors: ['link lost'] },
          {
            emergencyStopped: true,
            batteryLevel: 100,
            errors: ['estop: x'],
            emergencyStopReason: 'x',
          },
          true,
        ),
      ).toEqual({
        emergencyStopped: true,
        batteryLevel: 80,
        temperature: 30,
        errors: ['link lost', 'twin: estop: x'],
        emergencyStopReason: 'twin: x',
      });
    });
  });

  describe('capabilities', () => {
    it("reports the physical robot's capabilities and its missing camera, not the twin's", async () => {
      const { hal, physical, twin } = hybridRig();
      await hal.initialize();
      const info = hal.getDeviceInfo();
      expect(info).toMatchObject({ id: 'cube-1', mode: 'hybrid' });
      expect(info.capabilities).toEqual(physical.getDeviceInfo().capabilities);
      expect(twin.getDeviceInfo().capabilities).toContain('vision.camera:v1.0');
      expect(info.capabilities).not.toContain('vision.camera:v1.0');
      const frame = await hal.vision.captureFrame().catch((error: unknown) => error);
      expect(isHalError(frame) && frame.code).toBe('NOT_IMPLEMENTED');
      expect((await hal.vision.getIMU()).source).toBe('odometry');
      await hal.cleanup();
    });

    it('sets the LED on both robots and speaks only through the physical one', async () => {
      const { hal, robot, twin } = hybridRig();
      await hal.initialize();
      const led = await hal.communication.setLED(0, 255, 0, 'blink');
      expect(led).toMatchObject({ success: true, data: { twin: { success: true } } });
      expect(robot.requests.some((r) => r['cmd'] === 'set_led' && r['g'] === 255)).toBe(true);
      expect(twin.robot.led).toEqual({ r: 0, g: 255, b: 0, pattern: 'blink' });
      const spoken = await hal.communication.speak('hello');
      expect(spoken).toMatchObject({ success: false, code: 'NOT_IMPLEMENTED', mode: 'hybrid' });
      expect(spoken.data?.['twin']).toBeUndefined();
      await hal.cleanup();
    });

    it('logs through the physical robot, and reports a refused log to its own logger without throwing', async () => {
      const entries: Array<[string, string, string]> = [];
      const physicalEntries: string[] = [];
      const { hal } = hybridRig({
        hybrid: { logger: { log: (level, ns, message) => entries.push([level, ns, message]) } },
        physical: {
          logger: { log: (_l, ns, message) => physicalEntries.push(`${ns} ${message}`) },
        },
      });
      await hal.initialize();
      hal.communication.log('kept', 'info');
      expect(() => hal.communication.log('x', 'bogus' as 'info')).not.toThrow();
      expect(physicalEntries).toContain('hal:physical:log kept');
      expect(physicalEntries.filter((e) => e.startsWith('hal:physical:log'))).toHaveLength(1);
      expect(entries).toContainEqual(['warn', 'hal:hybrid', 'log refused']);
      await hal.cleanup();
    });

    it('refuses vision calls with NOT_READY before initialize()', async () => {
      const { hal } = hybridRig();
      const imu = await hal.vision.getIMU().catch((error: unknown) => error);
      expect(isHalError(imu) && imu.code).toBe('NOT_READY');
    });
  });

  describe('#initialize', () => {
    it('initialises both robots once when called twice at the same time', async () => {
      const { hal, robot, physical, twin } = hybridRig();
      await Promise.all([hal.initialize(), hal.initialize()]);
      expect([hal.isReady(), physical.isReady(), twin.isReady()]).toEqual([true, true, true]);
      expect(robot.requests.filter((r) => r['cmd'] === 'hello')).toHaveLength(1);
      await hal.cleanup();
      expect([hal.isReady(), physical.isReady(), twin.isReady()]).toEqual([false, false, false]);
    });

    it('fails naming the twin when the twin cannot start, and leaves the physical robot closed', async () => {
      const { hal, physical, twin } = hybridRig();
      twin.initialize = async () => {
        throw new HalError('HARDWARE_ERROR', 'the world is gone');
      };
      const error = await hal.initialize().catch((thrown: unknown) => thrown);
      expect(isHalError(error) && error.code).toBe('HARDWARE_ERROR');
      expect((error as Error).message).toBe(
        'hybrid: the twin failed to initialise: the world is gone',
      );
      expect((error as HalError).details).toMatchObject({ side: 'twin' });
      expect(physical.isReady()).toBe(false);
      expect(hal.isReady()).toBe(false);
      expect((await hal.locomotion.moveForward(1)).code).toBe('NOT_READY');
    });

    it("exposes the physical robot's limits as its robotConfig, or the ones it was given", async () => {
      const { hal, physical } = hybridRig();
      await hal.initialize();
      expect(hal.robotConfig).toBe(physical.robotConfig);
      const given = { ...physical.robotConfig, maxStepsPerCommand: 1000 };
      expect(hybridRig({ hybrid: { robotConfig: () => given } }).hal.robotConfig).toBe(given);
      await hal.cleanup();
    });

    it('fails naming the physical robot when it cannot be reached', async () => {
      const physical = new PhysicalHAL({ mode: 'physical', deviceId: 'cube-1' });
      physical.initialize = async () => {
        throw new HalError('NOT_CONNECTED', 'no reply from 192.0.2.1:4210');
      };
      const twin = new SimulationHAL();
      const hal = new HybridHAL({ physical, twin });
      const error = await hal.initialize().catch((thrown: unknown) => thrown);
      expect(isHalError(error) && error.code).toBe('NOT_CONNECTED');
      expect((error as Error).message).toBe(
        'hybrid: the physical robot failed to initialise: no reply from 192.0.2.1:4210',
      );
      expect(twin.isReady()).toBe(false);
    });
  });
});
