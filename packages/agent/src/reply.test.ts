import { describe, expect, it } from 'vitest';
import { AgentError } from './errors.js';
import { parseReply } from './reply.js';

describe('parseReply', () => {
  it('reads the text and the tool calls of the first choice', () => {
    const reply = parseReply(
      {
        choices: [
          {
            message: {
              content: 'Moving.',
              tool_calls: [
                { id: 'a', type: 'function', function: { name: 'stop', arguments: '{}' } },
              ],
            },
          },
        ],
      },
      1,
    );
    expect(reply).toEqual({
      text: 'Moving.',
      refusal: undefined,
      toolCalls: [{ id: 'a', type: 'function', function: { name: 'stop', arguments: '{}' } }],
    });
  });

  it('makes up missing call ids and turns object arguments into JSON text', () => {
    const reply = parseReply(
      {
        choices: [
          {
            message: {
              content: null,
              tool_calls: [{ function: { name: 'rotate', arguments: { degrees: 90 } } }],
            },
          },
        ],
      },
      4,
    );
    expect(reply.toolCalls).toEqual([
      {
        id: 'call_4_0',
        type: 'function',
        function: { name: 'rotate', arguments: '{"degrees":90}' },
      },
    ]);
    expect(reply.text).toBe('');
  });

  it('joins text parts and reads a refusal', () => {
    const reply = parseReply(
      { choices: [{ message: { content: [{ type: 'text', text: 'No' }], refusal: 'No.' } }] },
      1,
    );
    expect(reply).toMatchObject({ text: 'No', refusal: 'No.', toolCalls: [] });
  });

  it('throws BAD_REPLY for a payload without a choice', () => {
    for (const payload of [{}, { choices: [] }, { choices: [{}] }, 'text', null]) {
      expect(() => parseReply(payload, 1)).toThrow(AgentError);
      try {
        parseReply(payload, 1);
      } catch (error) {
        expect((error as AgentError).code).toBe('BAD_REPLY');
      }
    }
  });

  it('reads the token counts a server reports in usage, and leaves them out when it sends none', () => {
    const message = { content: 'Done.' };
    const withUsage = parseReply(
      {
        choices: [{ message }],
        usage: { prompt_tokens: 120, completion_tokens: 7, total_tokens: 127 },
      },
      1,
    );
    expect(withUsage.usage).toEqual({ promptTokens: 120, completionTokens: 7 });
    expect('usage' in parseReply({ choices: [{ message }] }, 1)).toBe(false);
    expect('usage' in parseReply({ choices: [{ message }], usage: null }, 1)).toBe(false);
  });
});
