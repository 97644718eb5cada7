import { describe, expect, it } from 'vitest';
import { compactGrammar, FRACTION_DIGITS } from './grammar.js';

// The rules as node-llama-cpp 3.21.1 writes them for a one-property object.
const GRAMMAR = [
  'root ::= ( rule1 ) "\\n\\n\\n\\n" [\\n]*',
  'comma-whitespace-b-1-4-rule ::= "," ([\\n] ("    " | "\\t") | [ ]?)',
  'fractional-number-rule ::= "-"? ("0" | [1-9] [0-9]{0,15}) ("." [0-9]{1,16})? ([eE] [-+]? ("0" | [1-9] [0-9]{0,15}))?',
  'whitespace-b-1-4-rule ::= [\\n] ("    " | "\\t") | [ ]?',
  'rule1 ::= "{" whitespace-b-1-4-rule "\\"d\\"" ":" [ ]? fractional-number-rule whitespace-b-1-4-rule "}"',
].join('\n');

describe('compactGrammar', () => {
  const compact = compactGrammar(GRAMMAR);

  it(`holds fractions to ${FRACTION_DIGITS} digits`, () => {
    expect(compact).toContain(`("." [0-9]{1,${FRACTION_DIGITS}})?`);
    expect(compact).not.toContain('[0-9]{1,16}');
  });

  it('allows no new lines inside the JSON, only a space', () => {
    expect(compact).toContain('whitespace-b-1-4-rule ::= [ ]?\n');
    expect(compact).toContain('comma-whitespace-b-1-4-rule ::= "," [ ]?\n');
    const rules = compact.split('\n').filter((line) => !line.startsWith('root'));
    expect(rules.join('\n')).not.toContain('[\\n]');
  });

  it('leaves the other rules as they were', () => {
    const unchanged = (text: string) =>
      text.split('\n').filter((line) => line.startsWith('root') || line.startsWith('rule1'));
    expect(unchanged(compact)).toEqual(unchanged(GRAMMAR));
  });
});
