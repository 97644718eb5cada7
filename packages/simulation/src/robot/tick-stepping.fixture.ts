import { integrateOdometry, MovePlan, VelocityPlan } from '@hal/kinematics';
import type { PlanarPoseCm, StepPlan } from '@hal/kinematics';
import { normalizeAngle, V1_ROBOT } from '@hal/types';
import { discContact } from '../shapes.js';
import type { Solid } from '../shapes.js';
import { blockingContact } from './contact.js';
import type { Contact } from './contact.js';

/*
 * The world's stepping as it was before event stepping, kept for tests only as the reference the
 * event stepping is held to: every tick (1 ms) each robot in turn asks its plan for the steps made
 * by the tick's end, integrates odometry over them in one go, and checks its disc at the new pose
 * against the solids and the other robots (those before it already moved this tick). A blocking
 * contact ends the motion at the tick's end with none of that tick's steps taken.
 */

/** A motion command: whole signed steps at a speed, or a drive at signed steps/s. */
export type TickCommand =
  | { kind: 'move'; left: number; right: number; speed: number }
  | { kind: 'drive'; left: number; right: number; durationMs?: number };

export interface TickRobotSpec {
  start: { x: number; y: number; yaw: number };
  radius: number;
  command: TickCommand;
}

/** Where a robot ended and why. */
export interface TickResult {
  outcome: 'running' | 'done' | 'collision';
  endedUs: number | undefined;
  doneLeft: number;
  doneRight: number;
  /** Metres and radians. */
  x: number;
  y: number;
  yaw: number;
  contact: Contact | undefined;
}

interface TickRobot {
  spec: TickRobotSpec;
  plan: StepPlan;
  limitUs: number;
  pose: PlanarPoseCm;
  result: TickResult;
}

/** Runs the robots from time 0 for `maxUs` (or until all have stopped), tick by tick. */
export function runTickStepping(
  solids: readonly Solid[],
  specs: readonly TickRobotSpec[],
  maxUs: number,
  tickUs = 1000,
): TickResult[] {
  const accel = V1_ROBOT.accelerationStepsPerS2;
  const robots: TickRobot[] = specs.map((spec) => {
    const c = spec.command;
    const plan =
      c.kind === 'move'
        ? new MovePlan(c.left, c.right, c.speed, accel)
        : new VelocityPlan(c.left, c.right, accel);
    const limitUs =
      c.kind === 'move'
        ? plan.durationUs
        : c.durationMs === undefined
          ? Number.POSITIVE_INFINITY
          : c.durationMs * 1000;
    const pose = {
      xCm: spec.start.x * 100,
      yCm: spec.start.y * 100,
      headingRad: normalizeAngle(spec.start.yaw),
    };
    return {
      spec,
      plan,
      limitUs,
      pose,
      result: {
        outcome: 'running',
        endedUs: undefined,
        doneLeft: 0,
        doneRight: 0,
        x: 0,
        y: 0,
        yaw: 0,
        contact: undefined,
      },
    };
  });
  const contactAt = (x: number, y: number, r: number, self: TickRobot): Contact | undefined => {
    for (const solid of solids) {
      const point = discContact(x, y, r, solid);
      if (point !== undefined) return { point, role: solid.role, index: solid.index };
    }
    for (let i = 0; i < robots.length; i += 1) {
      const other = robots[i] as TickRobot;
      if (other === self) continue;
      const ox = other.pose.xCm / 100;
      const oy = other.pose.yCm / 100;
      const dx = x - ox;
      const dy = y - oy;
      const reach = r + other.spec.radius;
      const d2 = dx * dx + dy * dy;
      if (d2 >= reach * reach) continue;
      const d = Math.sqrt(d2) || 1;
      const rr = other.spec.radius;
      return { point: { x: ox + (dx / d) * rr, y: oy + (dy / d) * rr }, role: 'robot', index: i };
    }
    return undefined;
  };
  for (let now = tickUs; now <= maxUs; now += tickUs) {
    let running = 0;
    for (const robot of robots) {
      const r = robot.result;
      if (r.outcome !== 'running') continue;
      running += 1;
      const elapsed = Math.min(now, robot.limitUs);
      const steps = robot.plan.stepsAt(
        robot.spec.command.kind === 'drive' && elapsed >= robot.limitUs
          ? robot.limitUs - 1
          : elapsed,
      );
      const dl = steps.left - r.doneLeft;
      const dr = steps.right - r.doneRight;
      if (dl !== 0 || dr !== 0) {
        const next = integrateOdometry(robot.pose, dl, dr, V1_ROBOT);
        const test = (x: number, y: number, rad: number) => contactAt(x, y, rad, robot);
        const contact = blockingContact(test, robot.spec.radius, robot.pose, next);
        if (contact !== undefined) {
          r.outcome = 'collision';
          r.contact = contact;
          r.endedUs = now;
          continue;
        }
        robot.pose = next;
        r.doneLeft = steps.left;
        r.doneRight = steps.right;
      }
      if (elapsed >= robot.limitUs) {
        r.outcome = 'done';
        r.endedUs = Math.min(robot.limitUs, now);
      }
    }
    if (running === 0) break;
  }
  return robots.map(({ pose, result }) => ({
    ...result,
    x: pose.xCm / 100,
    y: pose.yCm / 100,
    yaw: pose.headingRad,
  }));
}
