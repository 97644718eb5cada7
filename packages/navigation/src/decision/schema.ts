import { z } from 'zod';

/*
 * The navigation decision: what a decision provider (an LLM or a deterministic policy) tells the
 * bridge to do next. Field names are snake_case because this is the JSON an LLM writes.
 *
 * Yaw convention (pinned by a test): ROTATE_TO's `yaw_deg` is an ABSOLUTE heading in the world
 * frame, degrees, counter-clockwise from +x (REP-103: 0 faces +x, 90 faces +y). It is not a
 * relative turn and positive is not "right" (the seed's bridge read it as a relative turn,
 * positive to the right). The bridge turns the shorter way to reach it.
 */

/** Bounds for the target coordinates a decision may name, metres. */
export interface DecisionBounds {
  minX: number;
  maxX: number;
  minY: number;
  maxY: number;
}

/** Builds the decision schema, with MOVE_TO targets limited to `bounds` when given. */
export function createDecisionSchema(bounds?: DecisionBounds) {
  const coordinate = (axis: 'x' | 'y') => {
    const lo = bounds === undefined ? undefined : axis === 'x' ? bounds.minX : bounds.minY;
    const hi = bounds === undefined ? undefined : axis === 'x' ? bounds.maxX : bounds.maxY;
    let schema = z.number();
    if (lo !== undefined) schema = schema.min(lo);
    if (hi !== undefined) schema = schema.max(hi);
    const range = lo === undefined ? '' : `, ${lo}..${hi}`;
    const meaning = axis === 'x' ? 'forward/east' : 'left/north';
    return schema.describe(`Target ${axis}, metres, world frame (${meaning})${range}`);
  };
  const moveTo = z
    .object({
      type: z.literal('MOVE_TO'),
      x: coordinate('x'),
      y: coordinate('y'),
    })
    .describe('Drive to the point (x, y) along an obstacle-free route the planner finds');
  const explore = z
    .object({ type: z.literal('EXPLORE') })
    .describe('Go and look at the nearest unexplored area (the nearest frontier)');
  const rotateTo = z
    .object({
      type: z.literal('ROTATE_TO'),
      yaw_deg: z
        .number()
        .min(-360)
        .max(360)
        .describe(
          'Absolute heading to face, degrees, world frame, counter-clockwise from +x ' +
            '(0 faces +x/east, 90 faces +y/north, -90 faces -y/south); not a relative turn',
        ),
    })
    .describe('Turn in place to face an absolute heading');
  const stop = z
    .object({ type: z.literal('STOP') })
    .describe('Stop and end the run (with goal_reached true when the goal is reached)');
  // A plain union (JSON Schema anyOf), which structured-output servers accept more widely than
  // oneOf; the `type` literals keep the members apart.
  const action = z.union([moveTo, explore, rotateTo, stop]).describe('The next action');
  return z
    .object({
      reasoning: z
        .string()
        .max(2000)
        .describe('Why this action, in one or two sentences (what you see, what you intend)'),
      action,
      goal_reached: z
        .boolean()
        .describe('True only when the robot is at the goal now; then the action is STOP'),
    })
    .describe('The next navigation decision');
}

/** The decision schema without coordinate bounds. */
export const NavigationDecisionSchema = createDecisionSchema();
/** A navigation decision. */
export type NavigationDecision = z.infer<typeof NavigationDecisionSchema>;
/** One of the decision's actions. */
export type NavigationAction = NavigationDecision['action'];
/** The action names. */
export type NavigationActionType = NavigationAction['type'];

/**
 * The decision schema as JSON Schema (draft 2020-12, without the `$schema` key), for an LLM's
 * structured output (`response_format: { type: 'json_schema', ... }`) or its prompt.
 */
export function decisionJsonSchema(bounds?: DecisionBounds): Record<string, unknown> {
  const schema = z.toJSONSchema(createDecisionSchema(bounds)) as Record<string, unknown>;
  delete schema['$schema'];
  return schema;
}

/** Parses a decision, returning it or the first problem as text (path: message). */
export function parseDecision(
  value: unknown,
  bounds?: DecisionBounds,
): { ok: true; decision: NavigationDecision } | { ok: false; problem: string } {
  const parsed = (
    bounds === undefined ? NavigationDecisionSchema : createDecisionSchema(bounds)
  ).safeParse(value);
  if (parsed.success) return { ok: true, decision: parsed.data };
  const problems = parsed.error.issues
    .slice(0, 3)
    .map((issue) => `${issue.path.map(String).join('.') || 'decision'}: ${issue.message}`);
  return { ok: false, problem: problems.join('; ') };
}
