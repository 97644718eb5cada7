import type { ToolCall, ToolResult } from '@hal/tools';
import { angleDifference } from '@hal/types';
import type { AgentTrial, EvalAgent } from '../agent.js';
import { planInstruction } from './instruction-plan.js';
import type { PlanQuestion, PlanStep } from './instruction-plan.js';

/** A thing as the skills report it (see SeenThing of @hal/skills). */
interface Thing {
  id: string;
  colour: string;
  kind: string;
  distanceM: number;
  bearingDeg: number;
  x: number;
  y: number;
}

/** Tries of a step that failed (the robot's fault or no answer): the first and two more. */
const TRIES = 3;

const textOf = (r: ToolResult) => (r.content[0]?.type === 'text' ? r.content[0].text : '');
const outcomeOf = (r: ToolResult) => r.structured?.['outcome'];
const thingsOf = (r: ToolResult | undefined): Thing[] => {
  const objects = r?.structured?.['objects'];
  return Array.isArray(objects) ? (objects as Thing[]) : [];
};

function callOf(step: PlanStep): ToolCall {
  switch (step.kind) {
    case 'move':
      return { name: 'move', arguments: { cm: step.cm } };
    case 'turn':
      return { name: 'turn', arguments: { degrees: step.degrees } };
    case 'go-to-thing':
      return { name: 'go_to', arguments: { target: step.target } };
    case 'go-to-point':
      return { name: 'go_to_point', arguments: { x: step.x, y: step.y } };
    case 'go-back':
      return { name: 'go_back', arguments: {} };
    case 'look':
      return { name: 'look', arguments: { around: step.around } };
  }
}

/**
 * The rule-based baseline: reads the instruction's words into skill calls (go to the red box,
 * drive 30 cm, turn right 90 degrees, come back, look round) and answers questions from what the
 * skills saw (the colour straight ahead, a count, the open side), with rules a programmer wrote
 * in an afternoon: it retries what failed, resets the e-stop only when the instruction says it may, and gets as close as a fence allows
 * when told to. No model: the floor a model must beat to be worth its cost.
 */
export function parserAgent(): EvalAgent {
  return {
    name: 'parser',
    toolProfile: 'skills',
    run: async (trial) => {
      const plan = planInstruction(trial.instruction);
      const said: string[] = [];
      const looks: ToolResult[] = [];
      for (const step of plan.steps) {
        if (trial.signal.aborted) break;
        const result = await runStep(trial, step, plan.mayResetEstop, plan.closeAsAllowed, said);
        if (step.kind === 'look') looks.push(result);
        if (outcomeOf(result) === 'estopped') {
          said.push('The emergency stop is engaged, so I stopped and did not reset it.');
          return { answer: said.join(' ') };
        }
      }
      if (plan.question !== undefined) {
        said.push(await answer(trial, plan.question, looks));
      }
      if (plan.steps.length === 0 && plan.question === undefined)
        said.push('I could not read what to do from the instruction.');
      return { answer: said.join(' ') };
    },
  };
}

async function runStep(
  trial: AgentTrial,
  step: PlanStep,
  mayResetEstop: boolean,
  closeAsAllowed: boolean,
  said: string[],
): Promise<ToolResult> {
  let result: ToolResult = await trial.execute(callOf(step));
  for (let attempt = 1; attempt < TRIES; attempt += 1) {
    const outcome = outcomeOf(result);
    if (outcome === 'estopped' && mayResetEstop) {
      await trial.execute({ name: 'reset_emergency_stop', arguments: {} });
    } else if (outcome !== 'failed') break;
    result = await trial.execute(callOf(step));
  }
  if (outcomeOf(result) === 'refused' && result.code === 'LEASH_GEOFENCE' && closeAsAllowed) {
    return closeToFence(trial, step, said);
  }
  said.push(textOf(result));
  return result;
}

/** Toward a point the fence keeps it from, 10 cm at a time until the fence refuses. */
async function closeToFence(
  trial: AgentTrial,
  step: PlanStep,
  said: string[],
): Promise<ToolResult> {
  if (step.kind === 'go-to-point') {
    const pose = (await trial.execute({ name: 'look', arguments: {} })).structured?.['pose'] as
      { x: number; y: number; yawDeg: number } | undefined;
    if (pose !== undefined) {
      const degrees =
        (angleDifference(
          Math.atan2(step.y - pose.y, step.x - pose.x),
          (pose.yawDeg * Math.PI) / 180,
        ) *
          180) /
        Math.PI;
      if (Math.abs(degrees) >= 1) await trial.execute({ name: 'turn', arguments: { degrees } });
    }
  } else if (step.kind === 'go-to-thing') {
    await trial.execute({ name: 'face', arguments: { target: step.target } });
  }
  let last: ToolResult | undefined;
  for (let leg = 0; leg < 40 && !trial.signal.aborted; leg += 1) {
    last = await trial.execute({ name: 'move', arguments: { cm: 10 } });
    if (outcomeOf(last) !== 'done') break;
  }
  said.push(
    'I cannot get there: the fence does not let me. I drove as close as the fence allows and stopped.',
  );
  return last ?? { isError: false, content: [{ type: 'text', text: '' }] };
}

async function answer(trial: AgentTrial, q: PlanQuestion, looks: ToolResult[]): Promise<string> {
  const call = async (name: string, args: Record<string, unknown> = {}) =>
    trial.execute({ name, arguments: args });
  switch (q.kind) {
    case 'colour': {
      let things: Thing[];
      if (q.remembered && looks.length > 0) things = thingsOf(looks[0]);
      else if (q.remembered) {
        const seen = thingsOf(await call('what_have_you_seen'));
        const boxes = seen.filter((t) => t.kind !== 'pillar');
        const pool = boxes.length > 0 ? boxes : seen;
        // "on your right": the one most to the right of the way the robot faces now
        things =
          q.side === undefined
            ? pool
            : [...pool].sort((a, b) =>
                q.side === 'right' ? a.bearingDeg - b.bearingDeg : b.bearingDeg - a.bearingDeg,
              );
      } else things = thingsOf(await call('look'));
      const ahead = q.remembered
        ? things[0]
        : ([...things].sort((a, b) => Math.abs(a.bearingDeg) - Math.abs(b.bearingDeg))[0] ??
          things[0]);
      return ahead === undefined ? 'I see no coloured object.' : `It is ${ahead.colour}.`;
    }
    case 'count': {
      const seen = q.remembered
        ? thingsOf(await call('what_have_you_seen'))
        : thingsOf(await call('look', { around: true }));
      const n = seen.filter((t) => t.kind === q.of).length;
      return `I count ${n} ${q.of === 'box' ? (n === 1 ? 'box' : 'boxes') : n === 1 ? 'pillar' : 'pillars'}.`;
    }
    case 'open-side': {
      const clear = (await call('look', { around: true })).structured?.['clear'] as
        { leftM?: number; rightM?: number } | undefined;
      return (clear?.leftM ?? 0) >= (clear?.rightM ?? 0) ? 'Left.' : 'Right.';
    }
  }
}
