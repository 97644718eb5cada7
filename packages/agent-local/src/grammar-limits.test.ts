// The grammar llama.cpp is given for the largest tool sets: it must parse (llama.cpp refuses a
// counted repetition whose count times the rules before it reaches 2000, and prints the whole
// grammar on the process's stderr when it does). llama.cpp's bindings are loaded; no model is.
import type { ChatTool } from '@hal/agent';
import { getLlama, LlamaLogLevel } from 'node-llama-cpp';
import type { Llama } from 'node-llama-cpp';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { everyChatTool } from './every-tool.fixture.js';
import { replyGrammar } from './grammar.js';
import { MAX_COUNTED_REPETITION, replySchema } from './grammar-schema.js';

let llama: Llama;
beforeAll(async () => {
  llama = await getLlama({
    gpu: false,
    build: 'never',
    logLevel: LlamaLogLevel.error,
    logger: () => undefined,
  });
}, 60_000);
afterAll(async () => {
  await llama?.dispose();
});

const tool = (name: string, parameters: Record<string, unknown>): ChatTool => ({
  type: 'function',
  function: { name, description: name, parameters },
});

describe('replyGrammar', () => {
  it('builds the grammar of every tool @hal/tools can offer, and of each alone', async () => {
    const tools = everyChatTool();
    expect(tools.map((t) => t.function.name)).toContain('log');
    const grammar = await replyGrammar(llama, replySchema(tools));
    expect(grammar.grammar).toContain('"\\"log\\""');
    for (const one of tools)
      await expect(replyGrammar(llama, replySchema([one]))).resolves.toBeDefined();
  });

  it('builds a grammar for lengths and counts far past what llama.cpp can count', async () => {
    const big = tool('note', {
      type: 'object',
      properties: {
        text: { type: 'string', minLength: 1, maxLength: 100_000 },
        tags: { type: 'array', items: { type: 'string', maxLength: 5000 }, maxItems: 3000 },
      },
      required: ['text'],
    });
    const grammar = await replyGrammar(llama, replySchema([...everyChatTool(), big], 10_000));
    expect(grammar.grammar).not.toMatch(/\{\d+,(\d{4,})\}/);
  });

  it(`keeps bounds up to ${MAX_COUNTED_REPETITION} in the grammar`, async () => {
    const small = tool('name', {
      type: 'object',
      properties: { v: { type: 'string', maxLength: MAX_COUNTED_REPETITION } },
      required: ['v'],
    });
    const grammar = await replyGrammar(llama, replySchema([small]));
    expect(grammar.grammar).toContain(`{0,${MAX_COUNTED_REPETITION}}`);
  });

  it('says llama.cpp refused a grammar as SCHEMA_UNSUPPORTED, keeping its words', async () => {
    const schema = { oneOf: [{ type: 'string', maxLength: 2000 }] };
    await expect(replyGrammar(llama, schema as never)).rejects.toMatchObject({
      code: 'SCHEMA_UNSUPPORTED',
      message: expect.stringContaining('Failed to parse grammar'),
    });
  });
});
