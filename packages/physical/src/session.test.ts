import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { MockRobot } from './mock/mock-robot.js';
import { PhysicalHAL } from './hal/physical-hal.js';

const heartbeats = (robot: MockRobot) => robot.requests.filter((r) => r['cmd'] === 'heartbeat');

describe('PhysicalHAL heartbeat (fake clock)', () => {
  beforeEach(() => {
    vi.useFakeTimers({ toFake: ['setTimeout', 'clearTimeout', 'performance', 'Date'] });
  });
  afterEach(() => {
    vi.useRealTimers();
  });

  async function connected() {
    const robot = new MockRobot();
    const hal = new PhysicalHAL(
      { mode: 'physical', deviceId: 'cube-1' },
      { transport: robot.transport() },
    );
    const ready = hal.initialize();
    await vi.advanceTimersByTimeAsync(10);
    await ready;
    return { robot, hal };
  }

  it('speaks about every 500 ms while idle, so an agent may think for minutes', async () => {
    const { robot, hal } = await connected();
    expect((await runDrive(hal)).success).toBe(true);
    await vi.advanceTimersByTimeAsync(60_000);
    expect(heartbeats(robot).length).toBeGreaterThanOrEqual(100);
    expect(heartbeats(robot).length).toBeLessThanOrEqual(125);
    const status = await settle(hal.refreshStatus());
    expect(status.running).toBe(true);
    expect(status.safety.trips).toBe(0);
    await settle(hal.cleanup());
  });

  it('lets the robot stop the wheels after its host timeout when the heartbeat is paused', async () => {
    const { robot, hal } = await connected();
    expect((await runDrive(hal)).success).toBe(true);
    hal.pauseHeartbeat();
    const before = heartbeats(robot).length;
    await vi.advanceTimersByTimeAsync(3000);
    expect(heartbeats(robot).length).toBe(before);
    hal.resumeHeartbeat();
    const status = await settle(hal.refreshStatus());
    expect(status.running).toBe(false);
    expect(status.move_outcome).toBe('host_timeout');
    expect(status.safety.last_trip?.reason).toBe('host_timeout');
    await settle(hal.cleanup());
  });

  async function settle<T>(promise: Promise<T>): Promise<T> {
    await vi.advanceTimersByTimeAsync(10);
    return promise;
  }

  function runDrive(hal: PhysicalHAL) {
    return settle(hal.locomotion.drive(100, 100));
  }
});
