// The event feed over a robot whose safety status, link and guard the test sets: each change is
// one event, told once, with who did it where that is known; faults that come with an e-stop or a
// lost link belong to that event; a measured battery going low is said once until it recovers.
import type { HardwareAbstractionLayer, SafetyStatus } from '@hal/types';
import { afterEach, describe, expect, it } from 'vitest';
import { RobotEvents } from './events.js';
import type { GuardEventLike, RobotEvent, RobotLogLine } from './events.js';

const status: SafetyStatus = { emergencyStopped: false, batteryLevel: 100, errors: [] };
const robot = {
  safety: { getSafetyStatus: (): SafetyStatus => ({ ...status, errors: [...status.errors] }) },
} as unknown as HardwareAbstractionLayer;

let release: (() => void) | undefined;
afterEach(() => {
  release?.();
  release = undefined;
  Object.assign(status, { emergencyStopped: false, batteryLevel: 100, errors: [] });
  delete status.emergencyStopReason;
});

function feed(sources: ConstructorParameters<typeof RobotEvents>[1] = {}) {
  const events = new RobotEvents(robot, sources, { keep: 5 });
  const told: RobotEvent[] = [];
  const logged: RobotLogLine[] = [];
  events.on((e) => told.push(e));
  events.onLog((l) => logged.push(l));
  release = events.open();
  return { events, told, logged };
}

describe('RobotEvents', () => {
  it('tells an e-stop from elsewhere and a reset by the client, once each', () => {
    const { events, told, logged } = feed();
    Object.assign(status, {
      emergencyStopped: true,
      emergencyStopReason: 'bumper',
      errors: ['estop_command: bumper'],
    });
    events.check();
    events.check();
    events.expect('reset');
    Object.assign(status, { emergencyStopped: false, errors: [] });
    events.check();
    expect(told.map(({ type, by, reason, details }) => ({ type, by, reason, details }))).toEqual([
      {
        type: 'emergency_stop',
        by: 'elsewhere',
        reason: 'bumper',
        details: { faults: ['estop_command: bumper'] },
      },
      { type: 'reset', by: 'mcp-client', reason: undefined, details: undefined },
    ]);
    expect(told.map((e) => e.seq)).toEqual([1, 2]);
    expect(logged.map((l) => l.level)).toEqual(['warn', 'info']);
  });

  it('tells a fault of its own, low battery once until it recovers, and keeps the last few', () => {
    const { events, told } = feed();
    status.errors = ['motor driver hot'];
    events.check();
    status.batteryLevel = 15;
    status.batteryVoltage = 3.4;
    events.check();
    events.check();
    status.batteryLevel = 60;
    events.check();
    status.batteryLevel = 10;
    events.check();
    expect(told.map((e) => e.type)).toEqual(['fault', 'low_battery', 'low_battery']);
    expect(told[1]).toMatchObject({ details: { batteryLevel: 15, batteryVoltage: 3.4 } });
    for (let i = 0; i < 5; i++) {
      status.errors = [`trip ${i}`];
      events.check();
    }
    expect(events.recent()).toHaveLength(5);
    expect(events.recent().at(-1)?.message).toBe('Fault: trip 4');
  });

  it("tells the link lost and back, and the guard's stops; its warnings go to the log", () => {
    let link = 'connected';
    let guardListener: ((event: GuardEventLike) => void) | undefined;
    const { events, told, logged } = feed({
      link: () => link,
      guard: {
        onEvent: (listener) => {
          guardListener = listener;
          return () => (guardListener = undefined);
        },
      },
    });
    link = 'lost';
    events.check();
    link = 'connected';
    events.check();
    guardListener?.({
      type: 'obstacle',
      stop: { distanceM: 0.12, source: 'camera', motion: 'moveForward', when: 'during' },
    });
    guardListener?.({ type: 'unguarded', message: 'moveBackward runs unwatched' });
    expect(told.map((e) => e.type)).toEqual(['link_lost', 'link_back', 'guard_stop']);
    expect(told[2]?.message).toBe('The guard stopped the robot: something 0.12 m ahead (camera)');
    expect(logged.at(-1)).toEqual({
      level: 'warn',
      logger: 'guard',
      message: 'moveBackward runs unwatched',
    });
    release?.();
    release = undefined;
    expect(guardListener).toBeUndefined(); // released: it no longer listens
  });
});
