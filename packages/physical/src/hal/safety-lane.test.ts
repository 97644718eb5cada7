import { afterEach, describe, expect, it } from 'vitest';
import { MockRobot } from '../mock/mock-robot.js';
import { PhysicalHAL } from './physical-hal.js';

// A request is resent only after 300 ms: anything that waits for the queue takes that long.
const REQUEST_TIMEOUT_MS = 300;

const hals: PhysicalHAL[] = [];
afterEach(async () => {
  await Promise.all(hals.splice(0).map((hal) => hal.cleanup()));
});

async function rig() {
  const robot = new MockRobot({ hostTimeoutMs: 10_000 });
  const hal = new PhysicalHAL(
    { mode: 'physical', deviceId: 'cube-lane' },
    { transport: robot.transport({ latencyMs: 1 }), requestTimeoutMs: REQUEST_TIMEOUT_MS },
  );
  hals.push(hal);
  await hal.initialize();
  return { robot, hal };
}

const until = async (condition: () => boolean, timeoutMs = 5000) => {
  const start = performance.now();
  while (!condition()) {
    if (performance.now() - start > timeoutMs) throw new Error('condition not met in time');
    await new Promise((resolve) => setTimeout(resolve, 2));
  }
};

const sent = (robot: MockRobot, cmd: string) => robot.requests.filter((r) => r['cmd'] === cmd);

describe('PhysicalHAL safety lane', () => {
  it('sends emergencyStop at once while a lost get_status is being retried, and ends the move EMERGENCY_STOPPED', async () => {
    const { robot, hal } = await rig();
    const moving = hal.locomotion.moveForward(30);
    await until(() => robot.motionsStarted === 1);
    const polls = sent(robot, 'get_status').length;
    robot.dropReplies(2); // the next status replies are lost: the queue is stuck retrying
    const pending = hal.refreshStatus();
    await until(() => sent(robot, 'get_status').length > polls);
    const called = performance.now();
    const stop = await hal.safety.emergencyStop('lane test');
    const stopMs = performance.now() - called;
    const move = await moving;
    const moveMs = performance.now() - called;
    expect(stop.success).toBe(true);
    expect(robot.estopped).toBe(true);
    expect(move.code).toBe('EMERGENCY_STOPPED');
    // generous bounds that still prove neither waited for a 300 ms retry of the stuck request
    expect(stopMs).toBeLessThan(REQUEST_TIMEOUT_MS / 2);
    expect(moveMs).toBeLessThan(REQUEST_TIMEOUT_MS / 2);
    expect(robot.motionsStarted).toBe(1);
    // the stuck request is still answered, from the robot's memory (it ran before the stop),
    // never refused as stale and never run twice
    const stuck = await pending;
    expect(stuck.move_outcome).toBe('running');
    expect(hal.transportStats()?.timeouts).toBe(0);
    const after = await hal.refreshStatus();
    expect(after.safety.estop).toBe(true);
    expect(after.move_outcome).toBe('estop');
    const seqs = sent(robot, 'get_status')
      .slice(polls)
      .map((r) => r['seq']);
    expect(new Set(seqs).size).toBe(2); // the stuck request (resent), then the fresh one
  });

  it('never starts a move whose request was lost and then overtaken by stop(): it resolves INTERRUPTED', async () => {
    const { robot, hal } = await rig();
    robot.dropRequests(1);
    const moving = hal.locomotion.moveForward(10);
    await until(() => hal.transportStats()!.sent >= 3); // hello, get_status, the lost move_cm
    expect((await hal.locomotion.stop()).success).toBe(true);
    const move = await moving;
    expect(move.code).toBe('INTERRUPTED');
    // its retry reaches the robot later, and is refused there: a move sent before a stop
    await until(() => sent(robot, 'move_cm').length === 1, REQUEST_TIMEOUT_MS * 4);
    await new Promise((resolve) => setTimeout(resolve, 20));
    expect(robot.motionsStarted).toBe(0);
    expect(robot.position).toEqual({ left: 0, right: 0 });
    expect((await hal.locomotion.moveForward(1)).success).toBe(true);
    expect(robot.motionsStarted).toBe(1);
  });

  it('never sends a motion command that was still queued when stop() was issued', async () => {
    const { robot, hal } = await rig();
    robot.dropReplies(1);
    const status = hal.refreshStatus(); // its reply is lost: it holds the queue for 300 ms
    const moving = hal.locomotion.moveForward(10); // queued behind it
    await until(() => sent(robot, 'get_status').length >= 2);
    expect((await hal.locomotion.stop()).success).toBe(true);
    expect((await moving).code).toBe('INTERRUPTED');
    await status;
    expect(sent(robot, 'move_cm')).toHaveLength(0);
    expect(robot.motionsStarted).toBe(0);
  });

  it('latches before initialize() without sending, then e-stops the robot when it connects', async () => {
    const robot = new MockRobot();
    const hal = new PhysicalHAL(
      { mode: 'physical', deviceId: 'cube-early' },
      { transport: robot.transport() },
    );
    hals.push(hal);
    const early = await hal.safety.emergencyStop({ not: 'text' } as unknown as string);
    expect(early).toMatchObject({
      success: true,
      data: { delivered: false, reason: 'emergency stop' },
    });
    expect(robot.requests).toHaveLength(0);
    await hal.initialize();
    expect(robot.estopped).toBe(true);
    expect(hal.safety.getSafetyStatus().emergencyStopReason).toBe('emergency stop');
    expect((await hal.locomotion.moveForward(1)).code).toBe('EMERGENCY_STOPPED');
  });

  it('sends a 200-control-character reason as a sanitized one, and the running move stops', async () => {
    const { robot, hal } = await rig();
    const moving = hal.locomotion.moveForward(30);
    await until(() => robot.motionsStarted === 1);
    const result = await hal.safety.emergencyStop('\u0001'.repeat(199) + 'x');
    expect(result).toMatchObject({ success: true, data: { reason: 'x', delivered: true } });
    expect((await moving).code).toBe('EMERGENCY_STOPPED');
    expect(robot.estopped).toBe(true);
  });

  it('fails a motion that overruns its deadline with TIMEOUT, not INTERRUPTED, and stops the robot', async () => {
    // the robot's clock runs at half speed: the move takes twice as long as the HAL planned
    const robot = new MockRobot({ timeScale: 0.5, hostTimeoutMs: 10_000 });
    const hal = new PhysicalHAL(
      { mode: 'physical', deviceId: 'cube-slow' },
      { transport: robot.transport(), motionTimeoutMarginMs: 100 },
    );
    hals.push(hal);
    await hal.initialize();
    const move = await hal.locomotion.moveForward(1);
    expect(move.code).toBe('TIMEOUT');
    expect(sent(robot, 'stop').length).toBeGreaterThanOrEqual(1);
    expect((await hal.refreshStatus()).move_outcome).toBe('stopped');
  });
});
