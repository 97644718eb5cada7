// A host that dies during an endless drive: time from the end of the host process to the robot's
// motors stopping, on the robot's clock (emulator at time scale 1, host timeout 500 ms). Killed
// (SIGKILL: only the robot's host timeout can stop it) against ended politely (SIGTERM: the host
// calls hal.cleanup(), which sends stop), interleaved, with the ratio.
import { startEmulator } from '../tests/physical/emulator.js';
import { endHostDuringDrive } from '../tests/physical/host-kill.js';
import { percentile, reportFigure } from './report/figures.js';

const TRIALS = Number(process.env['KILL_TRIALS'] ?? 8);
const HOST_TIMEOUT_MS = 500;

const emulator = await startEmulator({ hostTimeoutMs: HOST_TIMEOUT_MS, pty: false });
const delays: Record<'SIGKILL' | 'SIGTERM', number[]> = { SIGKILL: [], SIGTERM: [] };
const outcomes: Record<'SIGKILL' | 'SIGTERM', Set<string>> = {
  SIGKILL: new Set(),
  SIGTERM: new Set(),
};
try {
  for (let i = 0; i < TRIALS; i++) {
    for (const signal of ['SIGKILL', 'SIGTERM'] as const) {
      const run = await endHostDuringDrive(emulator, { driveMs: 1000, signal });
      delays[signal].push(run.finishedRobotMs - run.killedRobotMs);
      outcomes[signal].add(String(run.finished['outcome']));
    }
  }
} finally {
  await emulator.stop();
}
const line = (signal: 'SIGKILL' | 'SIGTERM') => {
  const d = delays[signal];
  return `p50 ${percentile(d, 50).toFixed(1)} ms, max ${Math.max(...d).toFixed(1)} ms (outcome ${[...outcomes[signal]].join(', ')})`;
};
console.log(
  `Host ended during an endless drive, ${TRIALS} trials each, host timeout ${HOST_TIMEOUT_MS} ms; end of the host -> motors stopped, robot clock:`,
);
console.log(`  SIGKILL (host timeout):   ${line('SIGKILL')}`);
console.log(`  SIGTERM (cleanup, stop):  ${line('SIGTERM')}`);
console.log(
  `  ratio kill/term p50: ${(percentile(delays.SIGKILL, 50) / Math.max(0.1, percentile(delays.SIGTERM, 50))).toFixed(0)}x`,
);
for (const [stat, of] of [
  ['p50', (d: number[]) => percentile(d, 50)],
  ['max', (d: number[]) => Math.max(...d)],
] as const) {
  reportFigure({
    bench: 'host-kill',
    name: `host killed (SIGKILL) during an endless drive, end of the host to motors stopped, ${stat}`,
    value: of(delays.SIGKILL),
    unit: 'ms',
    better: 'lower',
    alternative: {
      name: `host ended with SIGTERM (cleanup sends stop), ${stat}`,
      value: of(delays.SIGTERM),
    },
    goal: `host timeout + 50 ms (${HOST_TIMEOUT_MS + 50} ms)`,
    met: of(delays.SIGKILL) <= HOST_TIMEOUT_MS + 50,
    note:
      `SIGKILL is stopped by the robot's host timeout (${HOST_TIMEOUT_MS} ms here), so it is expected to be ` +
      `slower than SIGTERM; robot clock, ${TRIALS} trials each, interleaved`,
  });
}
