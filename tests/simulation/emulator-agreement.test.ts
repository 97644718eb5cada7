// The measure of the simulation: the same command script ends in the same steps and the same pose
// on the emulated robot (firmware/build/cube-emulator, the firmware core on the host) and on the
// simulated one (SimRobot in a World). Build the emulator with `bash firmware/scripts/test.sh`.
import { spawn } from 'node:child_process';
import type { ChildProcessWithoutNullStreams } from 'node:child_process';
import { createSocket } from 'node:dgram';
import type { Socket } from 'node:dgram';
import { existsSync } from 'node:fs';
import { createInterface } from 'node:readline';
import { World } from '@hal/simulation';
import type { SimRobot } from '@hal/simulation';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { EMULATOR_PATH as EMULATOR, LONGEST_HOST_TIMEOUT_MS } from '../physical/emulator.js';
import { AGREEMENT_SCRIPT as SCRIPT, commandSimRobot } from './agreement-script.js';
import type { Command } from './agreement-script.js';

const TIME_SCALE = 20;

type EmulatorEvent = Record<string, unknown> & { event: string };

function runOnSimulation(robot: SimRobot, world: World, command: Command): void {
  commandSimRobot(robot, command);
  if (!world.advanceUntil(() => !robot.running, 120_000_000)) throw new Error('never finished');
}

describe('simulation vs the emulated firmware', () => {
  let emulator: ChildProcessWithoutNullStreams;
  let socket: Socket;
  let port = 0;
  const events: EmulatorEvent[] = [];
  const waiters: Array<() => void> = [];

  beforeAll(async () => {
    if (!existsSync(EMULATOR)) {
      throw new Error(`${EMULATOR} is missing: build it with "bash firmware/scripts/test.sh"`);
    }
    // the longest host timeout (500 ms of real time at x20): a heartbeat held back on a loaded
    // machine must not cut a motion this test compares
    emulator = spawn(
      EMULATOR,
      [
        '--udp-port',
        '0',
        '--no-pty',
        '--time-scale',
        String(TIME_SCALE),
        '--host-timeout-ms',
        String(LONGEST_HOST_TIMEOUT_MS),
        '--exit-on-stdin-eof',
      ],
      { stdio: ['pipe', 'pipe', 'pipe'] },
    );
    const lines = createInterface({ input: emulator.stdout });
    lines.on('line', (line) => {
      events.push(JSON.parse(line) as EmulatorEvent);
      for (const wake of waiters.splice(0)) wake();
    });
    await waitFor((e) => e.event === 'ready', 10_000);
    port = Number(events.find((e) => e.event === 'ready')?.['udp_port']);
    socket = createSocket('udp4');
    await new Promise<void>((resolve) => socket.bind(0, '127.0.0.1', resolve));
  }, 20_000);

  afterAll(async () => {
    socket?.close();
    if (emulator !== undefined && emulator.exitCode === null) {
      const exited = new Promise((resolve) => emulator.once('exit', resolve));
      emulator.kill('SIGTERM');
      await exited;
    }
  });

  function waitFor(
    match: (e: EmulatorEvent) => boolean,
    timeoutMs: number,
  ): Promise<EmulatorEvent> {
    return new Promise((resolve, reject) => {
      const timer = setTimeout(
        () => reject(new Error('the emulator did not report in time')),
        timeoutMs,
      );
      const check = () => {
        const found = events.find(match);
        if (found !== undefined) {
          clearTimeout(timer);
          resolve(found);
        } else {
          waiters.push(check);
        }
      };
      check();
    });
  }

  let nextSeq = 1;
  let sid = 0;
  function request(body: Command): Promise<Record<string, unknown>> {
    const seq = nextSeq;
    nextSeq += 1;
    const message = JSON.stringify(sid === 0 ? { ...body, seq } : { ...body, seq, sid });
    return new Promise((resolve, reject) => {
      const timer = setTimeout(() => {
        socket.off('message', onMessage);
        reject(new Error(`no reply to ${message}`));
      }, 3000);
      const onMessage = (data: Buffer) => {
        const reply = JSON.parse(data.toString('utf8')) as Record<string, unknown>;
        if (reply['seq'] !== seq) return;
        clearTimeout(timer);
        socket.off('message', onMessage);
        resolve(reply);
      };
      socket.on('message', onMessage);
      socket.send(message, port, '127.0.0.1');
    });
  }

  it('ends every command of the script with the same wheel positions and the same pose', async () => {
    const hello = await request({ cmd: 'hello', client: 'simulation-agreement-test' });
    expect(hello['ok']).toBe(true);
    sid = Number(hello['sid']);

    const world = new World({ map: { name: 'open', arena: { width: 20, height: 20 } } });
    const robot = world.addRobot();

    for (const command of SCRIPT) {
      const reply = await request(command);
      expect(reply['ok'], JSON.stringify(reply)).toBe(true);
      const moveId = Number(reply['move_id']);
      // Keep the host timeout from firing while the robot moves, as a host must.
      const heartbeat = setInterval(() => void request({ cmd: 'heartbeat' }).catch(() => {}), 5);
      let finished: EmulatorEvent;
      try {
        finished = await waitFor(
          (e) => e.event === 'move_finished' && e['move_id'] === moveId,
          30_000,
        );
      } finally {
        clearInterval(heartbeat);
      }
      runOnSimulation(robot, world, command);
      const where = JSON.stringify(command);
      expect(finished['outcome'], where).toBe('done');
      expect(robot.motion?.outcome, where).toBe('done');
      expect([robot.leftSteps, robot.rightSteps], where).toEqual([
        finished['left_position'],
        finished['right_position'],
      ]);
      // Both integrate the same steps with the same formula; only the grouping of steps per
      // update differs (which changes nothing on straight lines and turns in place).
      expect(robot.x * 100, where).toBeCloseTo(Number(finished['x_cm']), 3);
      expect(robot.y * 100, where).toBeCloseTo(Number(finished['y_cm']), 3);
      expect(robot.yaw, where).toBeCloseTo(Number(finished['heading_rad']), 6);
    }
  });
});
