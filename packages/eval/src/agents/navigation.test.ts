import { describe, expect, it } from 'vitest';
import { builtinTasks } from '../builtin-tasks.js';
import { runTrial } from '../trial.js';
import { navigationAgent } from './navigation.js';

const task = (id: string) => {
  const found = builtinTasks().find((t) => t.id === id);
  if (found === undefined) throw new Error(`no task ${id}`);
  return found;
};

describe('navigationAgent', () => {
  it('drives the bridge to the goal through the trial tools, each call counted', async () => {
    const { score } = await runTrial(task('goals/behind-the-box'), 1, navigationAgent());
    expect(score.success, score.failures.join('; ')).toBe(true);
    expect(score.toolCalls).toBeGreaterThan(3);
    expect(score.pathLengthM).toBeGreaterThan(score.optimalPathM ?? Infinity);
  });

  it('meets the faults and the leash of the task like any agent', async () => {
    const fault = await runTrial(
      task('robustness/move-fails'),
      1,
      navigationAgent({ name: 'nav' }),
    );
    expect(fault.score.success, fault.score.failures.join('; ')).toBe(true);
    expect(fault.score.toolCalls).toBeGreaterThan(1);
  });

  it('fails a task with no place to drive to, and says why', async () => {
    const { score } = await runTrial(task('perception/count-boxes'), 1, navigationAgent());
    expect(score.success).toBe(false);
    expect(score.failures.at(-1)).toBe('agent: no goal point');
    expect(score.toolCalls).toBe(0);
  });
});
