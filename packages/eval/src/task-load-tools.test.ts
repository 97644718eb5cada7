import { HAL_CALL_TABLE } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { EvalError } from './errors.js';
import { parseTaskFile } from './task-load.js';

const taskWithFault = (fault: Record<string, unknown>) =>
  JSON.stringify({
    version: 1,
    tasks: [
      {
        id: 'goals/blue-box',
        group: 'goals',
        instruction: 'Drive to the blue box.',
        world: {
          start: { x: 0, y: 0 },
          objects: [{ name: 'blue-box', kind: 'box', colour: 'blue', x: 1, y: 0 }],
        },
        checks: [{ kind: 'reach-object', object: 'blue-box', withinM: 0.25 }],
        faults: [fault],
      },
    ],
  });

describe('parseTaskFile: the tools a fault may name', () => {
  it('accepts a fault on every tool of the call table', () => {
    for (const spec of HAL_CALL_TABLE) {
      for (const kind of ['fail', 'timeout']) {
        const tasks = parseTaskFile(taskWithFault({ kind, tool: spec.tool.name }), 'tools.json');
        expect(tasks[0]?.faults[0], spec.tool.name).toMatchObject({ tool: spec.tool.name });
      }
    }
  });

  it('refuses a fault on an unknown tool with TASK_INVALID, naming the field and the tools', () => {
    let caught: unknown;
    try {
      parseTaskFile(taskWithFault({ kind: 'fail', tool: 'launch_rocket' }), 'tools.json');
    } catch (error) {
      caught = error;
    }
    expect(caught).toBeInstanceOf(EvalError);
    const error = caught as EvalError;
    expect(error.code).toBe('TASK_INVALID');
    expect(error.field).toBe('tasks.0.faults.0.tool');
    expect(error.message).toContain('"launch_rocket", which is no tool');
    expect(error.message).toContain('get_line_sensors');
    expect(error.message).toContain('"motion"');
  });
});
