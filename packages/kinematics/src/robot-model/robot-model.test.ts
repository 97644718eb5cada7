import { isHalError, robotConfig } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { RobotModel } from './robot-model.js';
import { FIRMWARE_SETTINGS } from './settings.js';

function thrown(fn: () => unknown): unknown {
  try {
    fn();
  } catch (error) {
    return error;
  }
  throw new Error('expected a throw');
}

function codeOf(fn: () => unknown): string | undefined {
  const error = thrown(fn);
  return isHalError(error) ? error.code : undefined;
}

/** Advances the model in 1 ms ticks until its motion ends (or `limitUs`). */
function runToEnd(model: RobotModel, limitUs = 600_000_000): void {
  let t = model.nowUs;
  while (model.running && t < limitUs) {
    t += 1000;
    model.advanceTo(t);
  }
}

describe('RobotModel', () => {
  describe('#emergencyStop', () => {
    it('stops at once, latches with the first reason and time, and counts one trip however often it is sent', () => {
      const model = new RobotModel();
      model.moveCm(10, 10);
      model.advanceTo(500_000);
      const stepsAtStop = model.leftSteps;
      model.emergencyStop('bumper');
      model.advanceTo(900_000);
      model.emergencyStop('again');
      model.advanceTo(2_000_000);
      expect(model.running).toBe(false);
      expect(model.motion?.outcome).toBe('estop');
      expect(model.leftSteps).toBe(stepsAtStop);
      expect(model.emergencyStopReason).toBe('bumper');
      expect(model.emergencyStopUs).toBe(500_000);
      expect(model.trips).toBe(1);
      expect(model.lastTrip).toEqual({ reason: 'estop_command', detail: 'bumper', atUs: 500_000 });
    });

    it('refuses every motion command with EMERGENCY_STOPPED before reading its arguments, until reset', () => {
      const model = new RobotModel();
      model.emergencyStop('test');
      for (const command of [
        () => model.moveSteps(Number.NaN, 1),
        () => model.moveCm(Number.NaN, 1),
        () => model.rotateDeg(Number.POSITIVE_INFINITY),
        () => model.drive(100, 100, -1),
      ]) {
        expect(codeOf(command)).toBe('EMERGENCY_STOPPED');
      }
      const error = thrown(() => model.moveCm(1, 1));
      expect(isHalError(error) && error.message).toBe(
        'emergency stop is latched (test); send reset_estop first',
      );
      expect(model.stop()).toBe(false); // a stop is always accepted
      expect(model.resetEmergencyStop()).toBe(true);
      expect(model.resetEmergencyStop()).toBe(false);
      expect(model.moveCm(1, 1).report.plannedLeft).toBe(217);
    });
  });

  describe('step limit', () => {
    it('refuses a move_cm over 40960 steps with the firmware message, latches, and keeps the carry as if it never came', () => {
      const model = new RobotModel();
      const control = new RobotModel();
      for (const m of [model, control]) {
        m.moveCm(10, 10); // 2172.99 steps: issues 2172, carries 0.99
        runToEnd(m);
      }
      const error = thrown(() => model.moveCm(10, 200));
      expect(isHalError(error) && error.code).toBe('RANGE_EXCEEDED');
      expect(isHalError(error) && error.message).toBe(
        '"right_cm" gives 43460 steps; the limit is 40960 steps per command (emergency stop latched)',
      );
      expect(isHalError(error) && error.details).toEqual({
        field: 'right_cm',
        min: -40960,
        max: 40960,
        value: 43460,
        estop: true,
      });
      expect(model.emergencyStopReason).toBe('step limit: "right_cm" 43460 steps');
      expect(model.lastTrip?.reason).toBe('step_limit');
      expect(model.running).toBe(false);
      expect(model.resetEmergencyStop()).toBe(true);
      expect(model.moveCm(10, 10).report.plannedLeft).toBe(
        control.moveCm(10, 10).report.plannedLeft,
      );
      expect(model.motion?.plannedLeft).toBe(2173);
    });

    it('checks the left wheel before the right, as the firmware does', () => {
      const model = new RobotModel();
      const error = thrown(() => model.moveSteps(50_000, 60_000));
      expect(isHalError(error) && error.details?.['field']).toBe('left');
      model.resetEmergencyStop();
      const right = thrown(() => model.moveSteps(10, -50_000));
      expect(isHalError(right) && right.details?.['field']).toBe('right');
      expect(model.trips).toBe(2);
    });

    it('names the degrees of a turn that is too long', () => {
      const model = new RobotModel();
      const error = thrown(() => model.rotateDeg(36_000));
      expect(isHalError(error) && error.details?.['field']).toBe('degrees');
      expect(model.emergencyStopped).toBe(true);
    });
  });

  describe('speed', () => {
    it('clamps a cruise speed above the top to the top and below 1 to 1, and refuses 0 and less', () => {
      const model = new RobotModel();
      const fast = model.moveSteps(100, 100, 5000).report;
      expect([fast.speed, fast.speedClamped]).toEqual([1024, true]);
      const slow = model.moveSteps(100, 100, 0.5).report;
      expect([slow.speed, slow.speedClamped]).toEqual([1, true]);
      expect(codeOf(() => model.moveSteps(100, 100, 0))).toBe('RANGE_EXCEEDED');
      expect(codeOf(() => model.moveSteps(100, 100, -3))).toBe('RANGE_EXCEEDED');
      expect(model.motion?.moveId).toBe(2);
    });

    it('scales both drive speeds together to the top speed, truncated toward zero', () => {
      const model = new RobotModel();
      const report = model.drive(2000, -1000)?.report;
      expect([report?.leftSps, report?.rightSps, report?.speedClamped]).toEqual([1024, -512, true]);
    });

    it('takes a drive of 1..600000 ms and refuses 0 or more than 600000 ms', () => {
      const model = new RobotModel();
      expect(codeOf(() => model.drive(100, 100, 0))).toBe('RANGE_EXCEEDED');
      expect(codeOf(() => model.drive(100, 100, 600_001))).toBe('RANGE_EXCEEDED');
      expect(model.running).toBe(false);
      expect(model.drive(100, 100, 600_000)?.report.durationUs).toBe(600_000_000);
    });
  });

  describe('host timeout', () => {
    it('stops a silent host’s drive exactly one host timeout after its last request, and latches nothing', () => {
      const model = new RobotModel({ config: robotConfig({ hostTimeoutMs: 1000 }) });
      model.setHostSilent(true);
      model.advanceTo(100_000);
      model.touchHost();
      model.drive(500, 500);
      model.advanceTo(700_000);
      model.touchHost(); // heard again at 0.7 s: the deadline moves to 1.7 s
      model.advanceTo(5_000_000);
      expect(model.running).toBe(false);
      expect(model.motion?.outcome).toBe('host_timeout');
      expect(model.motion?.endedUs).toBe(1_700_000);
      expect(model.lastTrip).toEqual({
        reason: 'host_timeout',
        detail: 'no request from the host for 1000 ms',
        atUs: 1_700_000,
      });
      expect(model.emergencyStopped).toBe(false);
      expect(model.drive(500, 500)).toBeDefined();
    });

    it('never stops a host that is heard throughout (its heartbeats), nor does a command count as hearing it', () => {
      const talking = new RobotModel({ config: robotConfig({ hostTimeoutMs: 500 }) });
      talking.drive(500, 500);
      talking.advanceTo(60_000_000);
      expect(talking.running).toBe(true);

      const silent = new RobotModel();
      silent.setHostSilent(true);
      silent.advanceTo(300_000);
      silent.moveSteps(10, 10);
      silent.stop();
      expect(silent.lastHostUs).toBe(0); // the request layer hears the host, not the commands
    });
  });

  describe('#setConfig', () => {
    it('refuses each firmware setting just outside its range with RANGE_EXCEEDED and changes nothing', () => {
      const model = new RobotModel();
      for (const setting of FIRMWARE_SETTINGS) {
        const step = setting.integer ? 1 : 0.01;
        for (const value of [setting.min - step, setting.max + step]) {
          const error = thrown(() => model.setConfig({ [setting.key]: value }));
          expect(isHalError(error) && error.code, `${setting.key} = ${value}`).toBe(
            'RANGE_EXCEEDED',
          );
          expect(isHalError(error) && error.details?.['field']).toBe(setting.key);
        }
      }
      expect(codeOf(() => model.setConfig({ stepsPerRevolution: 4096.5 }))).toBe(
        'INVALID_PARAMETER',
      );
      expect(model.config).toEqual(robotConfig());
    });

    it('takes each firmware setting at both ends of its range', () => {
      const model = new RobotModel();
      for (const setting of FIRMWARE_SETTINGS) {
        expect(model.setConfig({ [setting.key]: setting.min })[setting.key]).toBe(setting.min);
        expect(model.setConfig({ [setting.key]: setting.max })[setting.key]).toBe(setting.max);
      }
    });

    it('forgets the carry of the accumulators', () => {
      const model = new RobotModel();
      model.moveCm(10, 10);
      runToEnd(model);
      model.setConfig({});
      expect(model.moveCm(10, 10).report.plannedLeft).toBe(2172);
    });
  });
});
