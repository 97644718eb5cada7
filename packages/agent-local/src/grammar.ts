import type { GbnfJsonOneOfSchema, Llama, LlamaGrammar } from 'node-llama-cpp';

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

/**
 * The grammar for `schema`: node-llama-cpp's JSON-schema grammar, on one line, with numbers held
 * to {@link FRACTION_DIGITS} decimals (where its rules read as expected; unchanged otherwise).
 */
export async function replyGrammar(
  llama: Llama,
  schema: GbnfJsonOneOfSchema,
): Promise<LlamaGrammar> {
  const json = await llama.createGrammarForJsonSchema(schema);
  const text = compactGrammar(json.grammar);
  if (text === json.grammar) return json;
  return llama.createGrammar({
    grammar: text,
    stopGenerationTriggers: ['\n\n\n\n'],
    trimWhitespaceSuffix: true,
  });
}
