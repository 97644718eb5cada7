// `hal --json status` against the firmware emulator over each way a user reaches a robot: UDP, the
// serial link (the emulator's pty), WebSocket (`hal serve --ws-port` over serial) and NATS (`hal
// serve --nats` over UDP, through a real nats-server). Every program is started the way `hal`
// says (the checkout's launcher, the packed bin), so a build of the CLI is tested as a product.
import { expect } from 'vitest';
import { runHalProcess, startHalProcess } from '../helpers/hal-process.js';
import type { HalCommand } from '../helpers/hal-process.js';
import type { Emulator } from '../physical/emulator.js';
import type { NatsServer } from '../nats/nats-server.js';

/** The ways to the robot, in the order a test goes through them. */
export const TRANSPORTS = ['udp', 'serial', 'ws', 'nats'] as const;
export type Transport = (typeof TRANSPORTS)[number];

/** The robot and the NATS server the transports lead to. */
export interface TransportRig {
  emulator: Emulator;
  nats: NatsServer;
}

/** What `hal --json status` prints. */
export interface StatusDoc {
  device: { id: string; type: string; mode: string };
  capabilities: string[];
  safety: { emergencyStopped: boolean };
}

interface ServeEvent {
  event: string;
  ws?: { url: string };
}

/** Generous: a launcher may bundle first, on a machine busy with other tests. */
const RUN_TIMEOUT_MS = 60_000;

function udp(rig: TransportRig): string[] {
  return ['--udp', `127.0.0.1:${rig.emulator.udpPort}`];
}

/** `hal --json status` with `target`; its exit code must be 0 and its first line the status. */
async function status(hal: HalCommand, target: readonly string[]): Promise<StatusDoc> {
  const run = await runHalProcess(['--json', 'status', ...target], RUN_TIMEOUT_MS, hal);
  expect(run.code, `hal status ${target.join(' ')}: ${run.stderr}`).toBe(0);
  return JSON.parse(run.stdout.split('\n')[0]!) as StatusDoc;
}

/** `hal serve` with `args` while `use` runs; it must stop on Ctrl-C with exit code 0. */
async function whileServing<T>(
  hal: HalCommand,
  args: readonly string[],
  use: (serving: ServeEvent) => Promise<T>,
): Promise<T> {
  const serve = startHalProcess<ServeEvent>(['--json', 'serve', ...args], hal);
  try {
    const serving = await serve.waitFor((e) => e.event === 'serving', RUN_TIMEOUT_MS);
    const result = await use(serving);
    expect(await serve.stop('SIGINT')).toBe(0);
    return result;
  } finally {
    await serve.stop('SIGKILL');
  }
}

/** Runs `hal --json status` over `transport` with `hal` and returns what it printed. */
export async function statusOver(
  transport: Transport,
  hal: HalCommand,
  rig: TransportRig,
): Promise<StatusDoc> {
  switch (transport) {
    case 'udp':
      return status(hal, udp(rig));
    case 'serial':
      return status(hal, ['--serial', rig.emulator.pty]);
    case 'ws':
      return whileServing(hal, ['--serial', rig.emulator.pty, '--ws-port', '0'], (serving) =>
        status(hal, ['--ws', serving.ws!.url]),
      );
    case 'nats':
      return whileServing(hal, [...udp(rig), '--nats', rig.nats.url], () =>
        status(hal, ['--nats', rig.nats.url]),
      );
  }
}

/** Asserts that `doc` is the emulated robot's own answer: its id, its type, its capabilities. */
export function expectFromRobot(doc: StatusDoc, deviceId: string): void {
  expect(doc.device).toEqual({ id: deviceId, type: 'v1-stepper-cube', mode: 'physical' });
  expect(doc.capabilities).toContain('locomotion.stepper:v1.0:steps_per_rev=4096');
  expect(doc.safety.emergencyStopped).toBe(false);
}
