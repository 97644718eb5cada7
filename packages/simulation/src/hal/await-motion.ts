import { HalError } from '@hal/types';
import type { Contact } from '../robot/contact.js';
import type { MotionHandle, MotionReport } from '../robot/motion-report.js';
import type { SimRobot } from '../robot/sim-robot.js';
import type { HalContext } from './context.js';
import { SIMULATION_HAL_DEFAULTS } from './options.js';

/** The robot's pose as results carry it: metres and radians, the frame of its odometry. */
export function poseData(robot: SimRobot): Record<string, number> {
  // what the robot reports (its odometry), as PhysicalHAL's results carry it
  const p = robot.reportedPose;
  return { x: p.x, y: p.y, yaw: p.yaw };
}

/**
 * Where the robot felt a contact, in the frame of the pose it reports (its odometry): the contact's
 * place relative to the body, as a bumper would feel it, set on the pose the robot believes it has.
 * The world's record (the true point, and what was touched) is not the robot's to know.
 */
function feltContact(robot: SimRobot, contact: Contact): { point: { x: number; y: number } } {
  const dx = contact.point.x - robot.x;
  const dy = contact.point.y - robot.y;
  const yaw = robot.yaw;
  const forward = dx * Math.cos(yaw) + dy * Math.sin(yaw);
  const left = -dx * Math.sin(yaw) + dy * Math.cos(yaw);
  const p = robot.reportedPose;
  return {
    point: {
      x: p.x + forward * Math.cos(p.yaw) - left * Math.sin(p.yaw),
      y: p.y + forward * Math.sin(p.yaw) + left * Math.cos(p.yaw),
    },
  };
}

/**
 * Waits for a motion to end and returns its report, or throws: COLLISION (with the contact),
 * EMERGENCY_STOPPED, INTERRUPTED (with the outcome), or TIMEOUT (the robot is then stopped). In the fast clock the
 * HAL advances the world itself; otherwise it waits for whoever drives the clock.
 */
export async function awaitMotion(ctx: HalContext, handle: MotionHandle): Promise<MotionReport> {
  const report = handle.report;
  ctx.events.emit('motionStarted', { ...report });
  const planned = Number.isFinite(report.durationUs) ? report.durationUs : 0;
  const robot = ctx.robot();
  if (ctx.clock === 'fast') {
    // The motion's own plan bounds the wait; the margin covers one tick and rounding.
    const limit = planned + 1_000_000;
    ctx.world.advanceUntil(() => report.outcome !== 'running', limit);
  } else {
    await waitForClock(ctx, report, handle.finished, planned);
  }
  if (report.outcome === 'running') {
    robot.stop();
    throw new HalError(
      'TIMEOUT',
      `motion ${report.moveId} did not finish within its planned ${Math.ceil(planned / 1000)} ms (simulated time at ${Math.round(ctx.world.nowUs / 1000)} ms)`,
      { details: { moveId: report.moveId, plannedMs: Math.ceil(planned / 1000) } },
    );
  }
  ctx.events.emit('motionFinished', { ...report });
  if (report.outcome === 'done') return report;
  if (report.outcome === 'collision' && report.contact !== undefined) {
    const c = feltContact(ctx.robot(), report.contact);
    const self = ctx.world.deviceName(robot.id);
    throw new HalError(
      'COLLISION',
      `${self} touched something at (${c.point.x.toFixed(3)}, ${c.point.y.toFixed(3)}) m and stopped`,
      { details: { contact: c, pose: poseData(ctx.robot()), moveId: report.moveId } },
    );
  }
  const details = { outcome: report.outcome, moveId: report.moveId, pose: poseData(ctx.robot()) };
  if (report.outcome === 'estop') {
    // as PhysicalHAL reports it: the e-stop has its own code
    throw new HalError(
      'EMERGENCY_STOPPED',
      `motion ${report.moveId} was cut short by the emergency stop`,
      {
        details,
      },
    );
  }
  throw new HalError('INTERRUPTED', `motion ${report.moveId} ended early: ${report.outcome}`, {
    details,
  });
}

/**
 * Waits for a motion that someone else's clock drives. Gives up when simulated time passes the
 * planned end by a second, or when the clock has not moved for the stall timeout (wall time).
 */
async function waitForClock(
  ctx: HalContext,
  report: MotionReport,
  finished: Promise<MotionReport>,
  plannedUs: number,
): Promise<void> {
  const stallMs =
    ctx.clock === 'manual'
      ? (ctx.options.manualTimeoutMs ?? SIMULATION_HAL_DEFAULTS.manualTimeoutMs)
      : (ctx.options.stallTimeoutMs ?? SIMULATION_HAL_DEFAULTS.stallTimeoutMs);
  const deadlineUs = report.startedUs + plannedUs + 1_000_000;
  let seenUs = ctx.world.nowUs;
  let seenAt = Date.now();
  let timer: ReturnType<typeof setInterval> | undefined;
  await Promise.race([
    finished,
    new Promise<void>((resolve) => {
      timer = setInterval(() => {
        const now = ctx.world.nowUs;
        if (now !== seenUs) {
          seenUs = now;
          seenAt = Date.now();
        }
        if (now > deadlineUs || Date.now() - seenAt > stallMs) resolve();
      }, 10);
    }),
  ]);
  clearInterval(timer);
}
