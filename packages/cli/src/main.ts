#!/usr/bin/env node
// `hal`: runs the program on this process's argv and streams, and exits with its code. SIGINT
// and SIGTERM abort the running command, which then stops cleanly (a second signal exits at once).
import { runHal } from './program.js';

const abort = new AbortController();
const onSignal = (): void => {
  if (abort.signal.aborted) process.exit(130);
  abort.abort();
};
process.on('SIGINT', onSignal);
process.on('SIGTERM', onSignal);

// A reader that went away (`hal status --watch | head`): the command stops as on Ctrl-C (a robot
// in motion is stopped) and writes nothing more, instead of dying on an unhandled EPIPE.
let outClosed = false;
process.stdout.on('error', (error: NodeJS.ErrnoException) => {
  if (error.code !== 'EPIPE') throw error;
  outClosed = true;
  abort.abort();
});

const code = await runHal(process.argv.slice(2), {
  out: (text) => {
    if (!outClosed) process.stdout.write(text);
  },
  err: (text) => process.stderr.write(text),
  signal: abort.signal,
  stdin: process.stdin,
  env: process.env,
});
process.exit(code);
