// Runs a soak: the emulator, and a host process (processes/soak-host.ts) that sends COUNT commands
// through PhysicalHAL over UDP or the emulator's pseudo-terminal. Reports both processes' resident
// memory after warm-up and at the end (the host's after a full GC; the emulator's from /proc), the
// throughput and the latency. Used by the soak test and by bench/soak.bench.ts.
import { readFileSync } from 'node:fs';
import { startEmulator } from './emulator.js';
import { startHostProcess } from './host-process.js';
import type { HostEvent } from './host-process.js';

export type SoakLink = 'udp' | 'serial';

export interface SoakReport {
  link: SoakLink;
  commands: number;
  seconds: number;
  perSecond: number;
  p50Ms: number;
  p99Ms: number;
  failed: number;
  failures: string[];
  /** Requests the transport gave up on after every attempt: lost replies. */
  timeouts: number;
  retries: number;
  motions: number;
  moveStarted: number;
  trips: number;
  expected: { left: number; right: number };
  robot: { left: number; right: number; moveId: number };
  host: { rssStart: number; rssEnd: number; heapStart: number; heapEnd: number; gc: boolean };
  emulator: { rssStart: number; rssEnd: number };
}

/** VmRSS of a process, bytes. */
export function residentBytes(pid: number): number {
  const match = /^VmRSS:\s+(\d+) kB/m.exec(readFileSync(`/proc/${pid}/status`, 'utf8'));
  if (match === null) throw new Error(`no VmRSS in /proc/${pid}/status`);
  return Number(match[1]) * 1024;
}

export async function runSoak(options: {
  link: SoakLink;
  count: number;
  timeScale: number;
  maxSeconds: number;
}): Promise<SoakReport> {
  const emulator = await startEmulator({
    timeScale: options.timeScale,
    // the longest host timeout: a stall of the (loaded) machine must not stop a move
    hostTimeoutMs: 10_000,
    pty: options.link === 'serial',
  });
  try {
    const host = startHostProcess(
      'soak-host.ts',
      [
        options.link,
        options.link === 'udp' ? String(emulator.udpPort) : emulator.pty,
        String(options.count),
        String(options.timeScale),
        String(options.maxSeconds),
      ],
      ['--expose-gc'],
    );
    try {
      await host.waitFor((e) => e.event === 'warm', options.maxSeconds * 1000);
      const emulatorStart = residentBytes(emulator.pid);
      const done = await host.waitFor((e) => e.event === 'done', options.maxSeconds * 2000);
      const emulatorEnd = residentBytes(emulator.pid);
      return report(options.link, done, host.events, emulator.events, emulatorStart, emulatorEnd);
    } finally {
      await host.kill();
    }
  } finally {
    await emulator.stop();
  }
}

function report(
  link: SoakLink,
  done: HostEvent,
  hostEvents: HostEvent[],
  robotEvents: { event: string; [key: string]: unknown }[],
  emulatorStart: number,
  emulatorEnd: number,
): SoakReport {
  const warm = hostEvents.find((e) => e.event === 'warm')!;
  const start = done['start'] as { rss: number; heapUsed: number };
  const end = done['end'] as { rss: number; heapUsed: number };
  const transport = done['transport'] as { timeouts: number; retries: number };
  return {
    link,
    commands: Number(done['commands']),
    seconds: Number(done['seconds']),
    perSecond: Number(done['perSecond']),
    p50Ms: Number(done['p50Ms']),
    p99Ms: Number(done['p99Ms']),
    failed: Number(done['failed']),
    failures: done['failures'] as string[],
    timeouts: transport.timeouts,
    retries: transport.retries,
    motions: Number(done['motions']),
    moveStarted: robotEvents.filter((e) => e.event === 'move_started' && e['kind'] === 'move')
      .length,
    trips: robotEvents.filter((e) => e.event === 'trip').length,
    expected: done['expected'] as SoakReport['expected'],
    robot: done['robot'] as SoakReport['robot'],
    host: {
      rssStart: Number(warm['rss'] ?? start.rss),
      rssEnd: end.rss,
      heapStart: start.heapUsed,
      heapEnd: end.heapUsed,
      gc: done['gc'] === true,
    },
    emulator: { rssStart: emulatorStart, rssEnd: emulatorEnd },
  };
}
