import { describe, expect, it } from 'vitest';
import type { AgentTrial, EvalAgent } from './agent.js';
import { builtinTasks } from './builtin-tasks.js';
import { runEval } from './run-eval.js';
import { wrapAngle } from './truth.js';

interface Seen {
  imuHeading: number;
  odometryYaw: number;
  trueYaw: number;
  scan: Record<string, unknown>;
}

/**
 * A probe, not an agent under test: it drives a little, then reads the IMU, the pose and a scan
 * through the tools as any agent does, and (declaring ground truth) the true pose beside them.
 */
function probe(seen: Seen[]): EvalAgent {
  return {
    name: 'probe',
    usesGroundTruth: true,
    run: async (trial: AgentTrial) => {
      const call = async (name: string, args: Record<string, unknown> = {}) =>
        (await trial.execute({ name, arguments: args })).structured ?? {};
      await call('rotate', { direction: 'left', degrees: 90 });
      await call('move_forward', { distanceCm: 20 });
      await call('rotate', { direction: 'right', degrees: 90 });
      const imu = await call('get_imu');
      const pose = await call('get_pose');
      const scan = await call('scan', { mode: 'full' });
      seen.push({
        imuHeading: Number(imu['heading']),
        odometryYaw: Number((pose['rotation'] as { yaw: number }).yaw),
        trueYaw: trial.truePose?.().yaw ?? Number.NaN,
        scan,
      });
      return { answer: 'green' };
    },
  };
}

describe("what an agent's sensors tell it in a trial", () => {
  it('with odometry noise, the IMU heading is neither the true yaw nor the odometry, and scan names nothing of the task', async () => {
    const tasks = builtinTasks(['perception']).filter((t) => t.id === 'perception/colour-ahead');
    const seen: Seen[] = [];
    await runEval({
      tasks,
      agents: [probe(seen)],
      trials: 2,
      seed: 5,
      reality: { odometryNoisePct: 3 },
    });
    expect(seen).toHaveLength(2);
    for (const s of seen) {
      expect(Number.isFinite(s.imuHeading)).toBe(true);
      expect(Math.abs(wrapAngle(s.imuHeading - s.trueYaw))).toBeGreaterThan(1e-5);
      expect(s.imuHeading).not.toBe(s.odometryYaw);
      expect(s.scan['frame']).toBe('odometry');
      const objects = s.scan['objects'] as { id: string; type: string; sensor: string }[];
      const range = objects.filter((o) => o.sensor === 'range');
      const camera = objects.filter((o) => o.sensor === 'camera');
      expect(range.length).toBeGreaterThan(0);
      // the range sensors cannot tell what they saw; their ids are for this scan only
      for (const [i, o] of range.entries()) {
        expect(o.id).toBe(`seen-${i + 1}`);
        expect(o.type).toBe('obstacle');
      }
      // the camera names what it sees by its colour and shape, never by the task's names
      for (const o of camera) expect(o.id).toMatch(/^[a-z]+ (box|pillar|object) \d+$/);
      expect(objects.length).toBe(range.length + camera.length);
      expect(JSON.stringify(s.scan)).not.toMatch(/ahead|left-one|right-one|cylinder/);
    }
  }, 60_000);
});
