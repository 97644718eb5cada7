// What a motion tool call will do, in words a person approves ("drive 0.30 m forward at
// 0.10 m/s"), how far it goes (for `--approve over:DISTANCE`), and what its progress counts:
// metres along the path or degrees turned, of a total where one is known.
import { planMotion } from '@hal/tools';
import type { AgentTool, PlanStart } from '@hal/tools';
import { findCall } from '@hal/types';
import type { RobotConfig } from '@hal/types';

/** What progress counts: metres travelled, or degrees turned. */
export type ProgressUnit = 'm' | 'deg';

/** A motion call, summed up before it runs. */
export interface MotionSummary {
  /** What it will do, for a person: "drive 0.30 m forward at 0.10 m/s". */
  words: string;
  /** How far it travels, metres; undefined when that is known only as it goes (a skill's search). */
  distanceM: number | undefined;
  /** What its progress counts, and the total where it is known. */
  progress: { unit: ProgressUnit; total?: number };
}

/** What a motion call will do, read at the moment it is asked about (the pose now). */
export type Summarize = (
  tool: AgentTool,
  args: Record<string, unknown>,
) => Promise<MotionSummary | undefined>;

const m = (v: number) => `${v.toFixed(2)} m`;
const speed = (v: number) => `${v.toFixed(2)} m/s`;
const deg = (v: number) => `${Math.round(v)}°`;
const num = (v: unknown): number | undefined =>
  typeof v === 'number' && Number.isFinite(v) ? v : undefined;
const str = (v: unknown): string => (typeof v === 'string' ? v : 'it');

/** A HAL motion call (`move_forward`, `rotate`, `move_to`, `drive`), from its plan. */
function halMotion(
  call: string,
  args: Record<string, unknown>,
  start: PlanStart,
  config: RobotConfig,
): MotionSummary | undefined {
  const motion = findCall(call)?.motion;
  if (motion === undefined) return undefined;
  const plan = planMotion(call, args, start, config);
  if (plan === undefined) return undefined;
  switch (motion) {
    case 'forward':
    case 'backward':
      return {
        words: `drive ${m(plan.distanceM)} ${motion} at ${speed(plan.speedMPerS)}`,
        distanceM: plan.distanceM,
        progress: { unit: 'm', total: plan.distanceM },
      };
    case 'turn': {
      const degrees = Math.abs(num(args['degrees']) ?? 0);
      const side = args['direction'] === 'right' ? 'right (clockwise)' : 'left (counter-clockwise)';
      return {
        words: `turn ${deg(degrees)} ${side} on the spot`,
        distanceM: 0,
        progress: { unit: 'deg', total: degrees },
      };
    }
    case 'point':
      return {
        words:
          `turn toward (${num(args['x'])?.toFixed(2)}, ${num(args['y'])?.toFixed(2)}) m and drive ` +
          `${m(plan.distanceM)} to it at ${speed(plan.speedMPerS)}`,
        distanceM: plan.distanceM,
        progress: { unit: 'm', total: plan.distanceM },
      };
    case 'wheels': {
      const power = `left wheel ${num(args['left'])}, right wheel ${num(args['right'])} of 255`;
      const ms = num(args['durationMs']);
      return ms === undefined
        ? {
            words: `run the wheels (${power}) until the next call, with no end of its own`,
            distanceM: Infinity,
            progress: { unit: 'm' },
          }
        : {
            words: `run the wheels (${power}) for ${(ms / 1000).toFixed(1)} s, about ${m(plan.distanceM)}`,
            distanceM: plan.distanceM,
            progress: { unit: 'm', total: plan.distanceM },
          };
    }
  }
}

/** A skill of @hal/skills that moves: what it says it will do; its distance where known. */
function skillMotion(
  name: string,
  args: Record<string, unknown>,
  start: PlanStart,
): MotionSummary | undefined {
  const unknown = (words: string): MotionSummary => ({
    words,
    distanceM: undefined,
    progress: { unit: 'm' },
  });
  switch (name) {
    case 'move': {
      const cm = num(args['cm']) ?? 0;
      const metres = Math.abs(cm) / 100;
      return {
        words: `drive ${m(metres)} ${cm < 0 ? 'backward' : 'forward'}`,
        distanceM: metres,
        progress: { unit: 'm', total: metres },
      };
    }
    case 'turn': {
      const degrees = num(args['degrees']) ?? 0;
      return {
        words: `turn ${deg(Math.abs(degrees))} ${degrees < 0 ? 'right' : 'left'} on the spot`,
        distanceM: 0,
        progress: { unit: 'deg', total: Math.abs(degrees) },
      };
    }
    case 'look':
      return args['around'] === true
        ? {
            words: 'turn a full circle on the spot to look all round',
            distanceM: 0,
            progress: { unit: 'deg', total: 360 },
          }
        : undefined; // a look without `around` only reads the camera
    case 'face':
      return {
        words: `turn on the spot to face the ${str(args['target'])}`,
        distanceM: 0,
        progress: { unit: 'deg' },
      };
    case 'find':
      return {
        words: `turn on the spot until the ${str(args['target'])} is in view`,
        distanceM: 0,
        progress: { unit: 'deg' },
      };
    case 'go_to_point': {
      const x = num(args['x']) ?? start.x;
      const y = num(args['y']) ?? start.y;
      return {
        words: `drive to (${x.toFixed(2)}, ${y.toFixed(2)}) m, ${m(Math.hypot(x - start.x, y - start.y))} away in a straight line, around what it sees`,
        // the way around an obstacle is longer than the straight line
        distanceM: undefined,
        progress: { unit: 'm' },
      };
    }
    case 'go_to':
      return unknown(`drive to the ${str(args['target'])}, stopping about 25 cm before it`);
    case 'explore':
      return unknown('drive toward the nearest place not seen yet');
    case 'go_back':
      return unknown('drive back to where it started');
    default:
      return unknown(`run ${name}, which moves the robot`);
  }
}

/**
 * What `tool` called with `args` will do, from `start` (the pose now) and the robot's limits;
 * undefined for a call that does not move the robot.
 */
export function summarizeMotion(
  tool: AgentTool,
  args: Record<string, unknown>,
  start: PlanStart,
  config: RobotConfig,
): MotionSummary | undefined {
  if (!tool.motion) return undefined;
  const call = (tool as { call?: unknown }).call;
  if (typeof call === 'string') return halMotion(call, args, start, config);
  return skillMotion(tool.name, args, start);
}
