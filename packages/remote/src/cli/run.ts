// Builds the chosen HAL, initialises it and serves it until stopped.
import { calibrationSource, PhysicalHAL } from '@hal/physical';
import { SimulationHAL } from '@hal/simulation';
import type { HardwareAbstractionLayer } from '@hal/types';
import type { Logger } from '@hal/types';
import { checkBinding } from '../server/auth.js';
import { serveHal } from '../server/index.js';
import type { HalServer } from '../server/index.js';
import type { ServeCommand } from './parse.js';

/** Makes the HAL a command asks for (not yet initialised). */
export function buildHal(command: ServeCommand, logger: Logger): HardwareAbstractionLayer {
  const { hal } = command;
  if (hal.kind === 'sim') {
    return new SimulationHAL({ deviceId: command.deviceId, clock: 'realtime' });
  }
  const key = hal.key === undefined ? {} : { key: hal.key };
  const connection =
    hal.kind === 'udp'
      ? { type: 'wifi' as const, host: hal.host, udpPort: hal.port, ...key }
      : {
          type: 'serial' as const,
          port: hal.path,
          ...key,
          ...(hal.baudRate === undefined ? {} : { baudRate: hal.baudRate }),
        };
  return new PhysicalHAL(
    { mode: 'physical', deviceId: command.deviceId, connection },
    // the robot's calibration file (hal calibrate), sent after every hello
    {
      logger,
      timeScale: command.timeScale,
      calibration: calibrationSource(undefined, process.env),
    },
  );
}

/** Initialises the HAL and serves it. */
export async function runServe(
  command: ServeCommand,
  logger: Logger,
): Promise<{ hal: HardwareAbstractionLayer; server: HalServer }> {
  const hal = buildHal(command, logger);
  const options = {
    host: command.host,
    port: command.port,
    stateRateHz: command.stateRateHz,
    heartbeatTimeoutMs: command.heartbeatTimeoutMs,
    logger,
    ...(command.token === undefined ? {} : { token: command.token }),
  };
  // Refuse an unsafe binding before touching the robot.
  checkBinding(command.host, command.token);
  await hal.initialize();
  try {
    const server = await serveHal(hal, options);
    return { hal, server };
  } catch (e) {
    await hal.cleanup();
    throw e;
  }
}
