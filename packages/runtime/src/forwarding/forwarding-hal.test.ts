import { describe, expect, it } from 'vitest';
import { HAL_CALL_TABLE, isHalError } from '@hal/types';
import type { CallSpec, Logger } from '@hal/types';
import { describeHalContract } from '@hal/types/testing';
import { LoopbackHAL } from './loopback-hal.fixture.js';

const refuseEstop = (spec: CallSpec) =>
  spec.name === 'emergencyStop'
    ? Promise.reject(new Error('the link dropped mid-send'))
    : undefined;

describeHalContract('ForwardingHAL over a loopback link', { create: () => new LoopbackHAL() });

describe('ForwardingHAL', () => {
  describe('before initialize()', () => {
    it('refuses calls with NOT_READY and sends nothing', async () => {
      const hal = new LoopbackHAL();
      expect(await hal.locomotion.moveForward(1)).toMatchObject({
        success: false,
        code: 'NOT_READY',
      });
      expect((await hal.locomotion.stop()).code).toBe('NOT_READY');
      const read: unknown = await hal.locomotion.getPose().catch((e: unknown) => e);
      expect(isHalError(read) && read.code).toBe('NOT_READY');
      expect(hal.sent).toEqual([]);
      expect(hal.isReady()).toBe(false);
    });

    it('writes a refused log to its logger instead of sending it', () => {
      const lines: string[] = [];
      const logger: Logger = { log: (_level, _ns, message) => lines.push(message) };
      const hal = new LoopbackHAL({ logger });
      hal.communication.log('hello', 'info');
      expect(hal.sent).toEqual([]);
      expect(lines).toEqual([
        expect.stringMatching(/^log refused: log: the HAL is not initialised/),
      ]);
    });
  });

  describe('the host e-stop latch', () => {
    it('latches before initialize() with the reason sanitized, and initialize() sends it first', async () => {
      const hal = new LoopbackHAL();
      const stop = await hal.safety.emergencyStop('cliff\u0007ahead  ');
      expect(stop).toMatchObject({
        success: true,
        data: { estop: true, reason: 'cliff ahead', delivered: false },
      });
      expect(hal.safety.getSafetyStatus()).toMatchObject({
        emergencyStopped: true,
        emergencyStopReason: 'cliff ahead',
      });
      expect(hal.served.safety.isEmergencyStopped()).toBe(false);
      await hal.initialize();
      expect(hal.sent).toEqual(['emergencyStop']);
      expect(hal.served.safety.getSafetyStatus().emergencyStopReason).toBe('cliff ahead');
    });

    it('refuses motion while latched without sending it, and an accepted reset clears it', async () => {
      const hal = new LoopbackHAL();
      await hal.initialize();
      expect((await hal.safety.emergencyStop('bumper')).data).toMatchObject({ delivered: true });
      hal.sent.length = 0;
      expect(await hal.locomotion.moveForward(1)).toMatchObject({
        success: false,
        code: 'EMERGENCY_STOPPED',
      });
      expect(hal.sent).toEqual([]);
      expect((await hal.locomotion.stop()).success).toBe(true); // a stop is never refused
      expect((await hal.safety.resetEmergencyStop()).success).toBe(true);
      expect(hal.safety.isEmergencyStopped()).toBe(false);
      expect((await hal.locomotion.moveForward(1)).success).toBe(true);
      expect(hal.sent).toEqual(['stop', 'resetEmergencyStop', 'moveForward']);
    });

    it('keeps the latch when the reset is refused', async () => {
      const hal = new LoopbackHAL({
        answer: (spec) =>
          spec.name === 'resetEmergencyStop'
            ? Promise.resolve({
                success: false,
                error: 'not now',
                code: 'HARDWARE_ERROR',
                mode: 'simulation',
                timestamp: 0,
              })
            : undefined,
      });
      await hal.initialize();
      await hal.safety.emergencyStop('x');
      expect((await hal.safety.resetEmergencyStop()).code).toBe('HARDWARE_ERROR');
      expect(hal.safety.isEmergencyStopped()).toBe(true);
      expect((await hal.locomotion.moveForward(1)).code).toBe('EMERGENCY_STOPPED');
    });

    it('fails initialize() with NOT_CONNECTED, not ready, when the pending e-stop is not taken', async () => {
      const hal = new LoopbackHAL({ answer: refuseEstop });
      await hal.safety.emergencyStop('early');
      const error: unknown = await hal.initialize().catch((e: unknown) => e);
      expect(isHalError(error) && error.code).toBe('NOT_CONNECTED');
      expect(hal.isReady()).toBe(false);
      expect(hal.linkOpen).toBe(false);
      expect(hal.safety.isEmergencyStopped()).toBe(true);
    });

    it('until-reset: a connected e-stop the link loses answers a failure, and the latch holds', async () => {
      const hal = new LoopbackHAL({ latch: 'until-reset', answer: refuseEstop });
      await hal.initialize();
      const stop = await hal.safety.emergencyStop('lost');
      expect(stop).toMatchObject({ success: false, code: 'HARDWARE_ERROR' });
      expect(hal.safety.isEmergencyStopped()).toBe(true);
      expect((await hal.locomotion.moveForward(1)).code).toBe('EMERGENCY_STOPPED');
    });

    it('until-served: lets go once the served HAL holds the stop, whose state is then the truth', async () => {
      const hal = new LoopbackHAL({ latch: 'until-served' });
      await hal.initialize();
      await hal.safety.emergencyStop('shared');
      expect(hal.safety.isEmergencyStopped()).toBe(true);
      // another client of the served HAL resets it: the served state says so on the next reply
      expect((await hal.served.safety.resetEmergencyStop()).success).toBe(true);
      expect((await hal.locomotion.moveForward(1)).success).toBe(true);
      expect(hal.safety.isEmergencyStopped()).toBe(false);
    });

    it('until-served: an e-stop made while the link is down answers undelivered, and goes on reconnection', async () => {
      const hal = new LoopbackHAL({ latch: 'until-served' });
      await hal.initialize();
      hal.up = false;
      expect(await hal.locomotion.moveForward(1)).toMatchObject({ code: 'NOT_CONNECTED' });
      expect(await hal.safety.emergencyStop('link down')).toMatchObject({
        success: true,
        data: { delivered: false, reason: 'link down' },
      });
      expect(hal.served.safety.isEmergencyStopped()).toBe(false);
      hal.reconnect();
      await expect.poll(() => hal.served.safety.isEmergencyStopped()).toBe(true);
      expect(hal.served.safety.getSafetyStatus().emergencyStopReason).toBe('link down');
      expect((await hal.locomotion.moveForward(1)).code).toBe('EMERGENCY_STOPPED');
    });
  });

  describe('cleanup()', () => {
    it('stops the robot, bounded, before letting go of the link', async () => {
      const hal = new LoopbackHAL();
      await hal.initialize();
      await hal.cleanup();
      expect(hal.sent).toEqual(['stop']);
      expect(hal.timeouts).toEqual([2000]);
      expect(hal.linkOpen).toBe(false);
      expect((await hal.locomotion.moveForward(1)).code).toBe('NOT_READY');
      await hal.cleanup(); // twice is safe
      expect(hal.sent).toEqual(['stop']);
    });

    it('does not stop the robot for a client that only watches', async () => {
      const hal = new LoopbackHAL({ stopsOnCleanup: false });
      await hal.initialize();
      await hal.cleanup();
      expect(hal.sent).toEqual([]);
    });
  });

  describe('answers', () => {
    it('refuses a result that is not a HALToolResult, and a value that does not match its schema, as MALFORMED', async () => {
      const hal = new LoopbackHAL({
        answer: (spec) =>
          spec.name === 'moveForward' || spec.name === 'getPose'
            ? Promise.resolve({ nonsense: true })
            : undefined,
      });
      await hal.initialize();
      expect(await hal.locomotion.moveForward(1)).toMatchObject({
        success: false,
        code: 'MALFORMED',
      });
      const read: unknown = await hal.locomotion.getPose().catch((e: unknown) => e);
      expect(isHalError(read) && read.code).toBe('MALFORMED');
    });

    it('passes the served result through as it came (its data and timing)', async () => {
      const served = {
        success: true,
        data: { distanceCm: 3 },
        mode: 'physical',
        timestamp: 12,
        executionTime: 34,
      };
      const hal = new LoopbackHAL({
        answer: (spec) => (spec.name === 'moveForward' ? Promise.resolve(served) : undefined),
      });
      await hal.initialize();
      expect(await hal.locomotion.moveForward(3)).toEqual(served);
    });

    it("gates a motion call of an extended table like the table's own", async () => {
      const spin = {
        ...HAL_CALL_TABLE.find((spec) => spec.name === 'rotate')!,
        name: 'spin',
        method: 'spin',
      };
      const hal = new LoopbackHAL({
        calls: [...HAL_CALL_TABLE, spin],
        answer: (spec) =>
          spec.name === 'spin'
            ? Promise.resolve({ success: true, mode: 'simulation', timestamp: 0 })
            : undefined,
      });
      await hal.initialize();
      const locomotion = hal.locomotion as unknown as Record<
        string,
        () => Promise<{ code?: string; success: boolean }>
      >;
      expect((await locomotion['spin']!()).success).toBe(true);
      await hal.safety.emergencyStop('x');
      expect((await locomotion['spin']!()).code).toBe('EMERGENCY_STOPPED');
    });
  });
});
