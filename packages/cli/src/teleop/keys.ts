// The keys of `hal teleop`, read from a terminal in raw mode (arrow keys arrive as escape
// sequences; Ctrl-C arrives as the byte 0x03, not as a signal).

export type TeleopKey = 'forward' | 'back' | 'left' | 'right' | 'stop' | 'estop' | 'reset' | 'quit';

const SEQUENCES: readonly [string, TeleopKey][] = [
  ['\x1b[A', 'forward'],
  ['\x1b[B', 'back'],
  ['\x1b[C', 'right'],
  ['\x1b[D', 'left'],
  ['\x1bOA', 'forward'],
  ['\x1bOB', 'back'],
  ['\x1bOC', 'right'],
  ['\x1bOD', 'left'],
];

const SINGLE: Readonly<Record<string, TeleopKey>> = {
  w: 'forward',
  s: 'back',
  a: 'left',
  d: 'right',
  ' ': 'stop',
  e: 'estop',
  r: 'reset',
  q: 'quit',
  '\x03': 'quit', // Ctrl-C
  '\x04': 'quit', // Ctrl-D
};

/** The keys in one chunk of terminal input, in order; anything else is skipped. */
export function parseKeys(chunk: string): TeleopKey[] {
  const keys: TeleopKey[] = [];
  let i = 0;
  while (i < chunk.length) {
    const sequence = SEQUENCES.find(([text]) => chunk.startsWith(text, i));
    if (sequence !== undefined) {
      keys.push(sequence[1]);
      i += sequence[0].length;
      continue;
    }
    const key = SINGLE[chunk[i]!.toLowerCase()];
    if (key !== undefined) keys.push(key);
    i += chunk[i] === '\x1b' && chunk[i + 1] === '[' ? 3 : 1; // skip an unknown escape sequence
  }
  return keys;
}

/** The help line teleop prints when it starts. */
export const TELEOP_HELP =
  'arrows/WASD drive, space stop, e e-stop, r reset e-stop, q quit (a key sets the motion until the next)';
