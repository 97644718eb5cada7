#!/usr/bin/env node
// hal-serve: serves one HAL over WebSocket. Prints `listening ws://HOST:PORT` on stdout when ready;
// logs go to stderr. Stops cleanly on SIGINT/SIGTERM.
import { isHalError } from '@hal/types';
import type { Logger } from '@hal/types';
import { parseServeCommand } from './parse.js';
import { runServe } from './run.js';

const stderrLogger: Logger = {
  log: (level, namespace, message) => {
    if (level !== 'debug') process.stderr.write(`${level} ${namespace} ${message}\n`);
  },
};

async function main(): Promise<void> {
  const command = parseServeCommand(process.argv.slice(2));
  const { hal, server } = await runServe(command, stderrLogger);
  process.stdout.write(`listening ${server.url} (${hal.mode}, device ${hal.getDeviceInfo().id})\n`);
  const stop = async () => {
    await server.close();
    await hal.cleanup();
    process.exit(0);
  };
  process.once('SIGINT', () => void stop());
  process.once('SIGTERM', () => void stop());
}

main().catch((e: unknown) => {
  const message = isHalError(e) ? `${e.code}: ${e.message}` : String(e);
  process.stderr.write(`hal-serve: ${message}\n`);
  process.exit(1);
});
