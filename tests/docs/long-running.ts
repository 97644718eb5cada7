// The documented commands that run until stopped (servers, the demo, teleop): the doc-commands
// test starts each, waits for the line that says it is ready, leaves it running for the rest of
// its block (a later line may talk to it) and stops it with Ctrl-C (SIGINT) at the block's end.
// A long-running command missing here makes its block time out, with a message that points here.

export interface LongRunning {
  /** What it is, for messages. */
  name: string;
  /** Matches the command line (leading VAR=value assignments removed). */
  command: RegExp;
  /** Matches its output once it is ready (an extended regular expression, for grep -E). */
  ready: string;
  /** It needs a terminal (teleop reads keys): run it under script(1), in a pseudo-terminal. */
  tty?: boolean;
  /** The TCP ports it binds when the line names none, so blocks that share one never overlap. */
  defaultPorts?: number[];
}

const hal = String.raw`(?:pnpm (?:-s )?hal|hal)`;

export const LONG_RUNNING: readonly LongRunning[] = [
  { name: 'hal serve', command: new RegExp(String.raw`^${hal} serve\b`), ready: 'serving ' },
  {
    name: 'hal teleop',
    command: new RegExp(String.raw`^${hal} teleop\b`),
    ready: 'q quit',
    tty: true,
  },
  {
    name: 'hal status --watch',
    command: new RegExp(String.raw`^${hal} (?:--json )?status\b.*--watch\b`),
    ready: 'pose',
  },
  {
    name: 'hal mcp',
    command: new RegExp(String.raw`^${hal} mcp\b`),
    ready: 'MCP over (stdio|HTTP)',
    defaultPorts: [3333],
  },
  {
    name: 'hal emulate',
    command: new RegExp(String.raw`^${hal} (?:--json )?emulate\b`),
    ready: '"event":"announced"',
  },
  {
    name: 'cube-emulator',
    command: /^\S*cube-emulator\b/,
    ready: '"event":"ready"',
    defaultPorts: [4210],
  },
  {
    name: 'nats-server',
    command: /^nats-server\b/,
    ready: 'Server is ready',
    defaultPorts: [4222],
  },
  {
    name: 'the browser demo (vite)',
    command: /^pnpm (?:start|--filter @hal\/sim-demo start)\s*(?:#.*)?$/,
    ready: String.raw`http://(127\.0\.0\.1|localhost):[0-9]+`,
  },
];

/**
 * The long-running command `line` is, if any. A line the block itself puts in the background
 * (ending in `&`) is left as written: the block's end stops it all the same.
 */
export function longRunning(line: string): LongRunning | undefined {
  const command = line
    .replace(/\s+#.*$/, '')
    .trim()
    .replace(/^(?:[A-Z_][A-Z0-9_]*=\S*\s+)+/, '');
  if (/[^&]&$/.test(command)) return undefined;
  return LONG_RUNNING.find((entry) => entry.command.test(command));
}
