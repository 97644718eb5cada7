// Builds and connects the HAL a Target names, with a bound on connecting (a robot that is off
// is NOT_CONNECTED within the timeout, never a hang), and lets go of it the right way after.
import { NatsHAL, openConnection } from '@hal/nats';
import { calibratedGeometry, calibrationSource, PhysicalHAL } from '@hal/physical';
import type { CalibrationSource } from '@hal/physical';
import { RemoteHAL } from '@hal/remote';
import { SimulationHAL, World } from '@hal/simulation';
import { deadline, delay, HalError, isHalError } from '@hal/types';
import type { HardwareAbstractionLayer } from '@hal/types';
import type { CliIO } from './io.js';
import { cliLogger } from './logger.js';
import { DEFAULT_CONNECT_TIMEOUT_MS, describeTarget } from './target.js';
import type { Target } from './target.js';

/** A connected HAL and how to let go of it. */
export interface OpenedHal {
  hal: HardwareAbstractionLayer;
  /** The robot's id: a physical robot's own (from its hello), else the HAL's. */
  deviceId: string;
  /** Cleans up (a controller stops the robot); a watcher only disconnects. Bounded, never throws. */
  close(): Promise<void>;
}

export interface OpenTargetOptions {
  /** Give up connecting after this long, ms. Default {@link DEFAULT_CONNECT_TIMEOUT_MS}. */
  connectTimeoutMs?: number;
  /**
   * 'control' (default) drives the robot: on WebSocket it must become the controller (see
   * {@link openTarget}). 'safety' may only stop and e-stop, which a WebSocket watcher may do too.
   * 'watch' only reads: it never takes a WebSocket HAL's control and, on NATS, disconnects
   * without the stop a controller's cleanup sends.
   */
  role?: 'control' | 'safety' | 'watch';
  /** Write the HAL's warnings as JSON lines (--json). */
  json?: boolean;
  /** The device id a simulator reports, or a physical robot's HAL (default: the robot's own). */
  deviceId?: string;
  /**
   * Where a physical robot's calibration comes from (default: the target's `--calibration` file,
   * else the robot's own file in the calibration directory).
   */
  calibration?: CalibrationSource;
}

const CLOSE_TIMEOUT_MS = 5000;
/** How often to try again for control of a WebSocket HAL. */
const CONTROL_RETRY_MS = 200;

/** Runs `close`, bounded, swallowing its failure (the command's own outcome is what matters). */
async function bounded(close: () => Promise<void>): Promise<void> {
  await deadline(close(), CLOSE_TIMEOUT_MS, 'closing the HAL').catch(() => undefined);
}

/** Builds the HAL for `target` (not yet initialised) and its release. */
async function build(
  target: Target,
  io: CliIO,
  options: OpenTargetOptions,
): Promise<{ hal: HardwareAbstractionLayer; release: (initialised: boolean) => Promise<void> }> {
  const watch = options.role === 'watch';
  switch (target.kind) {
    case 'sim': {
      const robot =
        target.calibration === undefined
          ? {}
          : { robot: await calibratedGeometry(target.calibration, io.env) };
      const hal = new SimulationHAL({
        ...robot,
        world: new World({ map: target.map }),
        clock: 'realtime',
        realtimeSpeed: target.speed,
        ...(options.deviceId === undefined ? {} : { deviceId: options.deviceId }),
      });
      return { hal, release: () => hal.cleanup() };
    }
    case 'udp':
    case 'serial': {
      // the key, and the ESP32-CAM where one is named
      const link = {
        ...(target.key === undefined ? {} : { key: target.key }),
        ...(target.camera === undefined ? {} : { cameraUrl: target.camera.url }),
        ...(target.camera?.token === undefined ? {} : { cameraToken: target.camera.token }),
      };
      const connection =
        target.kind === 'udp'
          ? { type: 'wifi' as const, host: target.host, udpPort: target.port, ...link }
          : {
              type: 'serial' as const,
              port: target.path,
              ...link,
              ...(target.baudRate === undefined ? {} : { baudRate: target.baudRate }),
            };
      const hal = new PhysicalHAL(
        { mode: 'physical', deviceId: options.deviceId ?? 'robot', connection },
        {
          logger: cliLogger(io, options.json === true),
          timeScale: target.timeScale,
          client: 'hal-cli',
          calibration: options.calibration ?? calibrationSource(target.calibration, io.env),
          // the HAL says hello for as long as the user allows, and tells silence from a wrong key
          connectTimeoutMs: options.connectTimeoutMs ?? DEFAULT_CONNECT_TIMEOUT_MS,
        },
      );
      return { hal, release: () => hal.cleanup() };
    }
    case 'ws': {
      const hal = new RemoteHAL({
        url: target.url,
        ...(target.token === undefined ? {} : { token: target.token }),
        control: watch ? 'watch' : 'auto',
        clientId: 'hal-cli',
        reconnect: false,
        connectTimeoutMs: options.connectTimeoutMs ?? DEFAULT_CONNECT_TIMEOUT_MS,
        logger: cliLogger(io, options.json === true),
      });
      return { hal, release: () => hal.cleanup() };
    }
    case 'nats': {
      // Our own connection, so a watcher can let go without NatsHAL's cleanup (which stops the
      // wheels of a robot someone else may be driving).
      // a failure is already the one NOT_CONNECTED (or AUTH_FAILED) every command reports
      const nc = await openConnection(target.nats);
      const hal = new NatsHAL({
        connection: nc,
        ...(target.deviceId === undefined ? {} : { deviceId: target.deviceId }),
        clientId: `hal-cli-${process.pid}`,
        logger: cliLogger(io, options.json === true),
      });
      return {
        hal,
        release: async (initialised) => {
          if (initialised && !watch) await bounded(() => hal.cleanup());
          await nc.close();
        },
      };
    }
  }
}

/**
 * Builds and initialises the HAL `target` names. NOT_CONNECTED when it does not answer within
 * the connect timeout (or the connection fails); what was opened is released again.
 */
export async function openTarget(
  target: Target,
  io: CliIO,
  options: OpenTargetOptions = {},
): Promise<OpenedHal> {
  const deadline = Date.now() + (options.connectTimeoutMs ?? DEFAULT_CONNECT_TIMEOUT_MS);
  for (;;) {
    const opened = await openOnce(target, io, options);
    const { hal } = opened;
    if (options.role !== undefined && options.role !== 'control') return opened;
    if (!(hal instanceof RemoteHAL) || hal.role === 'controller') return opened;
    // Someone controls the served HAL. It may be our own previous run whose close the server
    // has not processed yet (nobody controls a moment later), so try again until the deadline;
    // control is never taken from another client.
    await opened.close();
    if (Date.now() + CONTROL_RETRY_MS > deadline) {
      throw new HalError(
        'NOT_CONTROLLER',
        `another client controls the ${describeTarget(target)}: this one could only watch`,
      );
    }
    await delay(CONTROL_RETRY_MS);
  }
}

/** Beyond the connect timeout, how long a physical HAL's own verdict is waited for. */
const PHYSICAL_VERDICT_MS = 1000;

/** The error of a robot that did not answer within the connect timeout: what was tried, hints. */
function unanswered(target: Target, timeoutMs: number, cause?: unknown): HalError {
  const name = describeTarget(target);
  const hint =
    target.kind === 'udp' || target.kind === 'serial'
      ? `: nothing came back. Is it powered${target.kind === 'udp' ? ', on this network, at this address and port' : ', on this port, at this baud rate'}? (A wrong --key is answered with AUTH_FAILED: silence is not a key problem.)`
      : '';
  return new HalError('NOT_CONNECTED', `no answer from the ${name} within ${timeoutMs} ms${hint}`, {
    ...(cause === undefined ? {} : { cause }),
    details: { timeoutMs },
  });
}

/** True for a physical HAL's "no answer to hello" (it waited), not a failure to open the link. */
function isSilence(error: HalError): boolean {
  return typeof error.details?.['waitedMs'] === 'number';
}

/** How long the HAL says it waited for an answer, else the timeout this command waited for. */
function waitedFor(error: HalError, timeoutMs: number): number {
  const waited = error.details?.['waitedMs'];
  return typeof waited === 'number' ? waited : timeoutMs;
}

async function openOnce(target: Target, io: CliIO, options: OpenTargetOptions): Promise<OpenedHal> {
  const timeoutMs = options.connectTimeoutMs ?? DEFAULT_CONNECT_TIMEOUT_MS;
  const name = describeTarget(target);
  const physical = target.kind === 'udp' || target.kind === 'serial';
  const { hal, release } = await deadline(build(target, io, options), timeoutMs, () =>
    unanswered(target, timeoutMs),
  );
  try {
    // PhysicalHAL bounds its own hello by the timeout and says why it failed (silence, a wrong
    // key); the margin lets that verdict arrive before this one
    await deadline(hal.initialize(), timeoutMs + (physical ? PHYSICAL_VERDICT_MS : 0), () =>
      unanswered(target, timeoutMs),
    );
  } catch (error) {
    // let go in the background: a HAL still connecting may take its own retry budget to stop
    void bounded(() => release(false));
    // only silence becomes "no answer within": a port that does not exist or a host that does
    // not resolve keeps the HAL's own reason, which came long before any timeout
    if (isHalError(error) && error.code === 'NOT_CONNECTED' && physical && isSilence(error)) {
      throw unanswered(target, waitedFor(error, timeoutMs), error);
    }
    if (isHalError(error) && error.code === 'AUTH_FAILED' && physical) {
      throw new HalError('AUTH_FAILED', error.message.replace(/^the robot /, `the ${name} `), {
        cause: error,
        ...(error.details === undefined ? {} : { details: error.details }),
      });
    }
    if (isHalError(error)) throw error;
    throw new HalError('NOT_CONNECTED', `cannot connect to the ${name}: ${String(error)}`, {
      cause: error,
    });
  }
  const own = hal instanceof PhysicalHAL && options.deviceId === undefined;
  const deviceId = (own ? hal.identity?.deviceId : undefined) ?? hal.getDeviceInfo().id;
  return { hal, deviceId, close: () => bounded(() => release(true)) };
}

/** Opens `target`, runs `use` with its HAL, and always closes it again. */
export async function withTarget<T>(
  target: Target,
  io: CliIO,
  options: OpenTargetOptions,
  use: (opened: OpenedHal) => Promise<T>,
): Promise<T> {
  const opened = await openTarget(target, io, options);
  try {
    return await use(opened);
  } finally {
    await opened.close();
  }
}
