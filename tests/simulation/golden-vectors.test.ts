// The simulated robot against the shared golden vectors (tests/vectors/kinematics.json), which the
// firmware's host tests read too: step schedules, accumulator carries and odometry.
import { readFileSync } from 'node:fs';
import { SimRobot, World } from '@hal/simulation';
import { describe, expect, it } from 'vitest';

interface Vectors {
  profile: Array<{
    steps: number;
    max_speed_steps_per_s: number;
    acceleration_steps_per_s2: number;
    duration_us: number;
    samples: Array<{ k: number; t_us: number }>;
  }>;
  accumulator: Array<{ distances_cm: number[]; deltas: number[] }>;
  odometry: Array<{
    deltas: Array<[number, number]>;
    x_cm: number;
    y_cm: number;
    heading_rad: number;
  }>;
}

const vectors = JSON.parse(
  readFileSync(new URL('../vectors/kinematics.json', import.meta.url), 'utf8'),
) as Vectors;

describe('SimRobot against the golden vectors', () => {
  it('makes step k of every profile at exactly its golden microsecond, and not a microsecond before', () => {
    for (const profile of vectors.profile) {
      const robot = new SimRobot({ id: 'r' });
      robot.setConfig({
        accelerationStepsPerS2: profile.acceleration_steps_per_s2,
        maxSpeedStepsPerS: Math.min(2048, Math.ceil(profile.max_speed_steps_per_s)),
      });
      const report = robot.moveSteps(
        profile.steps,
        profile.steps,
        profile.max_speed_steps_per_s,
      ).report;
      expect(report.durationUs).toBe(profile.duration_us);
      for (const { k, t_us } of profile.samples) {
        robot.advanceTo(t_us - 1);
        expect(robot.leftSteps, `k=${k}`).toBe(k - 1);
        robot.advanceTo(t_us);
        expect(robot.leftSteps, `k=${k}`).toBe(k);
      }
      expect(robot.running).toBe(false);
    }
  });

  it('issues the golden whole steps for each move_cm of every accumulator sequence', () => {
    for (const sequence of vectors.accumulator) {
      const world = new World({ map: { name: 'open', arena: { width: 100, height: 100 } } });
      const robot = world.addRobot();
      sequence.distances_cm.forEach((cm, i) => {
        const report = robot.moveCm(cm, cm).report;
        expect(report.plannedLeft, `move ${i} of ${sequence.distances_cm.length}`).toBe(
          sequence.deltas[i],
        );
        world.advanceUntil(() => !robot.running, 600_000_000);
      });
    }
  });

  it('ends at the golden odometry pose for straight moves and turns in place', () => {
    // Straight lines and turns in place integrate exactly whatever the grouping of steps; arcs are
    // checked against the emulator in emulator-agreement.test.ts.
    for (const vector of vectors.odometry.slice(0, 3)) {
      const world = new World({ map: { name: 'open', arena: { width: 100, height: 100 } } });
      const robot = world.addRobot();
      for (const [left, right] of vector.deltas) {
        robot.moveSteps(left, right);
        world.advanceUntil(() => !robot.running, 600_000_000);
      }
      expect(robot.x * 100).toBeCloseTo(vector.x_cm, 9);
      expect(robot.y * 100).toBeCloseTo(vector.y_cm, 9);
      expect(robot.yaw).toBeCloseTo(vector.heading_rad, 12);
    }
  });
});
