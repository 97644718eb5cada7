import type { ChatTool } from '@hal/agent';
import { halTools, toOpenAITools } from '@hal/tools';
import { SimulationHAL, World } from '@hal/simulation';
import { describe, expect, it } from 'vitest';
import { LocalModelError } from './errors.js';
import { replySchema } from './grammar-schema.js';

const tool = (name: string, parameters: Record<string, unknown>): ChatTool => ({
  type: 'function',
  function: { name, description: name, parameters },
});

describe('replySchema', () => {
  it('expresses every HAL tool: one call shape per tool, and an answer', () => {
    const tools = toOpenAITools(halTools(new SimulationHAL({ world: new World() })));
    const schema = replySchema(tools);
    expect(schema.oneOf).toHaveLength(tools.length + 1);
    const names = schema.oneOf.map((s) => JSON.stringify(s).match(/"const":"(\w+)"/)?.[1]);
    expect(names.slice(0, -1)).toEqual(tools.map((t) => t.function.name));
    expect(schema.oneOf.at(-1)).toMatchObject({ required: ['answer'] });
  });

  it('without the answer: a reply that must call a tool, and a refusal when there is none to call', () => {
    const tools = toOpenAITools(halTools(new SimulationHAL({ world: new World() })));
    const schema = replySchema(tools, undefined, { answer: false });
    expect(schema.oneOf).toHaveLength(tools.length);
    expect(JSON.stringify(schema)).not.toContain('"answer"');
    expect(() => replySchema([], undefined, { answer: false })).toThrow(LocalModelError);
  });

  it('leaves numeric bounds to the tool (the grammar cannot hold them) and keeps types', () => {
    const schema = replySchema([
      tool('move_forward', {
        type: 'object',
        properties: { distanceCm: { type: 'number', exclusiveMinimum: 0, maximum: 188.4 } },
        required: ['distanceCm'],
      }),
    ]);
    expect(schema.oneOf[0]).toEqual({
      type: 'object',
      properties: {
        tool: { const: 'move_forward' },
        arguments: {
          type: 'object',
          properties: { distanceCm: { type: 'number' } },
          required: ['distanceCm'],
          additionalProperties: false,
        },
      },
      required: ['tool', 'arguments'],
      additionalProperties: false,
    });
  });

  it('reads anyOf as the alternation oneOf is', () => {
    const schema = replySchema([
      tool('pick', {
        type: 'object',
        properties: { v: { anyOf: [{ type: 'string' }, { type: 'number' }] } },
      }),
    ]);
    expect(JSON.stringify(schema.oneOf[0])).toContain(
      '"oneOf":[{"type":"string"},{"type":"number"}]',
    );
  });

  it('refuses a schema the grammar cannot express, naming the tool and the keyword', () => {
    const tools = [
      tool('get_pose', { type: 'object', properties: {} }),
      tool('set_name', {
        type: 'object',
        properties: { name: { type: 'string', pattern: '^[a-z]+$' } },
      }),
    ];
    let thrown: unknown;
    try {
      replySchema(tools);
    } catch (error) {
      thrown = error;
    }
    expect(thrown).toBeInstanceOf(LocalModelError);
    expect(thrown).toMatchObject({ code: 'SCHEMA_UNSUPPORTED', details: { tool: 'set_name' } });
    expect((thrown as Error).message).toMatch(/tool "set_name".*"pattern"/);
  });

  it.each([
    [{ allOf: [{ type: 'object' }] }, 'allOf'],
    [{ type: 'object', properties: { a: { not: { type: 'string' } } } }, 'not'],
    [{ type: 'object', properties: { a: { $ref: '#/$defs/x' } } }, '$ref'],
    [{ type: 'object', properties: { a: { type: 'string', format: 'email' } } }, 'email'],
    [{ type: 'object', properties: { a: { type: ['object', 'null'] } } }, 'list of types'],
  ])('refuses %j', (parameters, word) => {
    expect(() => replySchema([tool('odd', parameters)])).toThrow(
      new RegExp(`tool "odd".*${word.replace('$', '\\$')}`),
    );
  });
});
