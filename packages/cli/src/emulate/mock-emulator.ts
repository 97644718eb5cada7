// `hal emulate` where there is no cube-emulator to run (an installed `hal`: the firmware sources it
// is built from are not in the packages): the mock robot of @hal/physical/testing on a real UDP
// socket, speaking the same protocol, behind the same ready line and announcement.
import { MessageCodec, createAuthenticator } from '@hal/physical/protocol';
import { MockUdpRobot } from '@hal/physical/testing';
import { isHalError } from '@hal/types';
import { CliError } from '../cli-error.js';
import { listenError } from '../listen-error.js';
import type { EmulateCliOptions } from './emulate-options.js';
import type { EmulatorProcess, ReadyLine } from './emulator-process.js';

/** What `hal emulate` says when it serves the mock, and why. */
export const MOCK_NOTICE =
  "no cube-emulator here (it is built from the project's firmware/ with cmake: give one with " +
  '--emulator PATH or $CUBE_EMULATOR): serving MockUdpRobot of @hal/physical/testing, the same ' +
  'protocol over UDP, without the serial link';

/** The TXT record of the announcement, from the robot's own hello (docs/discovery.md). */
async function announcement(robot: MockUdpRobot, key: string | undefined): Promise<ReadyLine> {
  const codec = new MessageCodec(key === undefined ? undefined : await createAuthenticator(key));
  const reply = codec.decode(robot.handle(codec.encode({ cmd: 'hello', seq: 1, nonce: 'mdns' })));
  robot.requests.length = 0; // the announcement's hello is not a request a host made
  if (!reply.ok)
    throw new CliError('FAILED', `the mock robot's hello failed: ${reply.error.message}`);
  const hello = reply.reply;
  const capabilities = Array.isArray(hello['capabilities']) ? hello['capabilities'] : [];
  const auth = String(hello['auth']);
  const protocol = String(hello['protocol_version']);
  return {
    event: 'ready',
    udp_port: robot.port,
    pty: '',
    device_id: robot.deviceId,
    auth,
    protocol_version: protocol,
    mdns: {
      service: '_hal-cube._udp',
      port: robot.port,
      txt: {
        txtvers: '1',
        device_id: robot.deviceId,
        proto: protocol,
        auth,
        caps: capabilities.join(','),
      },
    },
  };
}

/**
 * Starts the mock robot with `hal emulate`'s options, as an {@link EmulatorProcess}: the same ready
 * line (no pty), never exiting by itself, stopped by closing its socket. Refuses a non-loopback
 * `--bind` without `--key` or `--insecure`, as cube-emulator does.
 */
export async function startMockEmulator(o: EmulateCliOptions): Promise<EmulatorProcess> {
  if (!o.bind.startsWith('127.') && o.key === undefined && !o.insecure) {
    throw new CliError(
      'FAILED',
      `refusing to listen on ${o.bind} without a key: anyone who reaches it could drive it (give --key HEX, or --insecure)`,
    );
  }
  let robot: MockUdpRobot;
  try {
    robot = await MockUdpRobot.start({
      host: o.bind,
      port: o.udpPort,
      deviceId: o.deviceId,
      ...(o.key === undefined ? {} : { key: o.key }),
      ...(o.timeScale === undefined ? {} : { timeScale: o.timeScale }),
      ...(o.hostTimeoutMs === undefined ? {} : { hostTimeoutMs: o.hostTimeoutMs }),
    });
  } catch (error) {
    if (!isHalError(error)) throw error;
    // a port in use names the option that changes it, as every listening command does
    const place = { host: o.bind, port: o.udpPort, portOption: '--udp-port', hostOption: '--bind' };
    const named = listenError(error.cause, place);
    throw named instanceof CliError
      ? named
      : new CliError('FAILED', `${error.code}: ${error.message}`);
  }
  try {
    return {
      ready: await announcement(robot, o.key),
      exited: new Promise<never>(() => undefined),
      stop: () => robot.close(),
      wheels: () => robot.position,
    };
  } catch (error) {
    await robot.close();
    throw error;
  }
}
