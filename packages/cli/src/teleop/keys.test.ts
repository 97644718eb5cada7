import { describe, expect, it } from 'vitest';
import { parseKeys } from './keys.js';

describe('teleop keys', () => {
  it('reads arrow keys (both encodings), WASD in either case and the command keys', () => {
    expect(parseKeys('\x1b[A\x1b[B\x1b[C\x1b[D\x1bOA')).toEqual([
      'forward',
      'back',
      'right',
      'left',
      'forward',
    ]);
    expect(parseKeys('wAsD e r q')).toEqual([
      'forward',
      'left',
      'back',
      'right',
      'stop',
      'estop',
      'stop',
      'reset',
      'stop',
      'quit',
    ]);
    expect(parseKeys('\x03')).toEqual(['quit']);
  });

  it('skips keys and escape sequences it does not know', () => {
    expect(parseKeys('x\x1b[5~z\x1b[Aé')).toEqual(['forward']);
  });
});
