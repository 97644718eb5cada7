import { distanceToSteps, MovePlan, VelocityPlan } from '@hal/kinematics';
import { isHalError, robotConfig } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { SimRobot } from './sim-robot.js';

function runToEnd(robot: SimRobot, stepUs = 1000): void {
  let t = robot.nowUs;
  for (let i = 0; i < 10_000_000 && robot.running; i += 1) {
    t += stepUs;
    robot.advanceTo(t);
  }
}

function thrown(fn: () => unknown): unknown {
  try {
    fn();
  } catch (error) {
    return error;
  }
  throw new Error('expected a throw');
}

describe('SimRobot', () => {
  describe('#moveCm', () => {
    it('makes whole steps on the firmware schedule: step k lands at the planner time of step k', () => {
      const robot = new SimRobot({ id: 'r' });
      const handle = robot.moveCm(10, 10);
      expect(handle.report.plannedLeft).toBe(2172);
      const plan = new MovePlan(2172, 2172, 1024, 512);
      for (const k of [1, 2, 3, 100, 1086, 2171, 2172]) {
        const t = plan.profile.stepTimeUs(k);
        robot.advanceTo(t - 1);
        expect(robot.leftSteps).toBe(k - 1);
        robot.advanceTo(t);
        expect(robot.leftSteps).toBe(k);
        expect(robot.rightSteps).toBe(k);
      }
      expect(robot.running).toBe(false);
      expect(robot.motion?.outcome).toBe('done');
      expect(robot.motion?.endedUs).toBe(plan.durationUs);
    });

    it('carries the truncated fraction: 100 moves of 10 cm make the steps of 1000 cm, not 100 x 2172', () => {
      const robot = new SimRobot({ id: 'r' });
      for (let i = 0; i < 100; i += 1) {
        robot.moveCm(10, 10);
        runToEnd(robot, 50_000);
      }
      expect(robot.leftSteps).toBe(distanceToSteps(1000));
      expect(robot.rightSteps).toBe(217_299);
    });

    it('refuses NaN and Infinity before changing anything, and later moves and step-limit refusals behave as if they never came', () => {
      const control = new SimRobot({ id: 'control' });
      const robot = new SimRobot({ id: 'r' });
      for (const r of [control, robot]) {
        r.moveCm(10, 10); // carries 0.99 of a step per wheel
        runToEnd(r);
      }
      for (const bad of [
        () => robot.moveCm(Number.NaN, 5),
        () => robot.moveCm(5, Number.POSITIVE_INFINITY),
        () => robot.rotateDeg(Number.NaN),
        () => robot.drive(Number.NaN, 100),
        () => robot.drive(100, 100, Number.POSITIVE_INFINITY),
      ]) {
        const error = thrown(bad);
        expect(isHalError(error) && error.code).toBe('INVALID_PARAMETER');
      }
      expect(robot.running).toBe(false);
      expect(robot.emergencyStopped).toBe(false);
      expect(robot.trips).toBe(0);
      expect(robot.leftSteps).toBe(control.leftSteps);

      for (const r of [control, robot]) {
        const error = thrown(() => r.moveCm(1e6, 1e6));
        expect(isHalError(error) && error.code).toBe('RANGE_EXCEEDED');
        expect(r.resetEmergencyStop()).toBe(true);
      }
      const next = robot.moveCm(10, 10).report;
      expect(next.plannedLeft).toBe(control.moveCm(10, 10).report.plannedLeft);
      expect(next.plannedLeft).toBe(2173); // the carry survived the refusals
      runToEnd(robot);
      runToEnd(control);
      expect(robot.leftSteps).toBe(control.leftSteps);
    });

    it('forgets the carry on hello, as on a new session', () => {
      const robot = new SimRobot({ id: 'r' });
      robot.moveCm(10, 10); // 2172.99 steps: issues 2172, carries 0.99
      runToEnd(robot);
      robot.hello();
      expect(robot.moveCm(10, 10).report.plannedLeft).toBe(2172); // not 2173
    });

    it('forgets the carry on set_config', () => {
      const robot = new SimRobot({ id: 'r' });
      robot.moveCm(10, 10);
      runToEnd(robot);
      robot.setConfig({});
      expect(robot.moveCm(10, 10).report.plannedLeft).toBe(2172);
    });

    it('refuses more than 40960 steps with RANGE_EXCEEDED, trips the e-stop and keeps the carry', () => {
      const robot = new SimRobot({ id: 'r' });
      const error = thrown(() => robot.moveCm(200, 200));
      expect(isHalError(error) && error.code).toBe('RANGE_EXCEEDED');
      expect(robot.emergencyStopped).toBe(true);
      // the firmware's reason, word for word (cube_motion_commands.cpp)
      expect(robot.emergencyStopReason).toBe('step limit: "left_cm" 43459 steps');
      expect(robot.lastTrip?.reason).toBe('step_limit');
      const refused = thrown(() => robot.moveCm(1, 1));
      expect(isHalError(refused) && refused.code).toBe('EMERGENCY_STOPPED');
      expect(robot.resetEmergencyStop()).toBe(true);
      expect(robot.moveCm(10, 10).report.plannedLeft).toBe(2172);
    });

    it('clamps the speed to the top speed and raises (0, 1) to 1, as the firmware does', () => {
      const robot = new SimRobot({ id: 'r' });
      const fast = robot.moveCm(1, 1, 5000).report;
      expect([fast.speed, fast.speedClamped]).toEqual([1024, true]);
      const slow = robot.moveCm(1, 1, 0.2).report;
      expect([slow.speed, slow.speedClamped]).toEqual([1, true]);
      expect(isHalError(thrown(() => robot.moveCm(1, 1, 0)))).toBe(true);
    });
  });

  describe('#rotateDeg', () => {
    it('turns 90 degrees counter-clockwise with 1706 steps per wheel, left wheel backwards', () => {
      const robot = new SimRobot({ id: 'r' });
      const report = robot.rotateDeg(90).report;
      expect([report.plannedLeft, report.plannedRight]).toEqual([-1706, 1706]);
      runToEnd(robot);
      expect(robot.yaw).toBeCloseTo(1.5701827344797423, 12);
      expect(Math.hypot(robot.x, robot.y)).toBeLessThan(1e-12);
    });
  });

  describe('#drive', () => {
    it('runs the velocity plan until its duration, making only the steps due before it', () => {
      const robot = new SimRobot({ id: 'r' });
      robot.drive(1024, 1024, 3000);
      runToEnd(robot, 700);
      const expected = new VelocityPlan(1024, 1024, 512).stepsAt(3_000_000 - 1);
      expect(robot.leftSteps).toBe(expected.left);
      expect(robot.motion?.endedUs).toBe(3_000_000);
      expect(robot.velocity()).toEqual({ linear: 0, angular: 0 });
    });

    it('scales both speeds together (truncated) when one is above the top speed', () => {
      const robot = new SimRobot({ id: 'r' });
      const report = robot.drive(2048, 1000)?.report;
      expect([report?.leftSps, report?.rightSps, report?.speedClamped]).toEqual([1024, 500, true]);
    });

    it('stops a running motion when both speeds are 0', () => {
      const robot = new SimRobot({ id: 'r' });
      robot.drive(500, 500);
      expect(robot.drive(0, 0)).toBeUndefined();
      expect(robot.running).toBe(false);
      expect(robot.motion?.outcome).toBe('stopped');
    });
  });

  describe('#setConfig', () => {
    it("refuses a setting outside the firmware's range with RANGE_EXCEEDED and keeps the configuration and the carry", () => {
      const robot = new SimRobot({ id: 'r' });
      robot.moveCm(10, 10); // carries 0.99 of a step per wheel
      runToEnd(robot);
      const error = thrown(() => robot.setConfig({ wheelBaseCm: 12, wheelDiameterCm: 80 }));
      expect(isHalError(error) && error.code).toBe('RANGE_EXCEEDED');
      expect(isHalError(error) && error.details).toMatchObject({
        field: 'wheelDiameterCm',
        max: 50,
      });
      expect(robot.config).toEqual(robotConfig());
      expect(robot.moveCm(10, 10).report.plannedLeft).toBe(2173);
    });
  });

  describe('host timeout', () => {
    it('stops a drive exactly host_timeout_ms after the host fell silent and records a trip', () => {
      const robot = new SimRobot({ id: 'r', config: robotConfig({ hostTimeoutMs: 1000 }) });
      robot.drive(512, 512);
      robot.advanceTo(500_000);
      robot.setHostSilent(true);
      robot.advanceTo(1_400_000);
      expect(robot.running).toBe(true);
      robot.advanceTo(1_600_000);
      expect(robot.running).toBe(false);
      expect(robot.motion?.outcome).toBe('host_timeout');
      expect(robot.motion?.endedUs).toBe(1_500_000);
      expect(robot.leftSteps).toBe(new VelocityPlan(512, 512, 512).stepsAt(1_500_000).left);
      expect(robot.lastTrip?.reason).toBe('host_timeout');
      expect(robot.emergencyStopped).toBe(false);
    });

    it('never fires while the host keeps talking, however long the motion', () => {
      const robot = new SimRobot({ id: 'r', config: robotConfig({ hostTimeoutMs: 500 }) });
      robot.drive(512, 512);
      for (let t = 0; t < 10_000_000; t += 100_000) robot.advanceTo(t);
      expect(robot.running).toBe(true);
    });
  });

  describe('replacing and stopping', () => {
    it('replaces a running motion: the old one ends "replaced", the new one starts from rest', async () => {
      const robot = new SimRobot({ id: 'r' });
      const first = robot.moveCm(10, 10);
      robot.advanceTo(1_000_000);
      const done = first.report.doneLeft;
      const second = robot.moveCm(5, 5);
      expect((await first.finished).outcome).toBe('replaced');
      expect(second.report.startedUs).toBe(1_000_000);
      robot.advanceTo(1_000_000 + new MovePlan(1086, 1086, 1024, 512).profile.stepTimeUs(1));
      expect(robot.leftSteps).toBe(done + 1);
    });

    it('stops at once on stop() and on an e-stop, which latches', async () => {
      const robot = new SimRobot({ id: 'r' });
      const move = robot.moveCm(10, 10);
      robot.advanceTo(500_000);
      expect(robot.stop()).toBe(true);
      expect((await move.finished).outcome).toBe('stopped');
      const before = robot.leftSteps;
      robot.advanceTo(2_000_000);
      expect(robot.leftSteps).toBe(before);
      const again = robot.moveCm(10, 10);
      robot.emergencyStop('test');
      expect((await again.finished).outcome).toBe('estop');
      expect(robot.emergencyStopped).toBe(true);
      expect(robot.stop()).toBe(false);
      expect(robot.emergencyStopped).toBe(true);
    });
  });

  describe('contacts', () => {
    it('stops before a step that would bring it into contact and reports where', async () => {
      const robot = new SimRobot({ id: 'r' });
      robot.setContactTest((x, y, r) =>
        x + r > 0.1 ? { point: { x: 0.1, y }, role: 'wall', index: 0 } : undefined,
      );
      const move = robot.moveCm(20, 20);
      runToEnd(robot);
      const report = await move.finished;
      expect(report.outcome).toBe('collision');
      expect(report.contact?.point.x).toBe(0.1);
      expect(robot.x + robot.radius).toBeLessThanOrEqual(0.1);
      expect(robot.x + robot.radius).toBeGreaterThan(0.0999);
    });
  });
});
