import type { GbnfJsonOneOfSchema, Llama, LlamaGrammar } from 'node-llama-cpp';
import { errorMessage } from '@hal/types';
import { LocalModelError } from './errors.js';

/** Most digits after the decimal point a number may have (finer than any of the robot's steps). */
export const FRACTION_DIGITS = 3;

// node-llama-cpp's number rule allows 16 fraction digits; a greedy small model fills them
// ("10.0000001111111111"), which costs tokens and time for nothing. Its whitespace rules allow
// pretty-printing, which doubles a call's tokens: one space at most is enough.
const FRACTION_RULE = '("." [0-9]{1,16})?';
const WHITESPACE_RULE = /^(whitespace-[\w-]+-rule) ::= .*$/gm;
const COMMA_RULE = /^(comma-whitespace-[\w-]+-rule) ::= .*$/gm;

/** node-llama-cpp's grammar text with compact whitespace and short fractions. */
export function compactGrammar(grammar: string): string {
  return grammar
    .split(FRACTION_RULE)
    .join(`("." [0-9]{1,${FRACTION_DIGITS}})?`)
    .replace(WHITESPACE_RULE, '$1 ::= [ ]?')
    .replace(COMMA_RULE, '$1 ::= "," [ ]?');
}

/** llama.cpp's refusal of a grammar as a SCHEMA_UNSUPPORTED error (its own text is the cause). */
function refused(cause: unknown): LocalModelError {
  const said = errorMessage(cause);
  return new LocalModelError(
    'SCHEMA_UNSUPPORTED',
    `llama.cpp refused the grammar built from the tools' schemas (${said}); offer fewer tools with "offerTools"`,
    { cause },
  );
}

/**
 * The grammar for `schema`: node-llama-cpp's JSON-schema grammar, on one line, with numbers held
 * to {@link FRACTION_DIGITS} decimals (where its rules read as expected; unchanged otherwise).
 * Rejects with a LocalModelError SCHEMA_UNSUPPORTED when llama.cpp refuses the grammar.
 */
export async function replyGrammar(
  llama: Llama,
  schema: GbnfJsonOneOfSchema,
): Promise<LlamaGrammar> {
  let json: LlamaGrammar & { grammar: string };
  try {
    json = await llama.createGrammarForJsonSchema(schema);
  } catch (cause) {
    throw refused(cause);
  }
  const text = compactGrammar(json.grammar);
  if (text === json.grammar) return json;
  try {
    return await llama.createGrammar({
      grammar: text,
      stopGenerationTriggers: ['\n\n\n\n'],
      trimWhitespaceSuffix: true,
    });
  } catch (cause) {
    throw refused(cause);
  }
}
