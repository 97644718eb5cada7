import { gridExtent } from '../grid/geometry.js';
import type { GridSpec } from '../grid/geometry.js';
import { gridImageDataUrl } from '../grid/image.js';
import { describeWorld } from '../grid/summary.js';
import type { ResponseFormatMode } from './llm-options.js';
import type { DecisionContext } from './provider.js';
import type { DecisionBounds } from './schema.js';

/** The built-in system prompt: the actions, the frame, the yaw convention. */
export const SYSTEM_PROMPT: string = [
  'You steer a small differential-drive robot to a goal. Each turn you get what its camera sees,',
  'a summary of its occupancy-grid map and the result of your previous action, and you answer',
  'with ONE decision as a JSON object matching the given schema, nothing else.',
  'Actions: MOVE_TO {x, y} drives to a point along an obstacle-free route the planner finds',
  '(give the goal itself, or an intermediate point in known free space); EXPLORE visits the',
  'nearest unexplored area; ROTATE_TO {yaw_deg} turns in place to an ABSOLUTE heading in',
  'degrees, counter-clockwise from +x (0 = +x/east, 90 = +y/north); STOP ends the run.',
  'Set goal_reached to true only when the robot is within the goal tolerance, with STOP.',
  'Coordinates are metres in the world frame: x east, y north.',
].join(' ');

export type ContentPart =
  { type: 'text'; text: string } | { type: 'image_url'; image_url: { url: string } };
export type ChatMessage =
  | { role: 'system' | 'assistant'; content: string }
  | { role: 'user'; content: string | ContentPart[] };

/** What goes into the user message besides the decision context. */
export interface PromptOptions {
  /** The response format asked for: other than `json_schema`, the schema goes in the prompt. */
  format: ResponseFormatMode;
  sendFrame: boolean;
  sendMapImage: boolean;
}

/** MOVE_TO's limits: the world model's extent, rounded to the millimetre. */
export function decisionBounds(spec: GridSpec): DecisionBounds {
  const round = (v: number) => Math.round(v * 1000) / 1000;
  const { minX, minY, maxX, maxY } = gridExtent(spec);
  return { minX: round(minX), maxX: round(maxX), minY: round(minY), maxY: round(maxY) };
}

/**
 * The user message: the cycle, the mission, the previous action's result, the world summary
 * (and the schema when it is not sent as structured output), then the camera frame and the map
 * picture as images when they are sent.
 */
export function userContent(
  context: DecisionContext,
  schema: Record<string, unknown>,
  options: PromptOptions,
): ContentPart[] {
  const lines = [
    `Cycle ${context.cycle}.`,
    context.goal === null
      ? 'Mission: explore the area; STOP with goal_reached true when nothing is left to explore.'
      : `Mission: reach the goal (${context.goal.x.toFixed(2)}, ${context.goal.y.toFixed(
          2,
        )}) m, within ${context.goalToleranceM.toFixed(2)} m.`,
  ];
  const last = context.lastResult;
  if (last !== undefined) {
    lines.push(
      `Previous action ${last.action}: ${last.success ? 'succeeded' : `failed (${last.code ?? 'error'}: ${last.error ?? 'no message'})`}.`,
    );
  }
  const world: Parameters<typeof describeWorld>[1] = { pose: context.pose, goal: context.goal };
  if (context.readings !== undefined) world.readings = context.readings;
  lines.push(describeWorld(context.grid, world));
  if (options.format !== 'json_schema') {
    lines.push(`Answer with a JSON object matching this JSON Schema: ${JSON.stringify(schema)}`);
  }
  const parts: ContentPart[] = [{ type: 'text', text: lines.join('\n') }];
  if (options.sendFrame && context.frame !== undefined) {
    parts.push({ type: 'image_url', image_url: { url: context.frame } });
  }
  if (options.sendMapImage) {
    const url = gridImageDataUrl(context.grid, {
      pose: context.pose,
      goal: context.goal,
      size: 200,
    });
    parts.push({ type: 'text', text: 'The map (north up; black: obstacle, grey: unknown):' });
    parts.push({ type: 'image_url', image_url: { url } });
  }
  return parts;
}

/** The chat-completions request body, with `response_format` as `format` asks. */
export function requestBody(
  request: { model: string; temperature: number; maxTokens: number; format: ResponseFormatMode },
  messages: ChatMessage[],
  schema: Record<string, unknown>,
): Record<string, unknown> {
  const body: Record<string, unknown> = {
    model: request.model,
    messages,
    temperature: request.temperature,
    max_tokens: request.maxTokens,
  };
  if (request.format === 'json_schema') {
    body['response_format'] = {
      type: 'json_schema',
      json_schema: { name: 'navigation_decision', schema, strict: true },
    };
  } else if (request.format === 'json_object') {
    body['response_format'] = { type: 'json_object' };
  }
  return body;
}
