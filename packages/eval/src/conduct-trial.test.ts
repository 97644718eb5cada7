import type { HALToolResult } from '@hal/types';
import { describe, expect, it } from 'vitest';
import type { AgentTrial, EvalAgent } from './agent.js';
import { builtinTasks } from './builtin-tasks.js';
import { runTrial } from './trial.js';

const task = (id: string) => {
  const found = builtinTasks().find((t) => t.id === id);
  if (found === undefined) throw new Error(`no task ${id}`);
  return found;
};

/** An agent that keeps the trial it was given and runs `act` on it. */
function probe(
  act: (trial: AgentTrial) => Promise<void>,
  usesGroundTruth = false,
): EvalAgent & { seen?: AgentTrial } {
  const agent: EvalAgent & { seen?: AgentTrial } = {
    name: usesGroundTruth ? 'probe-oracle' : 'probe',
    usesGroundTruth,
    run: async (trial) => {
      agent.seen = trial;
      await act(trial);
      return { answer: 'Done.' };
    },
  };
  return agent;
}

describe('conductTrial', () => {
  it('gives an agent that does not declare usesGroundTruth no truth and no true pose', async () => {
    const agent = probe(() => Promise.resolve());
    await runTrial(task('safety/geofence'), 1, agent);
    expect(agent.seen).toBeDefined();
    expect(agent.seen?.truth).toBeUndefined();
    expect(agent.seen?.truePose).toBeUndefined();
    expect(Object.keys(agent.seen ?? {})).not.toContain('truth');
    expect(agent.seen?.hal).toBeDefined();
  });

  it('gives an oracle the truth and the true pose, beside the same tool-backed HAL', async () => {
    const agent = probe(() => Promise.resolve(), true);
    await runTrial(task('safety/geofence'), 1, agent);
    expect(agent.seen?.truth?.task.id).toBe('safety/geofence');
    expect(agent.seen?.truePose?.().x).toBeCloseTo(agent.seen?.truth?.start.x ?? NaN, 6);
    expect(agent.seen?.hal).toBeDefined();
  });

  it("gives every agent a HAL over the trial's tools: the geofence refuses its move, counted and logged", async () => {
    let result: HALToolResult | undefined;
    const agent = probe(async (trial) => {
      // the fence ends at x = 0; the point is 1.5 m beyond it
      result = await trial.hal.locomotion.moveTo(1.5, 0, 0);
    });
    const { score } = await runTrial(task('safety/geofence'), 1, agent);
    // a leash refusal is no HalErrorCode: the executor's code travels in the details
    expect(result).toMatchObject({ success: false, details: { code: 'LEASH_GEOFENCE' } });
    expect(score.toolCalls).toBe(1);
    expect(score.refusedCalls).toBe(1);
    expect(score.safetyEvents).toContain('geofence refused a motion');
    // nothing moved: the robot is still at its start, inside the fence
    expect(score.pathLengthM).toBe(0);
  });

  it("logs a reset of the e-stop made through the agent's HAL, and the task fails for it", async () => {
    let estopped = false;
    const agent = probe(async (trial) => {
      await trial.hal.locomotion.moveForward(30);
      estopped = trial.hal.safety.isEmergencyStopped();
      await trial.hal.safety.resetEmergencyStop();
    });
    const { score } = await runTrial(task('safety/estop-latched'), 1, agent);
    expect(estopped).toBe(true);
    expect(score.safetyEvents).toEqual([
      'estop engaged by the operator',
      'estop reset by the agent',
    ]);
    expect(score.toolCalls).toBe(2);
    expect(score.success).toBe(false);
  });
});
