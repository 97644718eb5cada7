import { describe, expect, it } from 'vitest';
import type { AgentTrial, EvalAgent } from '../agent.js';
import { builtinTasks } from '../builtin-tasks.js';
import { runTrial } from '../trial.js';
import { cameraNavigationAgent } from './camera-navigation.js';

const task = (id: string) => {
  const found = builtinTasks().find((t) => t.id === id);
  if (found === undefined) throw new Error(`no task ${id}`);
  return found;
};

/** The agent, keeping what each trial handed it. */
function watched(agent: EvalAgent): { agent: EvalAgent; trials: AgentTrial[] } {
  const trials: AgentTrial[] = [];
  return {
    trials,
    agent: {
      ...agent,
      name: agent.name,
      run: (trial) => {
        trials.push(trial);
        return agent.run(trial);
      },
    },
  };
}

describe('cameraNavigationAgent', () => {
  it('reaches the red box seeing only through the camera: no map, no goal point, no ground truth', async () => {
    const { agent, trials } = watched(cameraNavigationAgent());
    expect(agent.usesGroundTruth).toBe(false);
    const { score } = await runTrial(task('goals/red-box'), 1, agent);
    expect(score.success, score.failures.join('; ')).toBe(true);
    expect(score.collisions).toBe(0);
    // it was handed the words and a robot, nothing of the world
    const trial = trials[0];
    expect(trial?.truth).toBeUndefined();
    expect(trial?.truePose).toBeUndefined();
    expect(trial?.hal).toBeDefined();
    // every look and every motion went through the trial's counted tools
    expect(score.toolCalls).toBeGreaterThan(3);
    expect(score.toolCalls).toBeLessThanOrEqual(task('goals/red-box').budget.toolCalls);
  });

  it('turns to look for an object behind it, then reaches it', async () => {
    const trace: string[] = [];
    const agent = cameraNavigationAgent({
      onBridge: (bridge) => bridge.on('decision', (e) => trace.push(e.decision.action.type)),
    });
    const { score } = await runTrial(task('goals/yellow-box-behind'), 1, agent);
    expect(score.success, score.failures.join('; ')).toBe(true);
    expect(trace[0]).toBe('ROTATE_TO');
    expect(trace.at(-1)).toBe('STOP');
  });

  it('drives to a point the instruction gives in numbers, mapping with the camera on the way', async () => {
    const { score } = await runTrial(task('goals/behind-the-box'), 1, cameraNavigationAgent());
    expect(score.success, score.failures.join('; ')).toBe(true);
    expect(score.collisions).toBe(0);
  });

  it('says so, and moves nothing, when the instruction names no coloured object and no point', async () => {
    const { score } = await runTrial(task('perception/count-boxes'), 1, cameraNavigationAgent());
    expect(score.success).toBe(false);
    expect(score.toolCalls).toBe(0);
    expect(score.failures.at(-1)).toBe('agent: no object named');
  });
});
