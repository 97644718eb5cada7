// A keyboard for tests of `hal teleop`: a readable stream that says it is a TTY and records
// every raw-mode switch, so a test can type keys and check the terminal was restored.
import { PassThrough } from 'node:stream';

export interface FakeTty extends PassThrough {
  isTTY: true;
  /** Every setRawMode call, in order. */
  rawModes: boolean[];
  setRawMode(raw: boolean): FakeTty;
  /** The terminal is in raw mode now. */
  isRaw: boolean;
  /** Types `keys` (as a terminal sends them). */
  type(keys: string): void;
}

export function fakeTty(): FakeTty {
  const stream = new PassThrough() as unknown as FakeTty;
  stream.isTTY = true;
  stream.rawModes = [];
  stream.isRaw = false;
  stream.setRawMode = (raw: boolean) => {
    stream.rawModes.push(raw);
    stream.isRaw = raw;
    return stream;
  };
  stream.type = (keys: string) => void stream.write(Buffer.from(keys, 'latin1'));
  return stream;
}
