import type { ChatTool } from '@hal/agent';
import type { ExampleRun } from './example-run.js';

/**
 * A system prompt for small local models: short, since every token is read on a CPU and a
 * 135M-parameter model loses the thread in the long built-in prompt. The reply format and the
 * tool list follow it in the prompt the model sees.
 */
export const LOCAL_SYSTEM_PROMPT = 'You control a small robot with tools.';

/**
 * The tools a small model is offered by default: few, since a tiny model picks among many badly.
 * The agent loop can still run `stop` at the end of a run whatever the model was offered.
 */
export const SMALL_MODEL_TOOLS: readonly string[] = Object.freeze([
  'move_forward',
  'move_backward',
  'rotate',
  'get_pose',
]);

/** How the model is told to reply; the grammar makes it so. */
const FORMAT =
  'Reply with one JSON object: {"tool": name, "arguments": {...}} to call a tool, or {"answer": text} when the goal is done.';

/** The system text the model reads: the loop's system prompt, the reply format, the tools. */
export function systemText(systemPrompt: string, tools: readonly ChatTool[]): string {
  const lines = tools.map(({ function: fn }) => `- ${fn.name}: ${fn.description}`);
  return [systemPrompt, FORMAT, ...(lines.length === 0 ? [] : ['Tools:', ...lines])].join('\n');
}

/**
 * The system prompt for a small model offered the skills (look, go_to, move, turn...): one line;
 * the worked examples ({@link SKILL_EXAMPLES}) show the rest.
 */
export const SKILLS_SYSTEM_PROMPT =
  'You drive a small robot. Call the tool the words ask for, one at a time; when the last result says it is done, answer.';

/**
 * Worked runs a small model reads before its own, one per kind of request: a drive, a turn, two
 * steps, an object to reach, a point, a question to answer from what the camera sees. The
 * results are those the skills give; the objects and numbers differ from any task's.
 */
export const SKILL_EXAMPLES: readonly ExampleRun[] = Object.freeze([
  {
    goal: 'Reach the point x = 0.5 m, y = -1.5 m.',
    calls: [
      {
        tool: 'go_to_point',
        arguments: { x: 0.5, y: -1.5 },
        result: 'Reached (0.50, -1.50): 1.2 cm from it.',
      },
    ],
    answer: 'I reached the point.',
  },
  {
    goal: 'What colour is the thing in front of you? Answer with one colour.',
    calls: [
      {
        tool: 'look',
        arguments: {},
        result:
          'I see the green box 1 0.90 m away, straight ahead. Clear floor: ahead 0.70 m, left 1.50 m, right 1.20 m.',
      },
    ],
    answer: 'green',
  },
  {
    goal: 'How many pillars are there? Answer with a number.',
    calls: [
      {
        tool: 'look',
        arguments: { around: true },
        result:
          'All round I see 1 box and 2 pillars: the blue pillar 1 0.80 m away, 40° left; the orange box 1 1.10 m away, 90° right; the yellow pillar 1 1.90 m away, 150° left.',
      },
    ],
    answer: '2',
  },
  {
    goal: 'Which side is open, left or right? Answer with one word.',
    calls: [
      {
        tool: 'look',
        arguments: { around: true },
        result:
          'I see no coloured object all round. Clear floor: ahead 1.20 m, left 0.25 m, right 2.10 m, behind 1.80 m. More open: right.',
      },
    ],
    answer: 'right',
  },
  {
    goal: 'Drive to the purple box and stop within 25 cm of it, touching nothing.',
    calls: [
      {
        tool: 'go_to',
        arguments: { target: 'purple box' },
        result: 'Reached the purple box 1: stopped 0.21 m from it (as I estimate it).',
      },
    ],
    answer: 'I stopped 21 cm from the purple box.',
  },
  {
    goal: 'drive to the orange pillar',
    calls: [
      {
        tool: 'go_to',
        arguments: { target: 'orange pillar' },
        result: 'Reached the orange pillar 1: stopped 0.19 m from it (as I estimate it).',
      },
    ],
    answer: 'I stopped 19 cm from the orange pillar.',
  },
  {
    goal: 'Turn right 30 degrees, then drive back 15 cm.',
    calls: [
      { tool: 'turn', arguments: { degrees: -30 }, result: 'Turned 30° right.' },
      { tool: 'move', arguments: { cm: -15 }, result: 'Moved 15.0 cm backward.' },
    ],
    answer: 'I turned 30 degrees right and drove 15 cm back.',
  },
  {
    goal: 'Drive forward 45 cm.',
    calls: [{ tool: 'move', arguments: { cm: 45 }, result: 'Moved 45.0 cm forward.' }],
    answer: 'I drove 45 cm forward.',
  },
]);
