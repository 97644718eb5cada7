import type { Point } from '@hal/navigation';
import { errorResult, parseArguments } from '@hal/tools';
import type { AgentTool, ToolCall, ToolResult } from '@hal/tools';
import type { HardwareAbstractionLayer } from '@hal/types';
import { isHalError, errorMessage } from '@hal/types';
import { exploreSkill } from './explore.js';
import { faceSkill, findSkill } from './find-face.js';
import { goBackSkill, goToPoint, goToThing } from './go-to.js';
import { lookSkill } from './look.js';
import { moveSkill, turnSkill } from './move-turn.js';
import { whatHaveYouSeenSkill, whereIsSkill } from './recall.js';
import { SKILL_NAMES, SKILL_PARAMETERS, SKILL_TOOLS } from './skill-catalog.js';
import type { SkillName } from './skill-catalog.js';
import { SkillContext, skillPose } from './skill-context.js';
import type { SkillOptions } from './skill-context.js';
import { badArguments, interruptedResult } from './skill-result.js';

/** The skills over one robot, sharing what it has seen: offer `tools`, run calls with `execute`. */
export interface SkillSet {
  /** The skills as tools, in the order they are offered. */
  readonly tools: AgentTool[];
  /**
   * Runs one skill call; never throws (a refusal or failure is a result the model reads). Calls
   * run one at a time, in the order they came.
   */
  execute(call: ToolCall): Promise<ToolResult>;
  /**
   * Ends the skill running now, if any, before its next motion (the stop itself halts the one
   * under way), and drops the calls queued behind it.
   */
  interrupt(): void;
  /** The robot, map and memory the skills share. */
  readonly context: SkillContext;
}

/** Options of {@link createSkills}. */
export interface CreateSkillsOptions extends SkillOptions {
  /** Only these skills (default all). */
  include?: readonly SkillName[];
}

function isSkill(name: string): name is SkillName {
  return (SKILL_NAMES as readonly string[]).includes(name);
}

/**
 * The skills over `hal`. Give the HAL every motion should go through: a guarded one (see
 * `guardHal` of @hal/perception) whose calls pass the leash (`toolBackedHal` over a
 * `createToolExecutor` of @hal/tools), as `hal agent`, `hal mcp` and `hal eval` do; the skills
 * add no limit of their own and take none away.
 */
export function createSkills(
  hal: HardwareAbstractionLayer,
  options: CreateSkillsOptions = {},
): SkillSet {
  const context = new SkillContext(hal, options);
  const names = options.include ?? SKILL_NAMES;
  for (const name of names) {
    if (!isSkill(name)) throw new RangeError(`"include": no skill is called "${String(name)}"`);
  }
  const offered = new Set<string>(names);
  const tools = SKILL_NAMES.filter((n) => offered.has(n)).map((n) => SKILL_TOOLS[n]);
  const tried: Point[] = [];
  let queue: Promise<unknown> = Promise.resolve();
  let running: AbortController | undefined;
  // counts stops: a call queued before a stop does not run after it
  let epoch = 0;

  async function run(name: SkillName, args: Record<string, unknown>): Promise<ToolResult> {
    const parsed = SKILL_PARAMETERS[name].safeParse(args);
    if (!parsed.success) {
      const issue = parsed.error.issues[0];
      const path = issue?.path.join('.') ?? '';
      return badArguments(
        name,
        `${path === '' ? 'arguments' : `"${path}"`}: ${issue?.message ?? 'invalid'}`,
      );
    }
    const a = parsed.data as Record<string, unknown>;
    const target = typeof a['target'] === 'string' ? a['target'] : undefined;
    const x = typeof a['x'] === 'number' ? a['x'] : undefined;
    const y = typeof a['y'] === 'number' ? a['y'] : undefined;
    const signal = running?.signal;
    switch (name) {
      case 'look':
        return lookSkill(context, a['around'] === true);
      case 'find':
        return findSkill(context, target ?? '');
      case 'go_to':
        return goToThing(context, target ?? '', undefined, signal);
      case 'go_to_point':
        return goToPoint(
          context,
          { x: x ?? 0, y: y ?? 0 },
          context.pointToleranceM,
          `(${(x ?? 0).toFixed(2)}, ${(y ?? 0).toFixed(2)})`,
          signal,
        );
      case 'face':
        return faceSkill(context, target ?? '');
      case 'explore':
        return exploreSkill(context, tried, signal);
      case 'where_is':
        return whereIsSkill(context, target ?? '');
      case 'what_have_you_seen':
        return whatHaveYouSeenSkill(context);
      case 'go_back':
        return goBackSkill(context, signal);
      case 'move':
        return moveSkill(context, a['cm'] as number);
      case 'turn':
        return turnSkill(context, a['degrees'] as number);
    }
  }

  async function execute(call: ToolCall): Promise<ToolResult> {
    if (!isSkill(call.name) || !offered.has(call.name))
      return errorResult(
        'UNKNOWN_TOOL',
        `no skill "${call.name}"; the skills are ${tools.map((t) => t.name).join(', ')}`,
      );
    const parsed = parseArguments(call.arguments);
    if (!parsed.ok) return errorResult('BAD_ARGUMENTS', `${call.name}: ${parsed.message}`);
    const name = call.name;
    const asked = epoch;
    const turn = queue.then(async () => {
      // a stop came after this call and before its turn: it does not start
      if (epoch !== asked)
        return interruptedResult(name, { pose: skillPose(await context.pose()) });
      running = new AbortController();
      context.signal = running.signal;
      try {
        return await run(name, parsed.args);
      } catch (error) {
        // a sensor that failed (no frame, no pose): the skill could not go on
        const code = isHalError(error) ? error.code : 'HARDWARE_ERROR';
        const why = errorMessage(error);
        return errorResult(code, `${name}: ${why}`);
      } finally {
        running = undefined;
        context.signal = undefined;
      }
    });
    queue = turn.catch(() => undefined);
    return turn;
  }

  return {
    tools,
    execute,
    interrupt: () => {
      epoch += 1;
      running?.abort();
    },
    context,
  };
}
