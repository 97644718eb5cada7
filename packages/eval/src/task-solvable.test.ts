import { describe, expect, it } from 'vitest';
import { builtinTasks } from './builtin-tasks.js';
import { EvalError } from './errors.js';
import { parseTaskFile } from './task-load.js';

// A task the loader must refuse is one no agent could pass, or one whose 0 the report would
// blame on the agent: a start inside an obstacle (for some seed), an object out of reach, a
// question with no true answer.

const pillarMap = {
  name: 'pillar',
  obstacles: [
    { kind: 'box', x: -1.5, y: -1.5, width: 0.3, depth: 0.3 },
    { kind: 'cylinder', x: 0.5, y: 0.5, radius: 0.2 },
  ],
};
const base = {
  id: 'goals/blue-box',
  group: 'goals',
  instruction: 'Drive to the blue box.',
  world: {
    map: pillarMap,
    start: { x: 0, y: 0 },
    objects: [{ name: 'blue-box', kind: 'box', colour: 'blue', x: 1.5, y: 0 }],
  },
  checks: [{ kind: 'reach-object', object: 'blue-box', withinM: 0.25 }],
};
type Change = Record<string, unknown>;
const task = (world: Change = {}, rest: Change = {}) => ({
  ...base,
  ...rest,
  world: { ...base.world, ...world },
});
const file = (...tasks: unknown[]) => JSON.stringify({ version: 1, tasks });

function refusal(text: string): EvalError {
  try {
    parseTaskFile(text, 'my-tasks.json');
  } catch (error) {
    if (error instanceof EvalError) return error;
    throw error;
  }
  throw new Error('the file was accepted');
}
const accepted = (text: string) => parseTaskFile(text, 'my-tasks.json');

describe('the loader refuses a task no agent could pass', () => {
  it('accepts the task it starts from', () => {
    expect(accepted(file(task()))).toHaveLength(1);
  });

  it("refuses a start inside one of the map's obstacles, naming it", () => {
    const error = refusal(file(task({ start: { x: 0.5, y: 0.5 } })));
    expect(error.code).toBe('TASK_INVALID');
    expect(error.field).toBe('tasks.0.world.start');
    expect(error.message).toContain('my-tasks.json: "tasks.0.world.start"');
    expect(error.message).toContain("inside the map's obstacle 1");
  });

  it('refuses a start that the jitter can push into an obstacle, and accepts it without', () => {
    // 0.2 m (pillar) + 0.07 m (robot) = 0.27 m is contact; the start is 0.3 m from its centre
    const near = { start: { x: 0.5, y: 0.2 } };
    expect(accepted(file(task(near)))).toHaveLength(1);
    const error = refusal(file(task(near, { variants: { startM: 0.1 } })));
    expect(error.field).toBe('tasks.0.world.start');
    expect(error.message).toContain('(0.5 m, 0.2 m) ± 0.1 m');
    expect(error.message).toContain("can lie inside the map's obstacle 1");
  });

  it('refuses a start that an object placed with its jitter can cover', () => {
    // box edge at x = 1.35; robot reaches 1.07 + 0.1 (start) + 0.2 (object) = 1.37 > 1.35
    const near = { start: { x: 1, y: 0 } };
    expect(accepted(file(task(near, { variants: { startM: 0.1 } })))).toHaveLength(1);
    const error = refusal(file(task(near, { variants: { startM: 0.1, objectsM: 0.2 } })));
    expect(error.field).toBe('tasks.0.world.start');
    expect(error.message).toContain('can lie inside "blue-box" (placed ± 0.2 m)');
  });

  it("refuses an object inside one of the map's obstacles", () => {
    const objects = [{ name: 'blue-box', kind: 'box', colour: 'blue', x: -1.4, y: -1.4 }];
    const error = refusal(file(task({ objects })));
    expect(error.field).toBe('tasks.0.world.objects.0');
    expect(error.message).toContain(
      '"blue-box" at (-1.4 m, -1.4 m), where it can lie inside the map\'s obstacle 0',
    );
  });

  it('refuses an object outside the arena', () => {
    const objects = [{ name: 'blue-box', kind: 'box', colour: 'blue', x: 1.5, y: 2.6 }];
    const error = refusal(file(task({ objects })));
    expect(error.field).toBe('tasks.0.world.objects.0.y');
    expect(error.message).toContain('"blue-box" outside the 5 x 5 m arena');
  });

  it('refuses a colour question with nothing ahead of the start', () => {
    const colour = task(
      { start: { x: 0, y: 0, yawDeg: 90 } },
      {
        id: 'perception/colour',
        group: 'perception',
        checks: [{ kind: 'answer', question: 'colour-ahead' }],
      },
    );
    const error = refusal(file(colour));
    expect(error.field).toBe('tasks.0.checks.0.question');
    expect(error.message).toContain(
      'is colour-ahead, but nothing is ahead of the start, at (0, 0) facing 90°',
    );
    // facing the box, it has an answer
    expect(
      accepted(file({ ...colour, world: { ...colour.world, start: { x: 0, y: 0 } } })),
    ).toHaveLength(1);
  });

  it('refuses a colour question that some seed leaves with nothing ahead', () => {
    const colour = task(
      {},
      {
        id: 'perception/colour',
        group: 'perception',
        variants: { objectsM: 0.5 },
        checks: [{ kind: 'answer', question: 'colour-ahead' }],
      },
    );
    const error = refusal(file(colour));
    expect(error.field).toBe('tasks.0.checks.0.question');
    expect(error.message).toMatch(
      /with seed \d+ \(.*objects ± 0\.5 m\) nothing is ahead of the start$/,
    );
  });

  it('refuses a side question whose two sides are about as open', () => {
    const side = (y: number, variants: Change = {}) => ({
      id: 'perception/side',
      group: 'perception',
      instruction: 'Which side is open?',
      world: { map: 'empty', start: { x: 0, y } },
      variants,
      checks: [{ kind: 'answer', question: 'open-side' }],
    });
    const error = refusal(file(side(0)));
    expect(error.field).toBe('tasks.0.checks.0.question');
    expect(error.message).toContain(
      'is open-side, but neither side of the start is the open one (2.5 m free to the left, 2.5 m to the right',
    );
    expect(accepted(file(side(1)))).toHaveLength(1);
    // 0.1 m off the middle is clear as written, but a seed's ± 0.2 m can bring it back
    expect(accepted(file(side(0.1)))).toHaveLength(1);
    expect(refusal(file(side(0.1, { startM: 0.2 }))).message).toMatch(
      /with seed \d+ .* neither side/,
    );
  });

  it('refuses a memory question about no object, an absent one or one a seed may leave out', () => {
    const memory = (check: Change, variants: Change = {}) =>
      task(
        {},
        {
          id: 'memory/colour',
          group: 'memory',
          variants,
          checks: [{ kind: 'answer', question: 'colour-of', ...check }],
        },
      );
    expect(accepted(file(memory({ object: 'blue-box' })))).toHaveLength(1);
    const none = refusal(file(memory({})));
    expect(none.field).toBe('tasks.0.checks.0.object');
    expect(none.message).toContain('a "colour-of" question names its object');
    expect(refusal(file(memory({ object: 'red-box' }))).message).toContain(
      'names "red-box", which the world lacks (objects: blue-box)',
    );
    expect(
      refusal(file(memory({ object: 'blue-box' }, { maybeObjects: ['blue-box'] }))).message,
    ).toContain('lets a seed leave out');
  });

  it('refuses a pillar count with no pillar in its area, and an area on a colour question', () => {
    const count = (check: Change) =>
      task(
        {},
        {
          id: 'memory/count',
          group: 'memory',
          checks: [{ kind: 'answer', question: 'count-pillars', ...check }],
        },
      );
    const error = refusal(file(count({})));
    expect(error.field).toBe('tasks.0.checks.0.question');
    expect(error.message).toContain('asks to count pillars, but the world has no cylinder objects');
    const area = { minX: -1, maxX: 1, minY: -1, maxY: 1 };
    const colour = task({}, { checks: [{ kind: 'answer', question: 'colour-ahead', area }] });
    expect(refusal(file(colour)).field).toBe('tasks.0.checks.0.area');
  });

  it('loads every built-in task', () => {
    expect(builtinTasks().length).toBeGreaterThanOrEqual(60);
  });
});

describe('a task whose seed may mirror the world across y = 0', () => {
  it('is refused when the mirrored start lies on an obstacle the map has on one side only', () => {
    // the pillar is at (0.5, 0.5); a start at (0.5, -0.5) is clear, its mirror is not
    const start = { start: { x: 0.5, y: -0.5 } };
    expect(accepted(file(task(start)))).toHaveLength(1);
    const error = refusal(file(task(start, { variants: { mirror: true } })));
    expect(error.field).toBe('tasks.0.world.start');
    expect(error.message).toContain("can lie inside the map's obstacle 1");
    expect(error.message).toContain('in the world mirrored across y = 0');
  });
});
