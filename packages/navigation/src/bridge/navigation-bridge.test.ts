import { afterEach, describe, expect, it, vi } from 'vitest';
import { FrontierExplorationProvider, GoalSeekingProvider } from '../decision/deterministic.js';
import type { DecisionContext, DecisionProvider } from '../decision/provider.js';
import type { NavigationDecision } from '../decision/schema.js';
import { OccupancyGrid } from '../grid/occupancy-grid.js';
import { FakeHAL } from './fake-hal.fixture.js';
import { NavigationBridge } from './navigation-bridge.js';
import type { NavigationEvents } from './navigation-bridge.js';

/** A wall across the middle of the arena with a gap at the top: x in [-0.1, 0.1], y < 1.2. */
const wall = { minX: -0.1, minY: -2.5, maxX: 0.1, maxY: 1.2 };
const wallMap = {
  arena: { width: 5, height: 5 },
  obstacles: [{ kind: 'box' as const, x: 0, y: -0.65, width: 0.2, depth: 3.7 }],
};

/** A provider that answers from a list (the last answer repeats), recording its contexts. */
class ScriptedProvider implements DecisionProvider {
  readonly name = 'scripted';
  readonly contexts: DecisionContext[] = [];
  readonly #answers: NavigationDecision[];
  constructor(answers: NavigationDecision[]) {
    this.#answers = answers;
  }
  async decide(context: DecisionContext): Promise<NavigationDecision> {
    this.contexts.push(context);
    const answer = this.#answers[Math.min(this.contexts.length - 1, this.#answers.length - 1)];
    if (answer === undefined) throw new Error('no answers scripted');
    return answer;
  }
}

const decision = (
  action: NavigationDecision['action'],
  goal_reached = false,
): NavigationDecision => ({
  reasoning: 'scripted',
  action,
  goal_reached,
});

async function ready(hal: FakeHAL): Promise<FakeHAL> {
  await hal.initialize();
  return hal;
}

afterEach(() => {
  vi.useRealTimers();
});

describe('NavigationBridge', () => {
  describe('#run', () => {
    it('reaches a goal behind a wall with the goal-seeking provider, without touching it', async () => {
      const hal = await ready(new FakeHAL({ start: { x: -1.5, y: -1, yaw: 0 }, boxes: [wall] }));
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        map: wallMap,
      });
      const events: string[] = [];
      for (const name of ['cycle', 'decision', 'path', 'result', 'done'] as const) {
        bridge.on(name, () => events.push(name));
      }
      const outcome = await bridge.run({ x: 1.5, y: -1 });
      expect(outcome.status).toBe('reached');
      expect(outcome.reason).toBe('GOAL_REACHED');
      expect(hal.collisions).toBe(0);
      expect(outcome.distanceToGoalM).toBeLessThanOrEqual(0.1);
      expect(Math.hypot(hal.x - 1.5, hal.y + 1)).toBeLessThanOrEqual(0.1);
      // It went round the top of the wall.
      expect(Math.max(...outcome.trajectory.map((p) => p.y))).toBeGreaterThan(1.2);
      expect(events.slice(0, 4)).toEqual(['cycle', 'decision', 'path', 'result']);
      expect(events.at(-1)).toBe('done');
      expect(outcome.trajectory[0]).toEqual({ x: -1.5, y: -1, yaw: 0 });
      expect(outcome.cycles).toBe(outcome.trajectory.length - 1);
    });

    it('drives legs no longer than maxLegM, each to a point the robot may stand on', async () => {
      const hal = await ready(new FakeHAL({ start: { x: -1.5, y: -1, yaw: 0 }, boxes: [wall] }));
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        map: wallMap,
        maxLegM: 0.4,
      });
      const legs: NavigationEvents['path'][] = [];
      bridge.on('path', (e) => legs.push(e));
      const outcome = await bridge.run({ x: 1.5, y: -1 });
      expect(outcome.status).toBe('reached');
      let from = outcome.trajectory[0] as { x: number; y: number };
      for (const [k, e] of legs.entries()) {
        expect(Math.hypot(e.leg.x - from.x, e.leg.y - from.y)).toBeLessThanOrEqual(0.4 + 1e-9);
        expect(bridge.grid.isTraversable(e.leg.x, e.leg.y)).toBe(true);
        from = outcome.trajectory[k + 1] as { x: number; y: number };
      }
    });

    it('maps an obstacle missing from its map with the range sensors and drives round it', async () => {
      const box = { minX: 0.4, minY: -0.5, maxX: 0.8, maxY: 0.5 };
      const hal = await ready(new FakeHAL({ start: { x: -1, y: 0, yaw: 0 }, boxes: [box] }));
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        map: { arena: { width: 5, height: 5 } },
        maxLegM: 0.3,
      });
      const outcome = await bridge.run({ x: 1.5, y: 0 });
      expect(outcome.status).toBe('reached');
      expect(hal.collisions).toBe(0);
      expect(bridge.grid.stateAt(0.42, 0)).toBe('occupied');
    });

    it('takes short legs into unknown space when it has range sensors, long ones through known space', async () => {
      const legs: number[] = [];
      const run = async (grid: OccupancyGrid) => {
        // Short-sighted sensors: what lies ahead stays unknown until the robot is nearly there.
        const hal = await ready(new FakeHAL({ start: { x: -1.5, y: 0, yaw: 0 }, maxRange: 0.1 }));
        const bridge = new NavigationBridge({
          hal,
          grid,
          provider: new GoalSeekingProvider(),
          rangeSensors: { maxRangeM: 0.1 },
        });
        legs.length = 0;
        let from = { x: -1.5, y: 0 };
        bridge.on('path', (e) => legs.push(Math.hypot(e.leg.x - from.x, e.leg.y - from.y)));
        bridge.on('cycle', (e) => {
          from = e.pose;
        });
        return bridge.run({ x: 1.5, y: 0 });
      };
      const unknown = new OccupancyGrid();
      unknown.seedFromMap({ arena: { width: 5, height: 5 } }, { freeSpace: false });
      expect((await run(unknown)).status).toBe('reached');
      expect(Math.max(...legs)).toBeLessThanOrEqual(0.15 + 1e-9);
      const known = OccupancyGrid.fromMap({ arena: { width: 5, height: 5 } });
      expect((await run(known)).status).toBe('reached');
      expect(Math.max(...legs)).toBeCloseTo(0.5, 9);
    });

    it('forgets obstacles seen only once when they close every route, and gets through', async () => {
      const hal = await ready(new FakeHAL({ start: { x: -1, y: 0, yaw: 0 } }));
      const grid = OccupancyGrid.fromMap({ arena: { width: 5, height: 5 } });
      // A stray reading's worth of wall across the whole arena.
      for (let cy = 0; cy < 100; cy += 1) grid.addEvidence(50, cy, 0.85);
      const bridge = new NavigationBridge({
        hal,
        grid,
        provider: new GoalSeekingProvider(),
        rangeSensors: false,
      });
      const outcome = await bridge.run({ x: 1, y: 0 });
      expect(outcome.status).toBe('reached');
      expect(hal.calls.some((c) => c.name === 'moveForward')).toBe(false);
    });

    it('fails with COLLISION when it hits an obstacle it could not know about, and stops the wheels', async () => {
      const box = { minX: 0.4, minY: -0.5, maxX: 0.8, maxY: 0.5 };
      const hal = await ready(
        new FakeHAL({ start: { x: -1, y: 0, yaw: 0 }, boxes: [box], rangeSensors: false }),
      );
      const bridge = new NavigationBridge({ hal, provider: new GoalSeekingProvider() });
      const outcome = await bridge.run({ x: 1.5, y: 0 });
      expect(outcome.status).toBe('failed');
      expect(outcome.reason).toBe('COLLISION');
      expect(outcome.lastResult?.code).toBe('COLLISION');
      expect(hal.collisions).toBe(1);
      expect(hal.calls.at(-1)?.name).toBe('stop');
      // The world model learned where the obstacle is.
      expect(bridge.grid.stateAt(0.42, 0)).toBe('occupied');
    });

    it('fails with EMERGENCY_STOPPED and moves no more once the emergency stop is latched', async () => {
      const hal = await ready(new FakeHAL({ start: { x: -1.5, y: 0, yaw: 0 } }));
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        maxLegM: 0.3,
      });
      let results = 0;
      bridge.on('result', () => {
        results += 1;
        if (results === 2) hal.pressEmergencyStop();
      });
      const outcome = await bridge.run({ x: 1.5, y: 0 });
      expect(outcome.status).toBe('failed');
      expect(outcome.reason).toBe('EMERGENCY_STOPPED');
      expect(hal.calls.filter((c) => c.name === 'moveTo')).toHaveLength(2);
    });

    it('fails with EMERGENCY_STOPPED when a motion is refused for the emergency stop', async () => {
      const hal = await ready(new FakeHAL());
      hal.fault = () => ({
        success: false,
        code: 'EMERGENCY_STOPPED',
        error: 'latched',
        timestamp: 0,
        mode: 'simulation',
      });
      const bridge = new NavigationBridge({ hal, provider: new GoalSeekingProvider() });
      const outcome = await bridge.run({ x: 1, y: 0 });
      expect(outcome.reason).toBe('EMERGENCY_STOPPED');
      expect(outcome.cycles).toBe(1);
    });

    it('fails with TIMEOUT, and stops the wheels, when a motion never finishes', async () => {
      vi.useFakeTimers();
      const hal = await ready(new FakeHAL());
      hal.fault = (call) => (call.name === 'moveTo' ? 'hang' : undefined);
      const bridge = new NavigationBridge({ hal, provider: new GoalSeekingProvider() });
      const running = bridge.run({ x: 1, y: 0 });
      await vi.advanceTimersByTimeAsync(120_000);
      const outcome = await running;
      expect(outcome.status).toBe('failed');
      expect(outcome.reason).toBe('TIMEOUT');
      expect(outcome.message).toContain("bridge's limit");
      expect(hal.calls.at(-1)?.name).toBe('stop');
    });

    it('fails with TIMEOUT when getPose never answers', async () => {
      vi.useFakeTimers();
      const hal = await ready(new FakeHAL());
      hal.locomotion.getPose = () => new Promise(() => undefined);
      const bridge = new NavigationBridge({ hal, provider: new GoalSeekingProvider() });
      const running = bridge.run({ x: 1, y: 0 });
      await vi.advanceTimersByTimeAsync(30_000);
      const outcome = await running;
      expect(outcome.reason).toBe('TIMEOUT');
      expect(outcome.message).toContain('getPose');
    });

    it('goes on without readings or frames when the sensors and the camera never answer', async () => {
      vi.useFakeTimers();
      const hal = await ready(new FakeHAL());
      hal.vision.getDistanceSensors = () => new Promise(() => undefined);
      hal.vision.captureFrame = () => new Promise(() => undefined);
      const frames: (string | undefined)[] = [];
      const seeking = new GoalSeekingProvider();
      const provider: DecisionProvider = {
        name: 'camera-user',
        wantsFrame: true,
        decide: (context) => {
          frames.push(context.frame);
          return seeking.decide(context);
        },
      };
      const bridge = new NavigationBridge({ hal, provider });
      const running = bridge.run({ x: 1, y: 0 });
      await vi.advanceTimersByTimeAsync(120_000);
      const outcome = await running;
      expect(outcome.status).toBe('reached');
      expect(frames.length).toBeGreaterThan(0);
      expect(frames.every((f) => f === undefined)).toBe(true);
    });

    it('fails with PROVIDER_ERROR when the provider never answers, and cancels its signal', async () => {
      let seen: AbortSignal | undefined;
      const provider: DecisionProvider = {
        name: 'silent',
        decide: (_context, signal) => {
          seen = signal;
          return new Promise(() => undefined);
        },
      };
      const hal = await ready(new FakeHAL());
      const bridge = new NavigationBridge({ hal, provider, decisionTimeoutMs: 50 });
      const outcome = await bridge.run({ x: 1, y: 0 });
      expect(outcome.reason).toBe('PROVIDER_ERROR');
      expect(outcome.message).toContain('within 50 ms');
      expect(seen?.aborted).toBe(true);
      expect(hal.calls.filter((c) => c.name !== 'stop')).toHaveLength(0);
    });

    it('fails with PROVIDER_ERROR when the provider throws', async () => {
      const provider: DecisionProvider = {
        name: 'broken',
        decide: () => Promise.reject(new Error('model offline')),
      };
      const hal = await ready(new FakeHAL());
      const outcome = await new NavigationBridge({ hal, provider }).run({ x: 1, y: 0 });
      expect(outcome.reason).toBe('PROVIDER_ERROR');
      expect(outcome.message).toContain('model offline');
    });

    it('refuses a decision that breaks the schema before anything moves', async () => {
      const provider = new ScriptedProvider([decision({ type: 'MOVE_TO', x: Number.NaN, y: 0 })]);
      const hal = await ready(new FakeHAL());
      const outcome = await new NavigationBridge({ hal, provider }).run({ x: 1, y: 0 });
      expect(outcome.status).toBe('failed');
      expect(outcome.reason).toBe('INVALID_DECISION');
      expect(hal.calls.filter((c) => c.name !== 'stop')).toHaveLength(0);
    });

    it('fails with UNREACHABLE, after nudging, when no route reaches the goal', async () => {
      // The goal sits in a closed box of walls.
      const boxes = [
        { minX: 0.8, minY: -0.6, maxX: 1.6, maxY: -0.5 },
        { minX: 0.8, minY: 0.5, maxX: 1.6, maxY: 0.6 },
        { minX: 0.8, minY: -0.6, maxX: 0.9, maxY: 0.6 },
        { minX: 1.5, minY: -0.6, maxX: 1.6, maxY: 0.6 },
      ];
      const hal = await ready(new FakeHAL({ start: { x: -1, y: 0, yaw: 0 }, boxes }));
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        map: {
          arena: { width: 5, height: 5 },
          obstacles: boxes.map((b) => ({
            kind: 'box' as const,
            x: (b.minX + b.maxX) / 2,
            y: (b.minY + b.maxY) / 2,
            width: b.maxX - b.minX,
            depth: b.maxY - b.minY,
          })),
        },
      });
      const outcome = await bridge.run({ x: 1.2, y: 0 });
      expect(outcome.status).toBe('failed');
      expect(outcome.reason).toBe('UNREACHABLE');
      expect(hal.calls.some((c) => c.name === 'moveForward' && c.args[0] === 10)).toBe(true);
      expect(hal.collisions).toBe(0);
    });

    it('fails with MAX_CYCLES when the cycle cap is reached', async () => {
      const provider = new ScriptedProvider([
        decision({ type: 'ROTATE_TO', yaw_deg: 90 }),
        decision({ type: 'ROTATE_TO', yaw_deg: 0 }),
        decision({ type: 'ROTATE_TO', yaw_deg: 90 }),
        decision({ type: 'ROTATE_TO', yaw_deg: 0 }),
      ]);
      const hal = await ready(new FakeHAL());
      const outcome = await new NavigationBridge({ hal, provider, maxCycles: 4 }).run({
        x: 1,
        y: 0,
      });
      expect(outcome.reason).toBe('MAX_CYCLES');
      expect(outcome.cycles).toBe(4);
    });

    it('fails with TIME_LIMIT when the run takes longer than maxDurationMs', async () => {
      let now = 0;
      const provider = new ScriptedProvider(
        Array.from({ length: 10 }, (_, k) =>
          decision({ type: 'ROTATE_TO', yaw_deg: 90 * (k % 2) + 90 }),
        ),
      );
      const hal = await ready(new FakeHAL());
      hal.fault = () => {
        now += 1000;
        return undefined;
      };
      const bridge = new NavigationBridge({ hal, provider, maxDurationMs: 2500, now: () => now });
      const outcome = await bridge.run({ x: 1, y: 0 });
      expect(outcome.reason).toBe('TIME_LIMIT');
    });

    it('fails with HAL_ERROR at once when the HAL is not initialised', async () => {
      const hal = new FakeHAL();
      const outcome = await new NavigationBridge({ hal, provider: new GoalSeekingProvider() }).run({
        x: 1,
        y: 0,
      });
      expect(outcome.reason).toBe('HAL_ERROR');
      expect(outcome.cycles).toBe(0);
    });

    it('fails with STUCK when motions succeed but the robot does not move', async () => {
      const hal = await ready(new FakeHAL());
      hal.fault = () => 'freeze';
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        maxStuckRecoveries: 2,
      });
      const outcome = await bridge.run({ x: 1, y: 0 });
      expect(outcome.reason).toBe('STUCK');
      // Recovery backed off and turned before giving up.
      expect(hal.calls.some((c) => c.name === 'moveBackward')).toBe(true);
      expect(hal.calls.some((c) => c.name === 'rotate')).toBe(true);
    });

    it('reports a failed motion to the provider and fails after three in a row', async () => {
      const hal = await ready(new FakeHAL());
      hal.fault = () => ({
        success: false,
        code: 'HARDWARE_ERROR',
        error: 'motor driver fault',
        timestamp: 0,
        mode: 'simulation',
      });
      const provider = new ScriptedProvider([decision({ type: 'MOVE_TO', x: 1, y: 0 })]);
      const outcome = await new NavigationBridge({ hal, provider }).run({ x: 1, y: 0 });
      expect(provider.contexts[1]?.lastResult).toEqual({
        action: 'MOVE_TO',
        success: false,
        code: 'HARDWARE_ERROR',
        error: 'motor driver fault',
      });
      expect(outcome.reason).toBe('HAL_ERROR');
      expect(outcome.cycles).toBe(3);
    });

    it('is stopped by stop() during a run, and by an aborted signal', async () => {
      const hal = await ready(new FakeHAL({ start: { x: -2, y: 0, yaw: 0 } }));
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        maxLegM: 0.2,
      });
      bridge.on('result', () => void bridge.stop());
      const outcome = await bridge.run({ x: 2, y: 0 });
      expect(outcome.status).toBe('stopped');
      expect(outcome.reason).toBe('STOP_REQUESTED');
      expect(outcome.cycles).toBe(1);
      expect(bridge.running).toBe(false);

      const aborted = new AbortController();
      aborted.abort();
      const second = await new NavigationBridge({ hal, provider: new GoalSeekingProvider() }).run(
        { x: 2, y: 0 },
        { signal: aborted.signal },
      );
      expect(second.status).toBe('stopped');
    });

    it('lets a new run start as soon as stop() resolves (a new click-to-goal)', async () => {
      const hal = await ready(new FakeHAL({ start: { x: -2, y: 0, yaw: 0 } }));
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        maxLegM: 0.2,
      });
      let second: Promise<unknown> | undefined;
      const off = bridge.on('result', () => {
        off();
        second = bridge.stop().then(() => bridge.run({ x: -1, y: 1 }));
      });
      const first = await bridge.run({ x: 2, y: 0 });
      expect(first.status).toBe('stopped');
      const next = (await second) as { status: string };
      expect(next.status).toBe('reached');
      expect(Math.hypot(hal.x + 1, hal.y - 1)).toBeLessThanOrEqual(0.1);
    });

    it('stops when the provider says STOP away from the goal, even claiming it was reached', async () => {
      const hal = await ready(new FakeHAL());
      const provider = new ScriptedProvider([decision({ type: 'STOP' }, true)]);
      const outcome = await new NavigationBridge({ hal, provider }).run({ x: 1, y: 0 });
      expect(outcome.status).toBe('stopped');
      expect(outcome.reason).toBe('PROVIDER_STOPPED');
      expect(outcome.message).toContain('claimed');
    });

    it('works without range sensors, from the known map alone', async () => {
      const hal = await ready(
        new FakeHAL({ start: { x: -1.5, y: -1, yaw: 0 }, boxes: [wall], rangeSensors: false }),
      );
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        map: wallMap,
      });
      const outcome = await bridge.run({ x: 1.5, y: -1 });
      expect(outcome.status).toBe('reached');
      expect(hal.collisions).toBe(0);
    });

    it('explores a walled room until no frontier is left', async () => {
      const hal = await ready(new FakeHAL({ arena: 1.6, start: { x: 0, y: 0, yaw: 0 } }));
      const grid = new OccupancyGrid({ widthM: 2, heightM: 2 });
      const bridge = new NavigationBridge({
        hal,
        grid,
        provider: new FrontierExplorationProvider(),
        maxCycles: 150,
      });
      const outcome = await bridge.run(null);
      expect(outcome.status).toBe('reached');
      expect(outcome.reason).toBe('EXPLORATION_COMPLETE');
      expect(hal.collisions).toBe(0);
      // The inside of the room is known.
      expect(grid.stateAt(0.5, 0.5)).toBe('free');
      expect(grid.stateAt(-0.5, -0.5)).toBe('free');
    });

    it('refuses a second run while one is in progress, and a goal that is not finite', async () => {
      const hal = await ready(new FakeHAL());
      const bridge = new NavigationBridge({ hal, provider: new GoalSeekingProvider() });
      const first = bridge.run({ x: 1, y: 0 });
      await expect(bridge.run({ x: 1, y: 0 })).rejects.toThrow('already in progress');
      await first;
      await expect(bridge.run({ x: Number.NaN, y: 0 })).rejects.toThrow('"goal"');
    });
  });

  describe('ROTATE_TO', () => {
    // yaw_deg is an absolute heading, degrees, counter-clockwise from +x (REP-103); the bridge
    // turns the shorter way. Positive is NOT a relative turn to the right.
    it.each([
      { from: 0, to: 90, direction: 'left', degrees: 90 },
      { from: 90, to: 0, direction: 'right', degrees: 90 },
      { from: 0, to: -45, direction: 'right', degrees: 45 },
      { from: 170, to: -170, direction: 'left', degrees: 20 },
      { from: 30, to: 30 + 360, direction: undefined, degrees: 0 },
    ])('turns from $from deg to the absolute heading $to deg: $direction $degrees', async (c) => {
      const hal = await ready(
        new FakeHAL({ start: { x: 0, y: 0, yaw: (c.from * Math.PI) / 180 } }),
      );
      const provider = new ScriptedProvider([
        decision({ type: 'ROTATE_TO', yaw_deg: c.to }),
        decision({ type: 'STOP' }),
      ]);
      await new NavigationBridge({ hal, provider }).run({ x: 1, y: 1 });
      const rotations = hal.calls.filter((call) => call.name === 'rotate');
      if (c.direction === undefined) {
        expect(rotations).toHaveLength(0);
      } else {
        expect(rotations).toHaveLength(1);
        expect(rotations[0]?.args[0]).toBe(c.direction);
        expect(rotations[0]?.args[1] as number).toBeCloseTo(c.degrees, 6);
      }
      const target = Math.atan2(Math.sin((c.to * Math.PI) / 180), Math.cos((c.to * Math.PI) / 180));
      expect(
        Math.abs(Math.atan2(Math.sin(hal.yaw - target), Math.cos(hal.yaw - target))),
      ).toBeLessThan((0.5 * Math.PI) / 180);
    });
  });
});
