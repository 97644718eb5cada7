import { connect, createServer } from 'node:net';
import type { AddressInfo } from 'node:net';
import { afterEach, describe, expect, it } from 'vitest';
import { scoped } from '@hal/types';
import type { LogLevel } from '@hal/types';
import { ReferenceHAL } from '@hal/types/testing';
import { ControllerWatch } from './controller-watch.js';

function clock() {
  let t = 0;
  return { now: () => t, advance: (ms: number) => (t += ms) };
}

const watches: ControllerWatch[] = [];
afterEach(() => {
  for (const watch of watches.splice(0)) watch.close();
});

/** A ready reference HAL whose stops are counted, and a log that is kept. */
async function rig(timeoutMs: number) {
  const hal = new ReferenceHAL();
  await hal.initialize();
  let stops = 0;
  const stop = hal.locomotion.stop.bind(hal.locomotion);
  hal.locomotion.stop = () => {
    stops += 1;
    return stop();
  };
  const lines: Array<[LogLevel, string]> = [];
  const log = scoped({ log: (level, _ns, message) => lines.push([level, message]) }, 'test');
  const time = clock();
  const silent: Array<[string, number]> = [];
  const make = (onSilent?: (client: string, ms: number) => void) => {
    const watch = new ControllerWatch(hal, {
      timeoutMs,
      log,
      now: time.now,
      ...(onSilent === undefined ? {} : { onSilent }),
    });
    watches.push(watch);
    return watch;
  };
  return { hal, time, lines, silent, make, stops: () => stops };
}

/** A watch on the real clock and its own timer, and the clients it called silent. */
async function timedWatch(timeoutMs: number) {
  const hal = new ReferenceHAL();
  await hal.initialize();
  const silent: string[] = [];
  const watch = new ControllerWatch(hal, {
    timeoutMs,
    log: scoped({ log: () => undefined }, 'test'),
    onSilent: (client) => silent.push(client),
  });
  watches.push(watch);
  return { watch, silent };
}

describe('ControllerWatch', () => {
  it('tells of a watched client silent longer than the timeout, once', async () => {
    const { time, make, silent } = await rig(1000);
    const watch = make((client, ms) => silent.push([client, ms]));
    watch.watch('agent-1');
    time.advance(900);
    watch.heard('agent-1');
    time.advance(900);
    watch.check();
    expect(silent).toEqual([]);
    watch.heard('someone-else'); // not watched: changes nothing
    time.advance(200);
    watch.check();
    expect(silent).toEqual([['agent-1', 1100]]);
    time.advance(5000);
    watch.check();
    expect(silent).toEqual([['agent-1', 1100]]);
    expect(watch.watches('agent-1')).toBe(false);
  });

  it('does nothing for a client it was told to forget', async () => {
    const { time, make, silent } = await rig(1000);
    const watch = make((client, ms) => silent.push([client, ms]));
    watch.watch('agent-1');
    watch.watch('agent-2');
    watch.forget('agent-1');
    time.advance(5000);
    watch.check();
    expect(silent.map(([client]) => client)).toEqual(['agent-2']);
    watch.watch('agent-3');
    watch.forget();
    time.advance(5000);
    watch.check();
    expect(silent.map(([client]) => client)).toEqual(['agent-2']);
  });

  it('by default stops the robot once for a silent controller, and says for whom and why', async () => {
    const { time, make, lines, stops } = await rig(500);
    const watch = make();
    watch.watch('agent-1');
    time.advance(501);
    watch.check();
    watch.check();
    await expect.poll(stops).toBe(1);
    expect(lines).toEqual([['warn', 'controller agent-1 silent for 501 ms: stopping the robot']]);
  });

  it('logs a stop that failed as an error, naming the controller', async () => {
    const { hal, make, lines } = await rig(500);
    await hal.cleanup(); // a HAL that is not ready refuses the stop
    await make().stopFor('agent-9', 'disconnected');
    expect(lines).toEqual([
      ['warn', 'controller agent-9 disconnected: stopping the robot'],
      ['error', 'the stop for controller agent-9 failed'],
    ]);
  });

  it('checks on its own timer, without being asked', async () => {
    const { watch, silent } = await timedWatch(50);
    watch.watch('agent-1');
    await expect.poll(() => silent, { timeout: 2000 }).toEqual(['agent-1']);
  });

  it('reads what waited while this process was held up before calling a client silent', async () => {
    const { watch, silent } = await timedWatch(100);
    // a real socket: the client's message waits in the kernel while this process is busy
    const server = createServer((socket) => socket.on('data', () => watch.heard('agent-1')));
    await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
    const { port } = server.address() as AddressInfo;
    const client = connect(port, '127.0.0.1');
    await new Promise<void>((resolve) => client.once('connect', resolve));
    try {
      watch.watch('agent-1');
      const busyUntil = performance.now() + 300;
      let sent = false;
      while (performance.now() < busyUntil) {
        // the client speaks 250 ms into the stall, within the timeout of its last message
        if (!sent && performance.now() > busyUntil - 50) {
          client.write('heartbeat');
          sent = true;
        }
      }
      // the timer is due (300 ms since watch) before the message is read
      await new Promise((resolve) => setTimeout(resolve, 30));
      expect(silent).toEqual([]);
      // and a client that really says nothing is still called silent
      await expect.poll(() => silent, { timeout: 2000 }).toEqual(['agent-1']);
    } finally {
      client.destroy();
      await new Promise((resolve) => server.close(resolve));
    }
  });
});
