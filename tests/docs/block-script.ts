// Turns a documented shell block into the bash script the doc-commands test runs: the block's
// commands as written, stopping at the first that fails (set -e, pipefail), with each
// long-running command (long-running.ts) started in the background, waited for until its ready
// line, and stopped with Ctrl-C when the block ends. So is anything the block itself put in the
// background (`cube-emulator ... &`). Only one thing is rewritten: when CUBE_BUILD_DIR names the
// firmware's host build, `firmware/build/cube-emulator` becomes that build's emulator, as the
// tests' own emulator helper (tests/physical/emulator.ts) does. One thing is added: a block that
// names nats://127.0.0.1:4222 and starts no nats-server itself (the docs say to start one, as the
// README does) gets one there, started first and stopped with the rest.
import { commandLines } from './shell-blocks.js';
import type { ShellBlock } from './shell-blocks.js';
import { longRunning } from './long-running.js';

/** Seconds a long-running command may take to print its ready line. */
export const READY_TIMEOUT_S = 90;
/** Seconds a long-running command may take to exit after Ctrl-C. */
export const STOP_TIMEOUT_S = 10;

const PRELUDE = String.raw`set -eo pipefail
set -m  # job control: every background job has its own process group, stopped as one
# the block's commands read an empty input (one that waits for input ends, not hangs); the
# long-running ones keep the test's open pipe (fd 3): a stdio server ends when its input does
exec 3<&0 </dev/null
__doc_pids=()
__doc_stop() {
  local status=0 pid i
  for pid in "${'${'}__doc_pids[@]}" $(jobs -p); do kill -INT -- "-$pid" 2>/dev/null || true; done
  for pid in "${'${'}__doc_pids[@]}"; do
    for ((i = 0; i < ${STOP_TIMEOUT_S * 10}; i++)); do
      kill -0 -- "-$pid" 2>/dev/null || break
      sleep 0.1
    done
    if kill -0 -- "-$pid" 2>/dev/null; then
      echo "doc-test: a long-running command did not stop within ${STOP_TIMEOUT_S} s of Ctrl-C" >&2
      status=1
    fi
  done
  for pid in "${'${'}__doc_pids[@]}" $(jobs -p); do kill -KILL -- "-$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true # reap them: nothing outlives the block, not even as a zombie
  return $status
}
trap '__doc_code=$?; __doc_stop || __doc_code=1; exit $__doc_code' EXIT
# __doc_start NAME READY TTY COMMAND: starts COMMAND in the background, waits for READY in its output
__doc_start() {
  local log pid i
  log=$(mktemp)
  if [ "$3" = 1 ]; then
    script -qefc "$4" /dev/null <&3 >"$log" 2>&1 &
  else
    eval "$4" <&3 >"$log" 2>&1 &
  fi
  pid=$!
  __doc_pids+=("$pid")
  for ((i = 0; i < ${READY_TIMEOUT_S * 10}; i++)); do
    if grep -Eq -- "$2" "$log"; then
      head -c 2000 "$log"
      echo "doc-test: $1 is ready"
      return 0
    fi
    if ! kill -0 "$pid" 2>/dev/null; then
      cat "$log"
      echo "doc-test: $1 exited before printing its ready line (/$2/)" >&2
      return 1
    fi
    sleep 0.1
  done
  head -c 2000 "$log"
  echo "doc-test: $1 printed no ready line (/$2/) within ${READY_TIMEOUT_S} s" >&2
  return 1
}
`;

/** Single-quotes `text` for bash. */
function quote(text: string): string {
  return `'${text.replaceAll("'", String.raw`'\''`)}'`;
}

/** The NATS server the docs' commands name. */
export const DOCS_NATS_URL = 'nats://127.0.0.1:4222';

export interface BlockScriptOptions {
  /** CUBE_BUILD_DIR, when it is set. */
  buildDir?: string | undefined;
  /** The nats-server executable, for a block that needs the docs' NATS server. */
  natsServer?: string | undefined;
}

/** The script for `block`. */
export function blockScript(
  block: Pick<ShellBlock, 'language' | 'text'>,
  options: BlockScriptOptions = {},
): string {
  const { buildDir, natsServer } = options;
  const lines = commandLines(block);
  const services: string[] = [];
  if (
    block.text.includes(DOCS_NATS_URL) &&
    !lines.some((line) => /^(?:\S*\/)?nats-server\b/.test(line.trim()))
  ) {
    if (natsServer === undefined)
      throw new Error(`the block names ${DOCS_NATS_URL}: give natsServer`);
    const command = `${quote(natsServer)} -a 127.0.0.1 -p 4222`;
    services.push(`__doc_start 'nats-server' 'Server is ready' 0 ${quote(command)}`);
  }
  const body = lines.map((line) => {
    const command =
      buildDir === undefined
        ? line
        : line.replaceAll('firmware/build/cube-emulator', `${quote(buildDir)}/cube-emulator`);
    const entry = longRunning(command);
    if (entry === undefined) return command;
    return `__doc_start ${quote(entry.name)} ${quote(entry.ready)} ${entry.tty === true ? 1 : 0} ${quote(command)}`;
  });
  return `${PRELUDE}\n${[...services, ...body].join('\n')}\n`;
}

/**
 * The TCP and UDP ports a block uses (numbers it names after a colon or a port option, and the
 * defaults of the long-running commands it starts): blocks sharing one never run at once.
 */
export function blockPorts(block: Pick<ShellBlock, 'language' | 'text'>): number[] {
  const ports = new Set<number>();
  for (const match of block.text.matchAll(/(?::|-port[ =])(\d{4,5})\b/g))
    ports.add(Number(match[1]));
  for (const line of commandLines(block)) {
    for (const port of longRunning(line)?.defaultPorts ?? []) ports.add(port);
  }
  return [...ports];
}
