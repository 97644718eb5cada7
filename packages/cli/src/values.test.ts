import { InvalidArgumentError } from 'commander';
import { describe, expect, it } from 'vitest';
import { integerArg } from './values.js';

describe('integerArg', () => {
  const port = integerArg('--port', 0, 65_535);
  const offset = integerArg('--offset', -10, 10);

  it('reads decimal integers within the range, a minus where the range has negatives', () => {
    expect(port('0')).toBe(0);
    expect(port('65535')).toBe(65_535);
    expect(offset('-10')).toBe(-10);
  });

  it('refuses what is not written as a decimal integer, or is out of range, naming the option', () => {
    for (const value of ['', ' 5', '5 ', '1e3', '0x10', '2.0', '+1', 'NaN', '65536', '-1']) {
      expect(() => port(value), value).toThrow(InvalidArgumentError);
      expect(() => port(value), value).toThrow(
        `"--port" must be an integer in 0..65535, got "${value}"`,
      );
    }
    expect(() => offset('11')).toThrow('"--offset" must be an integer in -10..10, got "11"');
    expect(() => integerArg('--n', 0, 1e300)('99999999999999999999')).toThrow(InvalidArgumentError);
  });
});
