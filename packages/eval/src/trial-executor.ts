import { createSkills, toolProfile } from '@hal/skills';
import type { ToolProfile } from '@hal/skills';
import { createToolExecutor, halTools, REFUSAL_CODES, toolBackedHal } from '@hal/tools';
import type { AgentTool, Leash, ToolCall, ToolResult } from '@hal/tools';
import { SeededRandom } from '@hal/simulation';
import type { HardwareAbstractionLayer } from '@hal/types';
import type { TrialBody } from './bodies/trial-body.js';
import type { Reality } from './reality.js';
import { variantSeed } from './variant.js';
import { ANY_MOTION } from './task-schema.js';
import type { Fault, Task } from './task-schema.js';

/** Refusals the trial counts: nothing ran (the leash, validation, budgets), or the e-stop held it. */
const REFUSED = new Set([...REFUSAL_CODES, 'EMERGENCY_STOPPED']);

/**
 * Whether a motion call asks to move at all: at least 1 cm or 1° (move_to and wheel speeds always
 * count). A `motion` fault counts only these, so a throwaway nudge does not use it up.
 */
export function asksToMove(call: ToolCall): boolean {
  let args: unknown = call.arguments;
  if (typeof args === 'string') {
    try {
      args = JSON.parse(args) as unknown;
    } catch {
      return true;
    }
  }
  if (typeof args !== 'object' || args === null) return true;
  const size = (v: unknown) => (typeof v === 'number' ? Math.abs(v) : undefined);
  const cm = size((args as Record<string, unknown>)['distanceCm']);
  if (cm !== undefined) return cm >= 1;
  const degrees = size((args as Record<string, unknown>)['degrees']);
  if (degrees !== undefined) return degrees >= 1;
  return true;
}

/** What the executor saw during one trial (read from the trial's body: see TrialBody). */
export interface TrialLog {
  /** The agent's calls (a skill is one, whatever it does inside). */
  toolCalls: number;
  /** The HAL tool calls the agent's skills made (not counted against the budget's calls). */
  skillCalls: number;
  refusedCalls: number;
  /** Motion calls that ran (refused ones aside). */
  motions: number;
  /** Safety events in the order they happened, e.g. `estop engaged by the operator`. */
  safetyEvents: string[];
  /** Distance the robot's centre travelled, metres (see TrialBody.around). */
  pathLengthM: number;
  /** The robot's position after each call (the body's), metres, starting with the start. */
  positions: { x: number; y: number }[];
  /** Whether the budget ran out (a call was refused for it). */
  overBudget: boolean;
  /** Calls the `lossRate` knob lost. */
  lostCalls: number;
}

/** The executor an agent gets in a trial, and what it recorded. */
export interface TrialExecutor {
  tools: AgentTool[];
  execute(call: ToolCall): Promise<ToolResult>;
  readonly log: TrialLog;
}

function refusal(code: string, message: string): ToolResult {
  return {
    isError: true,
    code,
    content: [{ type: 'text', text: JSON.stringify({ error: message, code }) }],
    structured: { error: message, code },
  };
}

/** Options of {@link createTrialExecutor}. */
export interface TrialExecutorOptions {
  /** Narrows the HAL tools offered (names). */
  toolNames?: readonly string[];
  leash?: Leash;
  reality?: Reality;
  seed?: number;
  /**
   * What the agent is offered: `primitives` (the HAL tools, the default), `skills` (the skills of
   * @hal/skills with the stop and e-stop) or `all`.
   */
  profile?: ToolProfile;
}

/**
 * The tools over the trial's HAL under the task's leash, with the task's faults injected, the
 * budget enforced and every call counted, each measured on `body`. `toolNames` narrows the tools
 * offered. With skills, each skill call counts once against the budget's calls; the HAL calls it
 * makes meet the leash, the faults, the simulated time budget and the log as the agent's own do.
 */
export function createTrialExecutor(
  hal: HardwareAbstractionLayer,
  body: TrialBody,
  task: Task,
  options: TrialExecutorOptions = {},
): TrialExecutor {
  const reality = options.reality;
  const random = new SeededRandom((variantSeed(task.id, options.seed ?? 1) ^ 0x9e3779b9) >>> 0);
  const leash: Leash = { ...options.leash };
  if (task.leash?.maxDistanceM !== undefined) leash.maxDistanceM = task.leash.maxDistanceM;
  if (task.leash?.geofence !== undefined) leash.geofence = task.leash.geofence;
  const tools = halTools(
    hal,
    options.toolNames === undefined ? {} : { include: [...options.toolNames] },
  );
  const inner = createToolExecutor(hal, { leash, tools });
  const motionTools = new Set(tools.filter((t) => t.motion).map((t) => t.name));
  const start = body.pose();
  const log: TrialLog = {
    toolCalls: 0,
    skillCalls: 0,
    refusedCalls: 0,
    motions: 0,
    safetyEvents: [],
    pathLengthM: 0,
    positions: [{ x: start.x, y: start.y }],
    overBudget: false,
    lostCalls: 0,
  };
  const callsOf = new Map<string, number>();
  let motionCalls = 0;
  const faults: Fault[] = task.faults;
  const budgetUs = task.budget.simSeconds * 1e6;

  /** The fault this call meets, if any (the counts already include the call). */
  function injected(name: string, countsAsMotion: boolean): ToolResult | undefined {
    const n = callsOf.get(name) ?? 0;
    for (const fault of faults) {
      if (fault.kind === 'estop') continue;
      const hit =
        fault.tool === ANY_MOTION
          ? countsAsMotion && motionCalls === fault.nth
          : fault.tool === name && n === fault.nth;
      if (!hit) continue;
      return fault.kind === 'timeout'
        ? refusal('TIMEOUT', `${name}: no answer from the robot in time; nothing moved`)
        : refusal(fault.code, `${name}: the robot reported ${fault.code}; nothing moved`);
    }
    return undefined;
  }

  /** Counts an agent's call against the budget; the refusal when it is spent. */
  function overBudget(call: ToolCall): ToolResult | undefined {
    if (log.toolCalls < task.budget.toolCalls && body.nowUs() <= budgetUs) return undefined;
    log.overBudget = true;
    log.refusedCalls += 1;
    return refusal('BUDGET_EXCEEDED', `${call.name}: the task's budget is spent; answer now`);
  }

  async function execute(call: ToolCall): Promise<ToolResult> {
    const spent = overBudget(call);
    if (spent !== undefined) return spent;
    log.toolCalls += 1;
    return perform(call);
  }

  /** A HAL tool call a skill makes: bounded by the simulated time budget, not the call count. */
  async function fromSkill(call: ToolCall): Promise<ToolResult> {
    if (body.nowUs() > budgetUs && call.name !== 'stop' && call.name !== 'emergency_stop') {
      log.overBudget = true;
      log.refusedCalls += 1;
      return refusal('BUDGET_EXCEEDED', `${call.name}: the task's time is spent; answer now`);
    }
    log.skillCalls += 1;
    return perform(call);
  }

  /** One HAL tool call: faults, reality, the leash (in `inner`), the log. */
  async function perform(call: ToolCall): Promise<ToolResult> {
    callsOf.set(call.name, (callsOf.get(call.name) ?? 0) + 1);
    const countsAsMotion = motionTools.has(call.name) && asksToMove(call);
    if (countsAsMotion) motionCalls += 1;
    const fault = injected(call.name, countsAsMotion);
    if (fault !== undefined) return fault;
    const safety = call.name === 'stop' || call.name === 'emergency_stop';
    if (reality !== undefined && !safety) {
      if (reality.latencyMs > 0) await body.delay(reality.latencyMs);
      if (reality.lossRate > 0 && random.next() < reality.lossRate) {
        log.lostCalls += 1;
        return refusal(
          'TIMEOUT',
          `${call.name}: no answer from the robot in time (the call was lost); nothing moved`,
        );
      }
    }
    const { result, pathM } = await body.around(() => inner.execute(call));
    log.pathLengthM += pathM;
    const at = body.pose();
    log.positions.push({ x: at.x, y: at.y });
    if (result.isError && result.code !== undefined && REFUSED.has(result.code)) {
      log.refusedCalls += 1;
      if (result.code === 'LEASH_GEOFENCE') log.safetyEvents.push('geofence refused a motion');
    }
    if (call.name === 'emergency_stop' && !result.isError)
      log.safetyEvents.push('estop engaged by the agent');
    if (call.name === 'reset_emergency_stop' && !result.isError)
      log.safetyEvents.push('estop reset by the agent');
    if (motionTools.has(call.name) && !(result.isError && REFUSED.has(result.code ?? ''))) {
      log.motions += 1;
      for (const f of faults) {
        if (f.kind === 'estop' && f.afterMotions === log.motions && !body.emergencyStopped()) {
          await hal.safety.emergencyStop('operator pressed the emergency stop');
          log.safetyEvents.push('estop engaged by the operator');
        }
      }
    }
    return result;
  }

  const profile = options.profile ?? 'primitives';
  if (profile === 'primitives') return { tools: inner.tools, execute, log };
  // the skills drive the trial's robot through `fromSkill`: every motion inside them is leashed,
  // faulted and logged; the guard is already under `hal` when the trial has one
  const skills = createSkills(toolBackedHal(hal, fromSkill));
  const offered = toolProfile(profile, { tools: inner.tools, execute: perform }, skills);
  return {
    tools: offered.tools,
    execute: async (call) => {
      const spent = overBudget(call);
      if (spent !== undefined) return spent;
      log.toolCalls += 1;
      return offered.execute(call);
    },
    log,
  };
}
