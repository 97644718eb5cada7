// `hal emulate`: runs the emulated robot (cube-emulator, the firmware core on this computer),
// prints where it listens, announces it with mDNS as the board announces itself (the TXT entries
// come from the emulator, built by the firmware core), and stops it cleanly on Ctrl-C. Where no
// cube-emulator can be had (an installed `hal`, without the firmware sources), it serves the mock
// robot of @hal/physical/testing instead, and says so. With --camera it also serves the
// ESP32-CAM's HTTP interface, its frames rendered from the emulated body's true pose in a world.
import { announceRobot, findRobot } from '@hal/discovery';
import type { Announcer, MdnsOptions } from '@hal/discovery';
import { CliError } from '../cli-error.js';
import { CAMERA_TOKEN_ENV } from '../camera-options.js';
import { planCamera } from '../emulate/camera-plan.js';
import type { CameraPlan } from '../emulate/camera-plan.js';
import { addEmulateOptions, emulatorArgs } from '../emulate/emulate-options.js';
import type { EmulateCliOptions } from '../emulate/emulate-options.js';
import { startEmulatedCamera } from '../emulate/emulated-camera.js';
import type { EmulatedCamera } from '../emulate/emulated-camera.js';
import { startEmulatorProcess, WheelsEventSchema } from '../emulate/emulator-process.js';
import type { EmulatorProcess, ReadyLine } from '../emulate/emulator-process.js';
import { findFirmwareDir } from '../emulate/emulator-build.js';
import { locateEmulator } from '../emulate/locate-emulator.js';
import { MOCK_NOTICE, startMockEmulator } from '../emulate/mock-emulator.js';
import { emit, progress } from '../io.js';
import { listenError } from '../listen-error.js';
import type { CliIO, GlobalOptions } from '../io.js';
import type { RegisterCommand } from './context.js';

/** Announces the emulator unless its device id is already announced on the network. */
async function announce(ready: ReadyLine, mdns: MdnsOptions): Promise<Announcer> {
  if (!ready.mdns) throw new CliError('FAILED', 'cube-emulator printed no mDNS announcement');
  const taken = await findRobot(ready.device_id, { timeoutMs: 1000, mdns }).catch(() => undefined);
  if (taken !== undefined) {
    throw new CliError(
      'FAILED',
      `a robot "${ready.device_id}" is already announced (${taken.host}, port ${taken.port}): ` +
        'choose another --device-id',
    );
  }
  return announceRobot({ port: ready.mdns.port, txt: ready.mdns.txt, mdns });
}

/** Which robot runs: the firmware's cube-emulator, or the mock where there is none. */
type EmulatorKind = 'cube-emulator' | 'mock';

/** The lines about a served camera: where, what it sees, and how to use it. */
function describeCamera(camera: EmulatedCamera, plan: CameraPlan): string[] {
  const token = plan.token === undefined ? '' : ` --camera-token <token> (or $${CAMERA_TOKEN_ENV})`;
  return [
    `camera at ${camera.url}/stream (status ${camera.url}/status${plan.token === undefined ? '' : ', token required'}), ` +
      `seeing ${plan.world === undefined ? 'an empty arena' : `the world of ${plan.world.file}`}`,
    `drive it with its camera: --camera-url ${camera.url}${token}`,
  ];
}

function describeReady(
  ready: ReadyLine,
  o: EmulateCliOptions,
  announced: boolean,
  kind: EmulatorKind,
  camera?: { served: EmulatedCamera; plan: CameraPlan },
): string {
  const lines = [
    `${kind === 'mock' ? 'mock robot' : 'cube-emulator'} "${ready.device_id}" listening on udp ${o.bind}:${ready.udp_port}` +
      (ready.pty === '' ? '' : `, serial ${ready.pty}`) +
      ` (auth ${ready.auth}, protocol ${ready.protocol_version})`,
  ];
  if (kind === 'mock') lines.push(MOCK_NOTICE);
  if (announced) {
    lines.push(
      `announced as ${ready.mdns?.service ?? '_hal-cube._udp'} (see it with: hal discover)`,
    );
    if (o.bind.startsWith('127.'))
      lines.push('bound to loopback: reachable from this machine only');
  }
  if (camera) lines.push(...describeCamera(camera.served, camera.plan));
  lines.push('Ctrl-C stops it');
  return lines.join('\n');
}

/** Whether a cube-emulator can be had: named, or built from the checkout's firmware. */
function emulatorAvailable(o: EmulateCliOptions, io: CliIO): boolean {
  const fromEnv = io.env['CUBE_EMULATOR'];
  return (
    o.emulator !== undefined ||
    (fromEnv !== undefined && fromEnv !== '') ||
    findFirmwareDir() !== undefined
  );
}

async function startEmulator(
  o: EmulateCliOptions,
  io: CliIO,
  g: GlobalOptions,
): Promise<EmulatorProcess> {
  // the wheels events feed the camera; they are not news to the user
  let wheels = { left: 0, right: 0 };
  const path = await locateEmulator({
    ...(o.emulator === undefined ? {} : { explicit: o.emulator }),
    env: io.env,
    signal: io.signal,
    onBuild: (dir) => progress(io, g, `building cube-emulator in ${dir} (if needed)...`),
  });
  const emulator = await startEmulatorProcess(path, emulatorArgs(o), (event) => {
    const reported = WheelsEventSchema.safeParse(event);
    if (reported.success) {
      wheels = { left: reported.data.left_position, right: reported.data.right_position };
      return;
    }
    emit(io, g, event, () => `emulator: ${JSON.stringify(event)}`);
  });
  return { ...emulator, wheels: () => wheels };
}

/** Serves the camera `plan` asks for, naming --camera when its port cannot be had. */
async function serveCamera(
  plan: CameraPlan,
  o: EmulateCliOptions,
  emulator: EmulatorProcess,
): Promise<EmulatedCamera> {
  const wheels = emulator.wheels;
  if (wheels === undefined) throw new CliError('FAILED', 'the emulated robot reports no wheels');
  try {
    return await startEmulatedCamera({
      host: o.bind,
      port: plan.port,
      ...(plan.token === undefined ? {} : { token: plan.token }),
      ...(plan.world === undefined ? {} : { world: plan.world.realised }),
      wheels,
    });
  } catch (error) {
    const place = {
      host: o.bind,
      port: plan.port,
      portOption: '--camera PORT',
      hostOption: '--bind',
    };
    throw listenError(error, place);
  }
}

async function runEmulate(o: EmulateCliOptions, io: CliIO, g: GlobalOptions): Promise<void> {
  const plan = await planCamera(o, io.env);
  const kind: EmulatorKind = emulatorAvailable(o, io) ? 'cube-emulator' : 'mock';
  const emulator = kind === 'mock' ? await startMockEmulator(o) : await startEmulator(o, io, g);
  let announcer: Announcer | undefined;
  let camera: EmulatedCamera | undefined;
  try {
    if (plan !== undefined) camera = await serveCamera(plan, o, emulator);
    const mdns: MdnsOptions = o.interface === undefined ? {} : { interface: o.interface };
    if (o.announce) announcer = await announce(emulator.ready, mdns);
    emit(
      io,
      g,
      {
        event: 'ready',
        emulator: kind,
        deviceId: emulator.ready.device_id,
        address: o.bind,
        udpPort: emulator.ready.udp_port,
        pty: emulator.ready.pty,
        auth: emulator.ready.auth,
        protocolVersion: emulator.ready.protocol_version,
        announced: announcer !== undefined,
        ...(announcer && emulator.ready.mdns ? { service: emulator.ready.mdns.service } : {}),
        ...(camera === undefined || plan === undefined
          ? {}
          : {
              camera: {
                url: camera.url,
                world: plan.world?.file ?? null,
                token: plan.token !== undefined,
              },
            }),
      },
      () =>
        describeReady(
          emulator.ready,
          o,
          announcer !== undefined,
          kind,
          camera === undefined || plan === undefined ? undefined : { served: camera, plan },
        ),
    );
    const stopped = new Promise<void>((resolve) => {
      if (io.signal.aborted) resolve();
      io.signal.addEventListener('abort', () => resolve(), { once: true });
    });
    const how = await Promise.race([stopped.then(() => undefined), emulator.exited]);
    if (how !== undefined) {
      throw new CliError(
        'FAILED',
        `cube-emulator exited (${how.code ?? how.signal}): ${how.stderr.trim() || 'no message'}`,
      );
    }
    progress(io, g, 'stopping...');
  } finally {
    await camera?.close();
    await announcer?.stop();
    await emulator.stop();
  }
  emit(io, g, { event: 'stopped', deviceId: emulator.ready.device_id }, () => 'stopped');
}

export const registerEmulate: RegisterCommand = (program, { io, global }) => {
  addEmulateOptions(
    program
      .command('emulate')
      .description(
        'run the emulated robot (cube-emulator, else the mock robot) and announce it on the local network',
      ),
  ).action((options: EmulateCliOptions) => runEmulate(options, io, global()));
};
