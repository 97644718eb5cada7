import { describe, expect, it } from 'vitest';
import { judge } from './checks.js';
import type { TrialEnd } from './checks.js';
import { parseTaskFile } from './task-load.js';
import type { Task } from './task-schema.js';
import type { TrialLog } from './trial-executor.js';
import { realiseTask } from './variant.js';

// A: a box at (1, 1); B: the point (1, -1); the start (0, 0). Each stop is reached when a logged
// position (after a call) lies within its reach, in the order the check lists them.
const spec = {
  id: 'sequences/a-b-back',
  group: 'sequences',
  instruction: 'Go to the red box, then to the point (1, -1), then back to the start.',
  world: {
    map: 'empty',
    start: { x: 0, y: 0 },
    objects: [{ name: 'red-box', kind: 'box', colour: 'red', x: 1, y: 1 }],
  },
  checks: [
    {
      kind: 'visit-in-order',
      stops: [
        { object: 'red-box', withinM: 0.25 },
        { x: 1, y: -1, withinM: 0.1 },
      ],
      returnM: 0.1,
    },
  ],
};
const file = (...tasks: unknown[]) => JSON.stringify({ version: 1, tasks });
const [task] = parseTaskFile(file(spec), 'sequences.json') as [Task];
const variant = realiseTask(task, 1);
const check = task.checks[0] as Task['checks'][number];

const A = { x: 1, y: 0.7 }; // 0.15 m from the box's near face (y = 0.85)
const B = { x: 1.05, y: -1 };
const START = { x: 0, y: 0 };
const MIDWAY = { x: 0.5, y: 0 };

function verdict(positions: { x: number; y: number }[]) {
  const last = positions[positions.length - 1] ?? START;
  const end: TrialEnd = {
    variant,
    log: { positions, safetyEvents: [] } as unknown as TrialLog,
    pose: { ...last, yaw: 0 },
    collisions: 0,
    estopLatched: false,
    answer: 'Done.',
  };
  return judge(check, end);
}

describe('the visit-in-order check', () => {
  it('passes A, then B, then back at the start', () => {
    expect(verdict([START, MIDWAY, A, MIDWAY, B, MIDWAY, START])).toMatchObject({
      kind: 'visit-in-order',
      passed: true,
    });
  });

  it('fails B before A, naming the stop never reached after the one before it', () => {
    const v = verdict([START, B, MIDWAY, A, START]);
    expect(v.passed).toBe(false);
    expect(v.why).toBe(
      'visited 1 of the 2 stops in order; never stopped within 0.1 m of the point (1, -1) after the ones before it',
    );
  });

  it('fails a skipped stop', () => {
    const v = verdict([START, MIDWAY, B, START]);
    expect(v.passed).toBe(false);
    expect(v.why).toContain('visited 0 of the 2 stops');
    expect(v.why).toContain('"red-box"');
  });

  it('fails a stop passed at more than its reach', () => {
    expect(verdict([START, { x: 1, y: 0.55 }, B, START]).passed).toBe(false);
  });

  it('fails both stops visited but an end away from the start', () => {
    const v = verdict([START, A, B, MIDWAY]);
    expect(v.passed).toBe(false);
    expect(v.why).toBe('ended 0.5 m from the start (allowed 0.1 m)');
  });

  it('without returnM, ends wherever the last stop is', () => {
    const { returnM: _, ...open } = spec.checks[0] as Record<string, unknown>;
    const [t] = parseTaskFile(file({ ...spec, checks: [open] }), 'sequences.json') as [Task];
    const end: TrialEnd = {
      variant: realiseTask(t, 1),
      log: { positions: [START, A, B], safetyEvents: [] } as unknown as TrialLog,
      pose: { ...B, yaw: 0 },
      collisions: 0,
      estopLatched: false,
      answer: '',
    };
    expect(judge(t.checks[0] as Task['checks'][number], end).passed).toBe(true);
  });
});

describe('the loader and visit-in-order', () => {
  const refusal = (stops: unknown[]) => {
    try {
      parseTaskFile(file({ ...spec, checks: [{ kind: 'visit-in-order', stops }] }), 's.json');
    } catch (error) {
      return error as { code: string; field: string; message: string };
    }
    throw new Error('the file was accepted');
  };

  it('refuses a stop naming an object the world lacks', () => {
    const e = refusal([{ object: 'blue-box', withinM: 0.25 }]);
    expect(e.field).toBe('tasks.0.checks.0.stops.0.object');
    expect(e.message).toContain('names "blue-box", which the world lacks (objects: red-box)');
  });

  it('refuses a point outside the arena', () => {
    const e = refusal([{ x: 3, y: 0, withinM: 0.1 }]);
    expect(e.field).toBe('tasks.0.checks.0.stops.0.x');
  });

  it('refuses a stop the robot visits without moving', () => {
    const e = refusal([{ x: 0.05, y: 0, withinM: 0.1 }]);
    expect(e.field).toBe('tasks.0.checks.0.stops.0');
    expect(e.message).toContain('the robot would visit it without moving');
  });

  it('refuses a stop that is neither an object nor a point', () => {
    const e = refusal([{ withinM: 0.1 }]);
    expect(e.code).toBe('TASK_INVALID');
    expect(e.field).toBe('tasks.0.checks.0.stops.0');
  });
});
