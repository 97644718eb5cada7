// A UDP proxy that sits between a host and the robot and misbehaves on purpose, reproducibly
// (seeded): it drops, duplicates, delays and reorders datagrams, in each direction separately.
import { createSocket } from 'node:dgram';
import type { RemoteInfo } from 'node:dgram';

/** What the proxy does to the datagrams going one way. Probabilities are 0..1. */
export interface Faults {
  drop?: number;
  duplicate?: number;
  /** Each datagram (and copy) is held for a uniform random delay in [0, maxDelayMs]. */
  maxDelayMs?: number;
  /** Probability that a datagram is held back long enough to arrive after later ones. */
  reorder?: number;
}

export interface DirectionStats {
  received: number;
  dropped: number;
  duplicated: number;
  reordered: number;
  forwarded: number;
}

export interface FaultProxy {
  /** The port hosts should talk to. */
  port: number;
  toRobot: DirectionStats;
  toHost: DirectionStats;
  /** Drops the next `count` datagrams from the robot to the host, whatever the faults say. */
  dropNextReplies(count: number): void;
  /** Forgets the replies still to drop by `dropNextReplies`. */
  stopDropping(): void;
  /** Changes the faults of both directions from now on. */
  setFaults(faults: { toRobot: Faults; toHost: Faults }): void;
  close(): Promise<void>;
}

/** mulberry32: a small, seeded PRNG, so a failing run can be replayed. */
export function seededRandom(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

const stats = (): DirectionStats => ({
  received: 0,
  dropped: 0,
  duplicated: 0,
  reordered: 0,
  forwarded: 0,
});

export async function startFaultProxy(options: {
  robotPort: number;
  seed: number;
  toRobot: Faults;
  toHost: Faults;
}): Promise<FaultProxy> {
  const random = seededRandom(options.seed);
  const hostSide = createSocket('udp4');
  const robotSide = createSocket('udp4');
  const toRobot = stats();
  const toHost = stats();
  const timers = new Set<ReturnType<typeof setTimeout>>();
  let host: RemoteInfo | undefined;
  let closed = false;
  let dropReplies = 0;
  let faultsToRobot = options.toRobot;
  let faultsToHost = options.toHost;

  const pass = (
    message: Buffer,
    faults: Faults,
    s: DirectionStats,
    send: (m: Buffer) => void,
  ): void => {
    s.received += 1;
    if (random() < (faults.drop ?? 0)) {
      s.dropped += 1;
      return;
    }
    const copies = random() < (faults.duplicate ?? 0) ? 2 : 1;
    if (copies === 2) s.duplicated += 1;
    for (let i = 0; i < copies; i++) {
      let delay = random() * (faults.maxDelayMs ?? 0);
      if (random() < (faults.reorder ?? 0)) {
        s.reordered += 1;
        delay += 3 * (faults.maxDelayMs ?? 1) + 2;
      }
      const timer = setTimeout(() => {
        timers.delete(timer);
        if (closed) return;
        s.forwarded += 1;
        send(message);
      }, delay);
      timers.add(timer);
    }
  };

  hostSide.on('message', (message, remote) => {
    host = remote;
    pass(message, faultsToRobot, toRobot, (m) => robotSide.send(m, options.robotPort, '127.0.0.1'));
  });
  robotSide.on('message', (message) => {
    const to = host;
    if (to === undefined) return;
    if (dropReplies > 0) {
      dropReplies -= 1;
      toHost.received += 1;
      toHost.dropped += 1;
      return;
    }
    pass(message, faultsToHost, toHost, (m) => hostSide.send(m, to.port, to.address));
  });
  await Promise.all([
    new Promise<void>((resolve) => hostSide.bind(0, '127.0.0.1', resolve)),
    new Promise<void>((resolve) => robotSide.bind(0, '127.0.0.1', resolve)),
  ]);
  return {
    port: hostSide.address().port,
    toRobot,
    toHost,
    dropNextReplies: (count) => {
      dropReplies += count;
    },
    stopDropping: () => {
      dropReplies = 0;
    },
    setFaults: (faults) => {
      faultsToRobot = faults.toRobot;
      faultsToHost = faults.toHost;
    },
    close: async () => {
      closed = true;
      for (const timer of timers) clearTimeout(timer);
      await Promise.all([
        new Promise<void>((resolve) => hostSide.close(() => resolve())),
        new Promise<void>((resolve) => robotSide.close(() => resolve())),
      ]);
    },
  };
}
