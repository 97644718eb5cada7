import type { ChatMessage } from '@hal/agent';
import { describe, expect, it } from 'vitest';
import { fitHistory, IMAGE_PLACEHOLDER } from './history.js';

// one token per word is enough to test the budget arithmetic
const words = (text: string) => text.split(/\s+/).filter(Boolean).length;

const call = (id: string, name: string, args: string): ChatMessage => ({
  role: 'assistant',
  content: null,
  tool_calls: [{ id, type: 'function', function: { name, arguments: args } }],
});

const conversation: ChatMessage[] = [
  { role: 'system', content: 'ignored: the system text is given' },
  { role: 'user', content: 'drive forward 10 cm' },
  call('a', 'move_forward', '{"distanceCm":10}'),
  { role: 'tool', tool_call_id: 'a', content: 'moved one two three four five six seven' },
  call('b', 'get_pose', '{}'),
  { role: 'tool', tool_call_id: 'b', content: 'x 0.1' },
];

describe('fitHistory', () => {
  it('gives tool calls back as the JSON the model wrote and results as user turns', () => {
    const { history, droppedMessages } = fitHistory(conversation, 'SYSTEM', 1000, words);
    expect(droppedMessages).toBe(0);
    expect(history[0]).toEqual({ type: 'system', text: 'SYSTEM' });
    expect(history[1]).toEqual({ type: 'user', text: 'drive forward 10 cm' });
    expect(history[2]).toEqual({
      type: 'model',
      response: ['{"tool":"move_forward","arguments":{"distanceCm":10}}'],
    });
    expect(history[3]).toMatchObject({ type: 'user' });
    expect((history[3] as { text: string }).text).toMatch(/^Result of move_forward: moved/);
    const last = history.at(-2) as { text: string };
    expect(last.text).toContain('Result of get_pose: x 0.1');
    expect(last.text).toContain('"drive forward 10 cm"');
    expect(history.at(-1)).toEqual({ type: 'model', response: [] });
  });

  it('leaves out whole older turns, oldest first, to fit the budget, keeping the goal', () => {
    const full = fitHistory(conversation, 'SYSTEM', 1000, words).promptTokens;
    const fitted = fitHistory(conversation, 'SYSTEM', full - 1, words);
    expect(fitted.droppedMessages).toBe(2);
    expect(fitted.promptTokens).toBeLessThan(full);
    const texts = JSON.stringify(fitted.history);
    expect(texts).toContain('drive forward 10 cm');
    expect(texts).not.toContain('move_forward');
    expect(texts).toContain('get_pose');
  });

  it('refuses when the system text and goal alone do not fit', () => {
    expect(() => fitHistory(conversation, 'SYSTEM', 5, words)).toThrow(/context/);
  });

  it('puts a short text where a camera frame was', () => {
    const { history } = fitHistory(
      [
        ...conversation.slice(0, 2),
        {
          role: 'user',
          content: [
            { type: 'text', text: 'Camera frame:' },
            { type: 'image_url', image_url: { url: 'data:image/jpeg;base64,AAAA' } },
          ],
        },
      ],
      'SYSTEM',
      1000,
      words,
    );
    const text = JSON.stringify(history);
    expect(text).toContain(IMAGE_PLACEHOLDER);
    expect(text).not.toContain('base64');
  });
});

describe('fitHistory with worked examples', () => {
  const example = {
    goal: 'drive forward 45 cm',
    calls: [{ tool: 'move', arguments: { cm: 45 }, result: 'Moved 45.0 cm forward.' }],
    answer: 'I drove 45 cm forward.',
  };

  it('shows each example as turns of the model before the goal: its call, the result, its answer', () => {
    const { history } = fitHistory(conversation.slice(0, 2), 'SYSTEM', 1000, words, [example]);
    expect(history.slice(0, 6)).toEqual([
      { type: 'system', text: 'SYSTEM' },
      { type: 'user', text: 'drive forward 45 cm' },
      { type: 'model', response: ['{"tool":"move","arguments":{"cm":45}}'] },
      { type: 'user', text: 'Result of move: Moved 45.0 cm forward.' },
      { type: 'model', response: ['{"answer":"I drove 45 cm forward."}'] },
      { type: 'user', text: 'drive forward 10 cm' },
    ]);
  });

  it("ends a turn of results as the examples' turns end, with the last result and no reminder", () => {
    const { history } = fitHistory(conversation, 'SYSTEM', 1000, words, [example]);
    // the examples' results are followed by the answer: a reminder quoting the goal after the
    // results here is what a tiny model answered back
    expect(history.at(-2)).toEqual({ type: 'user', text: 'Result of get_pose: x 0.1' });
    expect(history.at(-1)).toEqual({ type: 'model', response: [] });
  });

  it('counts the examples in the budget that must fit, and says so when they do not', () => {
    expect(() => fitHistory(conversation.slice(0, 2), 'SYSTEM', 30, words, [example])).toThrow(
      /the system prompt, its examples and goal need about \d+ tokens/,
    );
    // the same without the example fits
    expect(fitHistory(conversation.slice(0, 2), 'SYSTEM', 30, words).droppedMessages).toBe(0);
  });
});
