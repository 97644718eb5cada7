import type { ChatProvider, ChatReply } from '@hal/agent';
import { describe, expect, it } from 'vitest';
import { builtinTasks } from '../builtin-tasks.js';
import { runTrial } from '../trial.js';
import { chatAgent } from './chat.js';

/** A provider that plays a script of replies, counting tokens as a model would report them. */
function scripted(replies: ChatReply[]): ChatProvider {
  let i = 0;
  return {
    name: 'scripted',
    complete: () => Promise.resolve(replies[Math.min(i++, replies.length - 1)] as ChatReply),
  };
}

const call = (name: string, args: object): ChatReply => ({
  text: '',
  refusal: undefined,
  toolCalls: [
    { id: `c${name}`, type: 'function', function: { name, arguments: JSON.stringify(args) } },
  ],
  usage: { promptTokens: 100, completionTokens: 10 },
});
const say = (text: string): ChatReply => ({
  text,
  refusal: undefined,
  toolCalls: [],
  usage: { promptTokens: 120, completionTokens: 5 },
});

describe('chatAgent', () => {
  const task = builtinTasks(['precision']).find((t) => t.id === 'precision/drive-30cm');
  if (task === undefined) throw new Error('no precision/drive-30cm');

  it("scores a model's run from the world, with its tokens counted", async () => {
    const agent = chatAgent({
      name: 'scripted',
      provider: scripted([call('move_forward', { distanceCm: 30 }), say('Done.')]),
    });
    const { score, timing } = await runTrial(task, 1, agent);
    expect(score).toMatchObject({
      success: true,
      toolCalls: 1,
      tokensIn: 220,
      tokensOut: 15,
      answer: 'Done.',
    });
    expect(timing.modelMs).toBeGreaterThanOrEqual(0);
  });

  it('fails a model that says it is done after the wrong move, whatever it says', async () => {
    const agent = chatAgent({
      name: 'scripted',
      provider: scripted([
        call('move_forward', { distanceCm: 20 }),
        say('I drove exactly 30 cm. Success!'),
      ]),
    });
    const { score } = await runTrial(task, 1, agent);
    expect(score.success).toBe(false);
    expect(score.failures[0]).toMatch(/^displacement: ended 0\.1 m from the target/);
    expect(score.positionErrorM).toBeCloseTo(0.1, 3);
  });
});

describe('runTrial', () => {
  it('leaves an agent that never answers behind when its time is up, and scores the trial', async () => {
    const task = builtinTasks(['precision'])[0];
    if (task === undefined) throw new Error('no task');
    const stuck = { name: 'stuck', run: () => new Promise<never>(() => undefined) };
    const { score } = await runTrial(task, 1, stuck, { wallTimeoutMs: 50 });
    expect(score.success).toBe(false);
    expect(score.failures.at(-1)).toBe('agent: no answer within 50 ms (+5000 ms)');
  }, 20_000);
});
